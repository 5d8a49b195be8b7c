// generated/polygon_inverse.hpp — polygon edge kernels of the inverse family.
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
///     C(P) = ∬_Ω |P − Q|^(−3) dQ
/// Operations per edge: 36 +, 48 ×, 1 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 96 +, 161 ×, 23 /, 22 sqrt, 3 atan, 0 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i3_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T zeta2 = in.z * in.z;
  const T c = zeta2 + ap_ap;
  const T D = zeta2 * ab_ab + cross_cross;
  const T h = cross1 * in.normal[1] + cross0 * in.normal[0] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T H_f;
  const T t0 = min(T(c), T(q1)) - T(2) * zeta2;
  const T t1 = max(T(D - T(2) * zeta2 * ab_ab), T(-ab_ap * a_minus_b));
  if (t0 >= T(0) && t1 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(1, 1, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * h * (r0 * a_minus_b + ab_ap * r1), h * h * r0 * r1 - ab_ap * zeta2 * a_minus_b) / zeta;
    H_f = H1;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−3) dQ
/// Operations per edge: 40 +, 52 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 445 +, 1011 ×, 145 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i3_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T zeta2 = in.z * in.z;
  const T c = zeta2 + ap_ap;
  const T D = zeta2 * ab_ab + cross_cross;
  const T h = cross1 * in.normal[1] + cross0 * in.normal[0] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = zeta2 + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * ab_ab - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(3, 3, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    J_3 = (ab_ap / r0 + a_minus_b / r1) / D;
  }
  T H_g;
  const T t4 = t2 - T(2) * zeta2;
  const T t5 = max(T(D - T(2) * zeta2 * ab_ab), T(t1));
  if (t4 >= T(0) && t5 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(3, 3, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(h * zeta * (a_minus_b * r0 + r1 * ab_ap), r1 * h * h * r0 - ab_ap * a_minus_b * zeta2) / zeta;
    const T H3 = -(h * J_3 - H1) / zeta2;
    H_g = H3;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_3;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−3) dQ
/// Operations per edge: 40 +, 52 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 465 +, 1012 ×, 145 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i3_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = ab_ab * zeta2 + cross_cross;
  const T h = in.normal[2] * cross2 + in.normal[0] * cross0 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * ab_ab * t2 - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(3, 3, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    J_3 = (ab_ap / r0 + a_minus_b / r1) / D;
  }
  T H_f;
  T H_g;
  const T t4 = t2 - T(2) * zeta2;
  const T t5 = max(T(D - T(2) * ab_ab * zeta2), T(t1));
  if (t4 >= T(0) && t5 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(1, 3, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((r0 * a_minus_b + r1 * ab_ap) * zeta * h, r0 * r1 * h * h - ab_ap * a_minus_b * zeta2) / zeta;
    const T H3 = (H1 - J_3 * h) / zeta2;
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
///     C(P) = ∬_Ω |P − Q|^(−4) dQ
/// Operations per edge: 38 +, 43 ×, 2 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 446 +, 969 ×, 145 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i4_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T zeta2 = in.z * in.z;
  const T c = zeta2 + ap_ap;
  const T D = zeta2 * ab_ab + cross_cross;
  const T h = in.normal[2] * cross2 + in.normal[1] * cross1 + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = zeta2 + bp_bp;
  const T c_minus_b = zeta2 + ap_bp;
  T J_2;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * ab_ab - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(2, 2, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(2, 2, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T J2 = atan2(t4, c_minus_b) / t4;
    J_2 = J2;
  }
  T H_f;
  const T t5 = t2 - T(2) * zeta2;
  const T t6 = max(T(D - T(2) * zeta2 * ab_ab), T(t1));
  if (t5 >= T(0) && t6 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(2, 2, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T H2 = -(h * J_2 - theta) / zeta2;
    H_f = H2;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−4) dQ
/// Operations per edge: 41 +, 50 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 450 +, 1001 ×, 147 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i4_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T zeta2 = in.z * in.z;
  const T c = zeta2 + ap_ap;
  const T D = zeta2 * ab_ab + cross_cross;
  const T h = in.normal[0] * cross0 + in.normal[2] * cross2 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T c_minus_b = zeta2 + ap_bp;
  T J_2;
  T J_4;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * ab_ab - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(2, 4, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = t5 * atan2(t4, c_minus_b);
    J_2 = J2;
    const T t6 = T(1) / D;
    J_4 = (T(1) / T(2)) * t6 * (ab_ap / c + a_minus_b / q1 + J2 * ab_ab);
  }
  T H_g;
  const T t7 = t2 - T(2) * zeta2;
  const T t8 = max(T(D - T(2) * zeta2 * ab_ab), T(t1));
  if (t7 >= T(0) && t8 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(4, 4, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t9 = T(1) / zeta2;
    const T H2 = t9 * (theta - h * J_2);
    const T H4 = -(h * J_4 - H2) * t9;
    H_g = H4;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_4;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−4) dQ
/// Operations per edge: 41 +, 50 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 470 +, 1022 ×, 147 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i4_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T zeta2 = in.z * in.z;
  const T c = zeta2 + ap_ap;
  const T D = zeta2 * ab_ab + cross_cross;
  const T h = in.normal[0] * cross0 + cross1 * in.normal[1] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = zeta2 + bp_bp;
  const T c_minus_b = zeta2 + ap_bp;
  T J_2;
  T J_4;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * ab_ab - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(2, 4, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = atan2(t4, c_minus_b) * t5;
    J_2 = J2;
    const T t6 = T(1) / D;
    J_4 = (T(1) / T(2)) * (ab_ab * J2 + ab_ap / c + a_minus_b / q1) * t6;
  }
  T H_f;
  T H_g;
  const T t7 = t2 - T(2) * zeta2;
  const T t8 = max(T(D - T(2) * zeta2 * ab_ab), T(t1));
  if (t7 >= T(0) && t8 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(2, 4, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t9 = T(1) / zeta2;
    const T H2 = -t9 * (h * J_2 - theta);
    const T H4 = t9 * (H2 - h * J_4);
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
///     C(P) = ∬_Ω |P − Q|^(−5) dQ
/// Operations per edge: 40 +, 52 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 445 +, 1011 ×, 145 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i5_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T zeta2 = in.z * in.z;
  const T c = zeta2 + ap_ap;
  const T D = zeta2 * ab_ab + cross_cross;
  const T h = cross1 * in.normal[1] + cross0 * in.normal[0] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * ab_ab - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(3, 3, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    J_3 = (a_minus_b / r1 + ab_ap / r0) / D;
  }
  T H_f;
  const T t4 = t2 - T(2) * zeta2;
  const T t5 = max(T(D - T(2) * zeta2 * ab_ab), T(t1));
  if (t4 >= T(0) && t5 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(3, 3, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(h * zeta * (a_minus_b * r0 + r1 * ab_ap), r1 * h * h * r0 - ab_ap * a_minus_b * zeta2) / zeta;
    const T H3 = (H1 - h * J_3) / zeta2;
    H_f = H3;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−5) dQ
/// Operations per edge: 43 +, 65 ×, 7 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 449 +, 1063 ×, 147 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i5_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = cross_cross + ab_ab * zeta2;
  const T h = in.normal[0] * cross0 + in.normal[2] * cross2 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * ab_ab - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(3, 5, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = T(1) / r1;
    const T t5 = T(1) / r0;
    const T t6 = t4 * a_minus_b + t5 * ab_ap;
    const T t7 = T(1) / D;
    J_3 = t6 * t7;
    J_5 = (T(1) / T(3)) * t7 * (t5 * ab_ap / c + t4 * a_minus_b / q1 + T(2) * t6 * ab_ab * t7);
  }
  T H_g;
  const T t8 = t2 - T(2) * zeta2;
  const T t9 = max(T(D - T(2) * ab_ab * zeta2), T(t1));
  if (t8 >= T(0) && t9 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(5, 5, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((r1 * ab_ap + a_minus_b * r0) * h * zeta, r1 * r0 * h * h - a_minus_b * ab_ap * zeta2) / zeta;
    const T t10 = T(1) / zeta2;
    const T H3 = (H1 - J_3 * h) * t10;
    const T H5 = -t10 * (h * J_5 - H3);
    H_g = H5;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_5;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−5) dQ
/// Operations per edge: 43 +, 65 ×, 7 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 469 +, 1064 ×, 147 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i5_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = ab_ab * zeta2 + cross_cross;
  const T h = in.normal[2] * cross2 + cross0 * in.normal[0] + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * ab_ab * t2 - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(3, 5, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = T(1) / r1;
    const T t5 = T(1) / r0;
    const T t6 = a_minus_b * t4 + t5 * ab_ap;
    const T t7 = T(1) / D;
    J_3 = t6 * t7;
    J_5 = (T(1) / T(3)) * t7 * (T(2) * t6 * ab_ab * t7 + t5 * ab_ap / c + a_minus_b * t4 / q1);
  }
  T H_f;
  T H_g;
  const T t8 = t2 - T(2) * zeta2;
  const T t9 = max(T(D - T(2) * ab_ab * zeta2), T(t1));
  if (t8 >= T(0) && t9 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(3, 5, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * (ab_ap * r1 + a_minus_b * r0) * h, r0 * h * h * r1 - a_minus_b * ab_ap * zeta2) / zeta;
    const T t10 = T(1) / zeta2;
    const T H3 = t10 * (H1 - J_3 * h);
    const T H5 = -(J_5 * h - H3) * t10;
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
///     C(P) = ∬_Ω |P − Q|^(−6) dQ
/// Operations per edge: 41 +, 50 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 450 +, 1001 ×, 147 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i6_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = cross_cross + ab_ab * zeta2;
  const T h = in.normal[2] * cross2 + cross0 * in.normal[0] + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T c_minus_b = ap_bp + zeta2;
  T J_2;
  T J_4;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * ab_ab - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(2, 4, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = atan2(t4, c_minus_b) * t5;
    J_2 = J2;
    const T t6 = T(1) / D;
    J_4 = (T(1) / T(2)) * (ab_ap / c + a_minus_b / q1 + ab_ab * J2) * t6;
  }
  T H_f;
  const T t7 = t2 - T(2) * zeta2;
  const T t8 = max(T(D - T(2) * ab_ab * zeta2), T(t1));
  if (t7 >= T(0) && t8 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(4, 4, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t9 = T(1) / zeta2;
    const T H2 = (theta - J_2 * h) * t9;
    const T H4 = t9 * (H2 - J_4 * h);
    H_f = H4;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−6) dQ
/// Operations per edge: 44 +, 65 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 454 +, 1034 ×, 149 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i6_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T zeta2 = in.z * in.z;
  const T c = zeta2 + ap_ap;
  const T D = zeta2 * ab_ab + cross_cross;
  const T h = in.normal[2] * cross2 + cross0 * in.normal[0] + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T c_minus_b = zeta2 + ap_bp;
  T J_2;
  T J_4;
  T J_6;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * ab_ab - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(2, 6, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(2, 6, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
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
    const T t9 = J2 * ab_ab + ab_ap * t7 + t8 * a_minus_b;
    J_4 = (T(1) / T(2)) * t6 * t9;
    const T t10 = t8 * t8;
    const T t11 = t7 * t7;
    J_6 = (T(1) / T(8)) * t6 * (T(2) * t10 * a_minus_b + T(3) * t6 * t9 * ab_ab + T(2) * ab_ap * t11);
  }
  T H_g;
  const T t12 = t2 - T(2) * zeta2;
  const T t13 = max(T(D - T(2) * zeta2 * ab_ab), T(t1));
  if (t12 >= T(0) && t13 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(6, 6, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t14 = T(1) / zeta2;
    const T H2 = t14 * (theta - h * J_2);
    const T H4 = -(J_4 * h - H2) * t14;
    const T H6 = t14 * (H4 - h * J_6);
    H_g = H6;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_6;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−6) dQ
/// Operations per edge: 44 +, 65 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 474 +, 1055 ×, 149 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i6_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = ab0 * bp0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T zeta2 = in.z * in.z;
  const T c = zeta2 + ap_ap;
  const T D = zeta2 * ab_ab + cross_cross;
  const T h = in.normal[1] * cross1 + in.normal[2] * cross2 + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T c_minus_b = zeta2 + ap_bp;
  T J_2;
  T J_4;
  T J_6;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * ab_ab - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(2, 6, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(2, 6, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = atan2(t4, c_minus_b) * t5;
    J_2 = J2;
    const T t6 = T(1) / q1;
    const T t7 = T(1) / c;
    const T t8 = J2 * ab_ab + t6 * a_minus_b + ab_ap * t7;
    const T t9 = T(1) / D;
    J_4 = (T(1) / T(2)) * t8 * t9;
    const T t10 = t7 * t7;
    const T t11 = t6 * t6;
    J_6 = (T(1) / T(8)) * (T(2) * ab_ap * t10 + T(2) * t11 * a_minus_b + T(3) * t8 * ab_ab * t9) * t9;
  }
  T H_f;
  T H_g;
  const T t12 = t2 - T(2) * zeta2;
  const T t13 = max(T(D - T(2) * zeta2 * ab_ab), T(t1));
  if (t12 >= T(0) && t13 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(4, 6, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t14 = T(1) / zeta2;
    const T H2 = -t14 * (h * J_2 - theta);
    const T H4 = t14 * (H2 - J_4 * h);
    const T H6 = -t14 * (h * J_6 - H4);
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
///     C(P) = ∬_Ω |P − Q|^(−7) dQ
/// Operations per edge: 43 +, 65 ×, 7 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 449 +, 1063 ×, 147 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i7_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + ap2 * bp2;
  const T zeta2 = in.z * in.z;
  const T c = zeta2 + ap_ap;
  const T D = cross_cross + ab_ab * zeta2;
  const T h = cross1 * in.normal[1] + cross0 * in.normal[0] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * ab_ab - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(3, 5, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = T(1) / r1;
    const T t5 = T(1) / r0;
    const T t6 = t4 * a_minus_b + ab_ap * t5;
    const T t7 = T(1) / D;
    J_3 = t6 * t7;
    J_5 = (T(1) / T(3)) * (t4 * a_minus_b / q1 + ab_ap * t5 / c + T(2) * ab_ab * t6 * t7) * t7;
  }
  T H_f;
  const T t8 = t2 - T(2) * zeta2;
  const T t9 = max(T(D - T(2) * ab_ab * zeta2), T(t1));
  if (t8 >= T(0) && t9 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(5, 5, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(h * (r1 * ab_ap + a_minus_b * r0) * zeta, r1 * r0 * h * h - a_minus_b * ab_ap * zeta2) / zeta;
    const T t10 = T(1) / zeta2;
    const T H3 = (H1 - J_3 * h) * t10;
    const T H5 = (H3 - J_5 * h) * t10;
    H_f = H5;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−7) dQ
/// Operations per edge: 46 +, 84 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 453 +, 1116 ×, 149 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i7_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + ap2 * bp2 + ap0 * bp0;
  const T zeta2 = in.z * in.z;
  const T c = zeta2 + ap_ap;
  const T D = cross_cross + ab_ab * zeta2;
  const T h = cross0 * in.normal[0] + in.normal[2] * cross2 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * ab_ab * t2 - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(3, 7, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(3, 7, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = T(1) / D;
    const T t5 = T(1) / r1;
    const T t6 = T(1) / r0;
    const T t7 = t5 * a_minus_b + ab_ap * t6;
    J_3 = t4 * t7;
    const T t8 = t5 * t5;
    const T t9 = t6 * t6;
    const T t10 = t5 * a_minus_b * t8 + t9 * ab_ap * t6 + T(2) * ab_ab * t4 * t7;
    J_5 = (T(1) / T(3)) * t4 * t10;
    const T t11 = t9 * t9;
    const T t12 = t8 * t8;
    J_7 = (T(1) / T(15)) * t4 * (T(3) * t11 * ab_ap * t6 + T(3) * t5 * a_minus_b * t12 + T(4) * ab_ab * t4 * t10);
  }
  T H_g;
  const T t13 = t2 - T(2) * zeta2;
  const T t14 = max(T(D - T(2) * ab_ab * zeta2), T(t1));
  if (t13 >= T(0) && t14 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(7, 7, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((a_minus_b * r0 + r1 * ab_ap) * zeta * h, r1 * h * h * r0 - a_minus_b * ab_ap * zeta2) / zeta;
    const T t15 = T(1) / zeta2;
    const T H3 = -(J_3 * h - H1) * t15;
    const T H5 = -t15 * (J_5 * h - H3);
    const T H7 = -(h * J_7 - H5) * t15;
    H_g = H7;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_7;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−7) dQ
/// Operations per edge: 46 +, 84 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 473 +, 1117 ×, 149 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i7_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T cross_cross = cross2 * cross2 + cross0 * cross0 + cross1 * cross1;
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = cross_cross + ab_ab * zeta2;
  const T h = cross0 * in.normal[0] + cross2 * in.normal[2] + in.normal[1] * cross1;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * ab_ab * t2 - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(3, 7, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(3, 7, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = T(1) / r0;
    const T t5 = T(1) / r1;
    const T t6 = t4 * ab_ap + a_minus_b * t5;
    const T t7 = T(1) / D;
    J_3 = t6 * t7;
    const T t8 = t5 * t5;
    const T t9 = t4 * t4;
    const T t10 = a_minus_b * t5 * t8 + T(2) * t6 * ab_ab * t7 + t4 * t9 * ab_ap;
    J_5 = (T(1) / T(3)) * t7 * t10;
    const T t11 = t9 * t9;
    const T t12 = t8 * t8;
    J_7 = (T(1) / T(15)) * (T(3) * t4 * t11 * ab_ap + T(4) * ab_ab * t7 * t10 + T(3) * a_minus_b * t5 * t12) * t7;
  }
  T H_f;
  T H_g;
  const T t13 = t2 - T(2) * zeta2;
  const T t14 = max(T(D - T(2) * ab_ab * zeta2), T(t1));
  if (t13 >= T(0) && t14 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(5, 7, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((r0 * a_minus_b + r1 * ab_ap) * zeta * h, r0 * r1 * h * h - a_minus_b * ab_ap * zeta2) / zeta;
    const T t15 = T(1) / zeta2;
    const T H3 = -(J_3 * h - H1) * t15;
    const T H5 = (H3 - J_5 * h) * t15;
    const T H7 = (H5 - J_7 * h) * t15;
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
///     C(P) = ∬_Ω |P − Q|^(−8) dQ
/// Operations per edge: 44 +, 65 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 454 +, 1034 ×, 149 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i8_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + ap0 * bp0 + ap2 * bp2;
  const T zeta2 = in.z * in.z;
  const T c = zeta2 + ap_ap;
  const T D = cross_cross + ab_ab * zeta2;
  const T h = cross0 * in.normal[0] + cross1 * in.normal[1] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T c_minus_b = ap_bp + zeta2;
  T J_2;
  T J_4;
  T J_6;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * ab_ab * t2 - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(2, 6, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(2, 6, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = sqrt(D);
    const T t5 = T(1) / t4;
    const T J2 = atan2(t4, c_minus_b) * t5;
    J_2 = J2;
    const T t6 = T(1) / D;
    const T t7 = T(1) / q1;
    const T t8 = T(1) / c;
    const T t9 = a_minus_b * t7 + ab_ab * J2 + t8 * ab_ap;
    J_4 = (T(1) / T(2)) * t6 * t9;
    const T t10 = t8 * t8;
    const T t11 = t7 * t7;
    J_6 = (T(1) / T(8)) * t6 * (T(2) * t10 * ab_ap + T(3) * ab_ab * t6 * t9 + T(2) * a_minus_b * t11);
  }
  T H_f;
  const T t12 = t2 - T(2) * zeta2;
  const T t13 = max(T(D - T(2) * ab_ab * zeta2), T(t1));
  if (t12 >= T(0) && t13 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(6, 6, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t14 = T(1) / zeta2;
    const T H2 = -t14 * (J_2 * h - theta);
    const T H4 = -t14 * (J_4 * h - H2);
    const T H6 = (H4 - h * J_6) * t14;
    H_f = H6;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−8) dQ
/// Operations per edge: 47 +, 78 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 458 +, 1068 ×, 151 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i8_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T zeta2 = in.z * in.z;
  const T c = zeta2 + ap_ap;
  const T D = cross_cross + zeta2 * ab_ab;
  const T h = in.normal[0] * cross0 + cross2 * in.normal[2] + in.normal[1] * cross1;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = zeta2 + bp_bp;
  const T c_minus_b = zeta2 + ap_bp;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * ab_ab - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(2, 8, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(2, 8, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
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
    const T t6 = T(1) / c;
    const T t7 = T(1) / q1;
    const T t8 = t6 * ab_ap + t7 * a_minus_b + J2 * ab_ab;
    const T t9 = T(1) / D;
    J_4 = (T(1) / T(2)) * t8 * t9;
    const T t10 = t7 * t7;
    const T t11 = t6 * t6;
    const T t12 = T(3) * ab_ab * t8 * t9 + T(2) * t10 * a_minus_b + T(2) * t11 * ab_ap;
    J_6 = (T(1) / T(8)) * t12 * t9;
    const T t13 = t10 * t7;
    const T t14 = t11 * t6;
    J_8 = (T(1) / T(48)) * (T(5) * t12 * ab_ab * t9 + T(8) * t13 * a_minus_b + T(8) * t14 * ab_ap) * t9;
  }
  T H_g;
  const T t15 = t2 - T(2) * zeta2;
  const T t16 = max(T(D - T(2) * zeta2 * ab_ab), T(t1));
  if (t15 >= T(0) && t16 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(8, 8, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t17 = T(1) / zeta2;
    const T H2 = -(h * J_2 - theta) * t17;
    const T H4 = -t17 * (J_4 * h - H2);
    const T H6 = t17 * (H4 - h * J_6);
    const T H8 = t17 * (H6 - h * J_8);
    H_g = H8;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_8;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−8) dQ
/// Operations per edge: 47 +, 78 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 478 +, 1089 ×, 151 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i8_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T zeta2 = in.z * in.z;
  const T c = zeta2 + ap_ap;
  const T D = zeta2 * ab_ab + cross_cross;
  const T h = cross1 * in.normal[1] + in.normal[0] * cross0 + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = zeta2 + bp_bp;
  const T c_minus_b = zeta2 + ap_bp;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * ab_ab - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(2, 8, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(2, 8, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
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
    const T t8 = J2 * ab_ab + a_minus_b * t6 + ab_ap * t7;
    const T t9 = T(1) / D;
    J_4 = (T(1) / T(2)) * t8 * t9;
    const T t10 = t7 * t7;
    const T t11 = t6 * t6;
    const T t12 = T(2) * ab_ap * t10 + T(2) * a_minus_b * t11 + T(3) * t8 * ab_ab * t9;
    J_6 = (T(1) / T(8)) * t12 * t9;
    const T t13 = t10 * t7;
    const T t14 = t11 * t6;
    J_8 = (T(1) / T(48)) * (T(8) * ab_ap * t13 + T(5) * ab_ab * t12 * t9 + T(8) * a_minus_b * t14) * t9;
  }
  T H_f;
  T H_g;
  const T t15 = t2 - T(2) * zeta2;
  const T t16 = max(T(D - T(2) * zeta2 * ab_ab), T(t1));
  if (t15 >= T(0) && t16 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(6, 8, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t17 = T(1) / zeta2;
    const T H2 = -t17 * (h * J_2 - theta);
    const T H4 = t17 * (H2 - J_4 * h);
    const T H6 = -t17 * (h * J_6 - H4);
    const T H8 = -(h * J_8 - H6) * t17;
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
///     C(P) = ∬_Ω |P − Q|^(−9) dQ
/// Operations per edge: 46 +, 84 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 453 +, 1116 ×, 149 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i9_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  const T zeta2 = in.z * in.z;
  const T c = zeta2 + ap_ap;
  const T D = zeta2 * ab_ab + cross_cross;
  const T h = in.normal[0] * cross0 + in.normal[1] * cross1 + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = zeta2 + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * ab_ab - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(3, 7, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(3, 7, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = T(1) / D;
    const T t5 = T(1) / r1;
    const T t6 = T(1) / r0;
    const T t7 = t5 * a_minus_b + t6 * ab_ap;
    J_3 = t4 * t7;
    const T t8 = t5 * t5;
    const T t9 = t6 * t6;
    const T t10 = t5 * a_minus_b * t8 + T(2) * ab_ab * t4 * t7 + t6 * t9 * ab_ap;
    J_5 = (T(1) / T(3)) * t10 * t4;
    const T t11 = t9 * t9;
    const T t12 = t8 * t8;
    J_7 = (T(1) / T(15)) * t4 * (T(3) * t6 * t11 * ab_ap + T(4) * t10 * ab_ab * t4 + T(3) * t5 * a_minus_b * t12);
  }
  T H_f;
  const T t13 = t2 - T(2) * zeta2;
  const T t14 = max(T(D - T(2) * zeta2 * ab_ab), T(t1));
  if (t13 >= T(0) && t14 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(7, 7, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((r1 * ab_ap + r0 * a_minus_b) * zeta * h, r0 * r1 * h * h - zeta2 * a_minus_b * ab_ap) / zeta;
    const T t15 = T(1) / zeta2;
    const T H3 = (H1 - J_3 * h) * t15;
    const T H5 = -t15 * (J_5 * h - H3);
    const T H7 = -t15 * (J_7 * h - H5);
    H_f = H7;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−9) dQ
/// Operations per edge: 49 +, 99 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 457 +, 1169 ×, 151 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i9_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T zeta2 = in.z * in.z;
  const T c = zeta2 + ap_ap;
  const T D = zeta2 * ab_ab + cross_cross;
  const T h = cross1 * in.normal[1] + in.normal[2] * cross2 + cross0 * in.normal[0];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = zeta2 + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  T J_9;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * ab_ab - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(3, 9, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
    J_9 = M_flat[3];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(3, 9, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
    J_9 = M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = T(1) / r1;
    const T t5 = T(1) / r0;
    const T t6 = a_minus_b * t4 + ab_ap * t5;
    const T t7 = T(1) / D;
    J_3 = t6 * t7;
    const T t8 = t4 * t4;
    const T t9 = t5 * t5;
    const T t10 = a_minus_b * t8 * t4 + T(2) * t6 * ab_ab * t7 + ab_ap * t9 * t5;
    J_5 = (T(1) / T(3)) * t10 * t7;
    const T t11 = t9 * t9;
    const T t12 = t8 * t8;
    const T t13 = T(3) * ab_ap * t11 * t5 + T(3) * a_minus_b * t12 * t4 + T(4) * t10 * ab_ab * t7;
    J_7 = (T(1) / T(15)) * t13 * t7;
    const T t14 = t12 * t8;
    const T t15 = t11 * t9;
    J_9 = (T(1) / T(35)) * (T(5) * a_minus_b * t14 * t4 + T(2) * t13 * ab_ab * t7 + T(5) * ab_ap * t15 * t5) * t7;
  }
  T H_g;
  const T t16 = t2 - T(2) * zeta2;
  const T t17 = max(T(D - T(2) * zeta2 * ab_ab), T(t1));
  if (t16 >= T(0) && t17 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(9, 9, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(h * zeta * (a_minus_b * r0 + ab_ap * r1), h * h * r0 * r1 - a_minus_b * ab_ap * zeta2) / zeta;
    const T t18 = T(1) / zeta2;
    const T H3 = -t18 * (h * J_3 - H1);
    const T H5 = -(J_5 * h - H3) * t18;
    const T H7 = t18 * (H5 - h * J_7);
    const T H9 = t18 * (H7 - h * J_9);
    H_g = H9;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_9;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−9) dQ
/// Operations per edge: 49 +, 99 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 477 +, 1170 ×, 151 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i9_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T zeta2 = in.z * in.z;
  const T c = zeta2 + ap_ap;
  const T D = cross_cross + ab_ab * zeta2;
  const T h = in.normal[1] * cross1 + in.normal[2] * cross2 + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  T J_9;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * ab_ab - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(3, 9, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
    J_9 = M_flat[3];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(3, 9, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
    J_9 = M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = T(1) / r1;
    const T t5 = T(1) / r0;
    const T t6 = t4 * a_minus_b + t5 * ab_ap;
    const T t7 = T(1) / D;
    J_3 = t6 * t7;
    const T t8 = t4 * t4;
    const T t9 = t5 * t5;
    const T t10 = T(2) * t6 * ab_ab * t7 + t4 * a_minus_b * t8 + t5 * ab_ap * t9;
    J_5 = (T(1) / T(3)) * t7 * t10;
    const T t11 = t9 * t9;
    const T t12 = t8 * t8;
    const T t13 = T(3) * t5 * ab_ap * t11 + T(3) * t4 * a_minus_b * t12 + T(4) * ab_ab * t7 * t10;
    J_7 = (T(1) / T(15)) * t7 * t13;
    const T t14 = t12 * t8;
    const T t15 = t11 * t9;
    J_9 = (T(1) / T(35)) * t7 * (T(5) * t4 * a_minus_b * t14 + T(5) * t5 * ab_ap * t15 + T(2) * ab_ab * t7 * t13);
  }
  T H_f;
  T H_g;
  const T t16 = t2 - T(2) * zeta2;
  const T t17 = max(T(D - T(2) * ab_ab * zeta2), T(t1));
  if (t16 >= T(0) && t17 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(7, 9, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * h * (ab_ap * r1 + r0 * a_minus_b), r0 * r1 * h * h - ab_ap * a_minus_b * zeta2) / zeta;
    const T t18 = T(1) / zeta2;
    const T H3 = t18 * (H1 - J_3 * h);
    const T H5 = -t18 * (J_5 * h - H3);
    const T H7 = (H5 - h * J_7) * t18;
    const T H9 = (H7 - J_9 * h) * t18;
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
///     C(P) = ∬_Ω |P − Q|^(−10) dQ
/// Operations per edge: 47 +, 78 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 458 +, 1068 ×, 151 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i10_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + ap1 * bp1 + ap2 * bp2;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = cross_cross + ab_ab * zeta2;
  const T h = cross0 * in.normal[0] + cross1 * in.normal[1] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T c_minus_b = ap_bp + zeta2;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * ab_ab * t2 - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(2, 8, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(2, 8, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
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
    const T t9 = t7 * ab_ap + a_minus_b * t8 + ab_ab * J2;
    J_4 = (T(1) / T(2)) * t6 * t9;
    const T t10 = t8 * t8;
    const T t11 = t7 * t7;
    const T t12 = T(2) * a_minus_b * t10 + T(2) * t11 * ab_ap + T(3) * ab_ab * t6 * t9;
    J_6 = (T(1) / T(8)) * t6 * t12;
    const T t13 = t11 * t7;
    const T t14 = t10 * t8;
    J_8 = (T(1) / T(48)) * (T(5) * ab_ab * t6 * t12 + T(8) * t13 * ab_ap + T(8) * a_minus_b * t14) * t6;
  }
  T H_f;
  const T t15 = t2 - T(2) * zeta2;
  const T t16 = max(T(D - T(2) * ab_ab * zeta2), T(t1));
  if (t15 >= T(0) && t16 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(8, 8, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t17 = T(1) / zeta2;
    const T H2 = (theta - J_2 * h) * t17;
    const T H4 = -(J_4 * h - H2) * t17;
    const T H6 = -(h * J_6 - H4) * t17;
    const T H8 = -(J_8 * h - H6) * t17;
    H_f = H8;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−10) dQ
/// Operations per edge: 50 +, 91 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 462 +, 1102 ×, 153 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i10_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = ab_ab * zeta2 + cross_cross;
  const T h = in.normal[2] * cross2 + in.normal[0] * cross0 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T c_minus_b = ap_bp + zeta2;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  T J_10;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * ab_ab - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(2, 10, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
    J_10 = M_flat[4];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(2, 10, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
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
    const T t7 = T(1) / q1;
    const T t8 = T(1) / c;
    const T t9 = a_minus_b * t7 + t8 * ab_ap + ab_ab * J2;
    J_4 = (T(1) / T(2)) * t6 * t9;
    const T t10 = t8 * t8;
    const T t11 = t7 * t7;
    const T t12 = T(3) * ab_ab * t6 * t9 + T(2) * t10 * ab_ap + T(2) * a_minus_b * t11;
    J_6 = (T(1) / T(8)) * t12 * t6;
    const T t13 = t10 * t8;
    const T t14 = t11 * t7;
    const T t15 = T(8) * t13 * ab_ap + T(5) * t12 * ab_ab * t6 + T(8) * a_minus_b * t14;
    J_8 = (T(1) / T(48)) * t6 * t15;
    const T t16 = t10 * t10;
    const T t17 = t11 * t11;
    J_10 = (T(1) / T(384)) * t6 * (T(7) * ab_ab * t6 * t15 + T(48) * t16 * ab_ap + T(48) * a_minus_b * t17);
  }
  T H_g;
  const T t18 = t2 - T(2) * zeta2;
  const T t19 = max(T(D - T(2) * ab_ab * zeta2), T(t1));
  if (t18 >= T(0) && t19 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(10, 10, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t20 = T(1) / zeta2;
    const T H2 = (theta - J_2 * h) * t20;
    const T H4 = -t20 * (J_4 * h - H2);
    const T H6 = (H4 - J_6 * h) * t20;
    const T H8 = -(J_8 * h - H6) * t20;
    const T H10 = -(J_10 * h - H8) * t20;
    H_g = H10;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_10;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−10) dQ
/// Operations per edge: 50 +, 91 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 482 +, 1123 ×, 153 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i10_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T ap_bp = bp0 * ap0 + ap1 * bp1 + ap2 * bp2;
  const T zeta2 = in.z * in.z;
  const T c = zeta2 + ap_ap;
  const T D = cross_cross + ab_ab * zeta2;
  const T h = cross1 * in.normal[1] + cross0 * in.normal[0] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T c_minus_b = ap_bp + zeta2;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  T J_10;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * ab_ab - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(2, 10, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
    J_10 = M_flat[4];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(2, 10, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
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
    const T t9 = ab_ab * J2 + t7 * ab_ap + t8 * a_minus_b;
    J_4 = (T(1) / T(2)) * t6 * t9;
    const T t10 = t8 * t8;
    const T t11 = t7 * t7;
    const T t12 = T(3) * ab_ab * t6 * t9 + T(2) * t10 * a_minus_b + T(2) * t11 * ab_ap;
    J_6 = (T(1) / T(8)) * t12 * t6;
    const T t13 = t10 * t8;
    const T t14 = t11 * t7;
    const T t15 = T(8) * t13 * a_minus_b + T(8) * t14 * ab_ap + T(5) * t12 * ab_ab * t6;
    J_8 = (T(1) / T(48)) * t6 * t15;
    const T t16 = t11 * t11;
    const T t17 = t10 * t10;
    J_10 = (T(1) / T(384)) * (T(7) * ab_ab * t6 * t15 + T(48) * t16 * ab_ap + T(48) * t17 * a_minus_b) * t6;
  }
  T H_f;
  T H_g;
  const T t18 = t2 - T(2) * zeta2;
  const T t19 = max(T(D - T(2) * ab_ab * zeta2), T(t1));
  if (t18 >= T(0) && t19 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(8, 10, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t20 = T(1) / zeta2;
    const T H2 = (theta - J_2 * h) * t20;
    const T H4 = -(h * J_4 - H2) * t20;
    const T H6 = -(h * J_6 - H4) * t20;
    const T H8 = (H6 - J_8 * h) * t20;
    const T H10 = -(J_10 * h - H8) * t20;
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
///     C(P) = ∬_Ω |P − Q|^(−11) dQ
/// Operations per edge: 49 +, 99 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 457 +, 1169 ×, 151 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i11_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T zeta2 = in.z * in.z;
  const T c = zeta2 + ap_ap;
  const T D = cross_cross + ab_ab * zeta2;
  const T h = in.normal[2] * cross2 + in.normal[1] * cross1 + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  T J_9;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * ab_ab - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(3, 9, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
    J_9 = M_flat[3];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(3, 9, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
    J_9 = M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = T(1) / D;
    const T t5 = T(1) / r1;
    const T t6 = T(1) / r0;
    const T t7 = t5 * a_minus_b + t6 * ab_ap;
    J_3 = t4 * t7;
    const T t8 = t6 * t6;
    const T t9 = t5 * t5;
    const T t10 = T(2) * ab_ab * t4 * t7 + t6 * ab_ap * t8 + t5 * a_minus_b * t9;
    J_5 = (T(1) / T(3)) * t4 * t10;
    const T t11 = t9 * t9;
    const T t12 = t8 * t8;
    const T t13 = T(3) * t5 * a_minus_b * t11 + T(3) * t6 * ab_ap * t12 + T(4) * ab_ab * t4 * t10;
    J_7 = (T(1) / T(15)) * t4 * t13;
    const T t14 = t12 * t8;
    const T t15 = t11 * t9;
    J_9 = (T(1) / T(35)) * t4 * (T(5) * t6 * ab_ap * t14 + T(5) * t5 * a_minus_b * t15 + T(2) * ab_ab * t4 * t13);
  }
  T H_f;
  const T t16 = t2 - T(2) * zeta2;
  const T t17 = max(T(D - T(2) * ab_ab * zeta2), T(t1));
  if (t16 >= T(0) && t17 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(9, 9, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((ab_ap * r1 + r0 * a_minus_b) * h * zeta, r0 * r1 * h * h - ab_ap * a_minus_b * zeta2) / zeta;
    const T t18 = T(1) / zeta2;
    const T H3 = (H1 - J_3 * h) * t18;
    const T H5 = -t18 * (J_5 * h - H3);
    const T H7 = t18 * (H5 - h * J_7);
    const T H9 = -t18 * (J_9 * h - H7);
    H_f = H9;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−11) dQ
/// Operations per edge: 52 +, 114 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 461 +, 1223 ×, 153 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i11_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T zeta2 = in.z * in.z;
  const T c = zeta2 + ap_ap;
  const T D = cross_cross + zeta2 * ab_ab;
  const T h = cross0 * in.normal[0] + cross1 * in.normal[1] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = zeta2 + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  T J_9;
  T J_11;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * ab_ab * t2 - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(3, 11, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
    J_9 = M_flat[3];
    J_11 = M_flat[4];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(3, 11, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
    J_9 = M_beyond[3];
    J_11 = M_beyond[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t4 = T(1) / D;
    const T t5 = T(1) / r1;
    const T t6 = T(1) / r0;
    const T t7 = a_minus_b * t5 + t6 * ab_ap;
    J_3 = t4 * t7;
    const T t8 = t5 * t5;
    const T t9 = t6 * t6;
    const T t10 = a_minus_b * t5 * t8 + t9 * t6 * ab_ap + T(2) * ab_ab * t4 * t7;
    J_5 = (T(1) / T(3)) * t10 * t4;
    const T t11 = t9 * t9;
    const T t12 = t8 * t8;
    const T t13 = T(4) * t10 * ab_ab * t4 + T(3) * t11 * t6 * ab_ap + T(3) * a_minus_b * t5 * t12;
    J_7 = (T(1) / T(15)) * t13 * t4;
    const T t14 = t11 * t9;
    const T t15 = t12 * t8;
    const T t16 = T(2) * t13 * ab_ab * t4 + T(5) * t14 * t6 * ab_ap + T(5) * a_minus_b * t5 * t15;
    J_9 = (T(1) / T(35)) * t4 * t16;
    const T t17 = t11 * t11;
    const T t18 = t12 * t12;
    J_11 = (T(1) / T(315)) * (T(35) * t17 * t6 * ab_ap + T(35) * a_minus_b * t5 * t18 + T(8) * ab_ab * t4 * t16) * t4;
  }
  T H_g;
  const T t19 = t2 - T(2) * zeta2;
  const T t20 = max(T(D - T(2) * zeta2 * ab_ab), T(t1));
  if (t19 >= T(0) && t20 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(11, 11, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((r1 * ab_ap + a_minus_b * r0) * h * zeta, h * h * r1 * r0 - zeta2 * a_minus_b * ab_ap) / zeta;
    const T t21 = T(1) / zeta2;
    const T H3 = (H1 - h * J_3) * t21;
    const T H5 = -t21 * (J_5 * h - H3);
    const T H7 = (H5 - h * J_7) * t21;
    const T H9 = t21 * (H7 - h * J_9);
    const T H11 = -(h * J_11 - H9) * t21;
    H_g = H11;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_11;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−11) dQ
/// Operations per edge: 52 +, 114 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 481 +, 1224 ×, 153 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i11_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = cross_cross + ab_ab * zeta2;
  const T h = cross1 * in.normal[1] + cross0 * in.normal[0] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  T J_9;
  T J_11;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * ab_ab * t2 - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(3, 11, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
    J_9 = M_flat[3];
    J_11 = M_flat[4];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(3, 11, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
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
    const T t7 = ab_ap * t5 + a_minus_b * t6;
    J_3 = t4 * t7;
    const T t8 = t5 * t5;
    const T t9 = t6 * t6;
    const T t10 = T(2) * ab_ab * t4 * t7 + t8 * ab_ap * t5 + a_minus_b * t9 * t6;
    J_5 = (T(1) / T(3)) * t10 * t4;
    const T t11 = t9 * t9;
    const T t12 = t8 * t8;
    const T t13 = T(3) * a_minus_b * t11 * t6 + T(4) * ab_ab * t10 * t4 + T(3) * t12 * ab_ap * t5;
    J_7 = (T(1) / T(15)) * t13 * t4;
    const T t14 = t12 * t8;
    const T t15 = t11 * t9;
    const T t16 = T(5) * t14 * ab_ap * t5 + T(5) * a_minus_b * t15 * t6 + T(2) * ab_ab * t13 * t4;
    J_9 = (T(1) / T(35)) * t16 * t4;
    const T t17 = t11 * t11;
    const T t18 = t12 * t12;
    J_11 = (T(1) / T(315)) * (T(8) * ab_ab * t16 * t4 + T(35) * a_minus_b * t17 * t6 + T(35) * t18 * ab_ap * t5) * t4;
  }
  T H_f;
  T H_g;
  const T t19 = t2 - T(2) * zeta2;
  const T t20 = max(T(D - T(2) * ab_ab * zeta2), T(t1));
  if (t19 >= T(0) && t20 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(9, 11, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * (a_minus_b * r0 + ab_ap * r1) * h, r0 * h * h * r1 - a_minus_b * ab_ap * zeta2) / zeta;
    const T t21 = T(1) / zeta2;
    const T H3 = (H1 - J_3 * h) * t21;
    const T H5 = (H3 - J_5 * h) * t21;
    const T H7 = (H5 - J_7 * h) * t21;
    const T H9 = -(J_9 * h - H7) * t21;
    const T H11 = (H9 - J_11 * h) * t21;
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
///     C(P) = ∬_Ω |P − Q|^(−12) dQ
/// Operations per edge: 50 +, 91 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 462 +, 1102 ×, 153 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i12_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T zeta2 = in.z * in.z;
  const T c = zeta2 + ap_ap;
  const T D = cross_cross + zeta2 * ab_ab;
  const T h = cross0 * in.normal[0] + cross1 * in.normal[1] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = zeta2 + bp_bp;
  const T c_minus_b = zeta2 + ap_bp;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  T J_10;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * ab_ab - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(2, 10, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
    J_10 = M_flat[4];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(2, 10, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
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
    const T t6 = T(1) / D;
    const T t7 = T(1) / c;
    const T t8 = T(1) / q1;
    const T t9 = ab_ab * J2 + ab_ap * t7 + a_minus_b * t8;
    J_4 = (T(1) / T(2)) * t6 * t9;
    const T t10 = t8 * t8;
    const T t11 = t7 * t7;
    const T t12 = T(2) * a_minus_b * t10 + T(2) * ab_ap * t11 + T(3) * ab_ab * t6 * t9;
    J_6 = (T(1) / T(8)) * t12 * t6;
    const T t13 = t11 * t7;
    const T t14 = t10 * t8;
    const T t15 = T(8) * ab_ap * t13 + T(8) * a_minus_b * t14 + T(5) * ab_ab * t12 * t6;
    J_8 = (T(1) / T(48)) * t15 * t6;
    const T t16 = t10 * t10;
    const T t17 = t11 * t11;
    J_10 = (T(1) / T(384)) * t6 * (T(48) * a_minus_b * t16 + T(48) * ab_ap * t17 + T(7) * ab_ab * t15 * t6);
  }
  T H_f;
  const T t18 = t2 - T(2) * zeta2;
  const T t19 = max(T(D - T(2) * zeta2 * ab_ab), T(t1));
  if (t18 >= T(0) && t19 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(10, 10, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t20 = T(1) / zeta2;
    const T H2 = -t20 * (h * J_2 - theta);
    const T H4 = -t20 * (J_4 * h - H2);
    const T H6 = -(h * J_6 - H4) * t20;
    const T H8 = t20 * (H6 - h * J_8);
    const T H10 = t20 * (H8 - J_10 * h);
    H_f = H10;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−12) dQ
/// Operations per edge: 53 +, 104 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 466 +, 1137 ×, 155 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i12_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ab1 * ap2 - ab2 * ap1;
  const T cross1 = ab2 * ap0 - ab0 * ap2;
  const T cross2 = ab0 * ap1 - ab1 * ap0;
  const T cross_cross = cross0 * cross0 + cross2 * cross2 + cross1 * cross1;
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T zeta2 = in.z * in.z;
  const T c = zeta2 + ap_ap;
  const T D = cross_cross + ab_ab * zeta2;
  const T h = cross0 * in.normal[0] + cross1 * in.normal[1] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T c_minus_b = zeta2 + ap_bp;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  T J_10;
  T J_12;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -a_minus_b * ab_ap;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * ab_ab * t2 - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(2, 12, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
    J_10 = M_flat[4];
    J_12 = M_flat[5];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(2, 12, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
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
    const T t6 = T(1) / D;
    const T t7 = T(1) / c;
    const T t8 = T(1) / q1;
    const T t9 = ab_ap * t7 + a_minus_b * t8 + ab_ab * J2;
    J_4 = (T(1) / T(2)) * t6 * t9;
    const T t10 = t8 * t8;
    const T t11 = t7 * t7;
    const T t12 = T(2) * a_minus_b * t10 + T(3) * ab_ab * t6 * t9 + T(2) * ab_ap * t11;
    J_6 = (T(1) / T(8)) * t6 * t12;
    const T t13 = t10 * t8;
    const T t14 = t11 * t7;
    const T t15 = T(8) * a_minus_b * t13 + T(5) * ab_ab * t6 * t12 + T(8) * ab_ap * t14;
    J_8 = (T(1) / T(48)) * t15 * t6;
    const T t16 = t11 * t11;
    const T t17 = t10 * t10;
    const T t18 = T(7) * t15 * ab_ab * t6 + T(48) * ab_ap * t16 + T(48) * a_minus_b * t17;
    J_10 = (T(1) / T(384)) * t6 * t18;
    const T t19 = t16 * t7;
    const T t20 = t17 * t8;
    J_12 = (T(1) / T(1280)) * t6 * (T(3) * ab_ab * t6 * t18 + T(128) * ab_ap * t19 + T(128) * a_minus_b * t20);
  }
  T H_g;
  const T t21 = t2 - T(2) * zeta2;
  const T t22 = max(T(D - T(2) * ab_ab * zeta2), T(t1));
  if (t21 >= T(0) && t22 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(12, 12, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t23 = T(1) / zeta2;
    const T H2 = -(J_2 * h - theta) * t23;
    const T H4 = -(J_4 * h - H2) * t23;
    const T H6 = (H4 - h * J_6) * t23;
    const T H8 = (H6 - J_8 * h) * t23;
    const T H10 = -(J_10 * h - H8) * t23;
    const T H12 = (H10 - h * J_12) * t23;
    H_g = H12;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_12;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−12) dQ
/// Operations per edge: 53 +, 104 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 486 +, 1158 ×, 155 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i12_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T cross0 = ap2 * ab1 - ap1 * ab2;
  const T cross1 = ap0 * ab2 - ap2 * ab0;
  const T cross2 = ap1 * ab0 - ap0 * ab1;
  const T cross_cross = cross1 * cross1 + cross0 * cross0 + cross2 * cross2;
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T zeta2 = in.z * in.z;
  const T c = zeta2 + ap_ap;
  const T D = zeta2 * ab_ab + cross_cross;
  const T h = cross1 * in.normal[1] + cross0 * in.normal[0] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = zeta2 + bp_bp;
  const T c_minus_b = zeta2 + ap_bp;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  T J_10;
  T J_12;
  const T t0 = D - T(2) * ab_ab * ab_ab;
  const T t1 = -ab_ap * a_minus_b;
  const T t2 = min(T(c), T(q1));
  const T t3 = (T(7) / T(10)) * t2 * ab_ab - D;
  if (t0 >= T(0)) {
    // P far from the line (D ≥ 2a²): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(2, 12, 0, ab_ab, ab_ap, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
    J_10 = M_flat[4];
    J_12 = M_flat[5];
  } else if (t1 >= T(0) && t3 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(2, 12, 0, ab_ab, ab_ap, D, c, q1, M_beyond.data());
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
    const T t6 = T(1) / c;
    const T t7 = T(1) / q1;
    const T t8 = J2 * ab_ab + ab_ap * t6 + t7 * a_minus_b;
    const T t9 = T(1) / D;
    J_4 = (T(1) / T(2)) * t8 * t9;
    const T t10 = t7 * t7;
    const T t11 = t6 * t6;
    const T t12 = T(3) * t8 * ab_ab * t9 + T(2) * t10 * a_minus_b + T(2) * ab_ap * t11;
    J_6 = (T(1) / T(8)) * t12 * t9;
    const T t13 = t10 * t7;
    const T t14 = t11 * t6;
    const T t15 = T(8) * t13 * a_minus_b + T(8) * ab_ap * t14 + T(5) * t12 * ab_ab * t9;
    J_8 = (T(1) / T(48)) * t15 * t9;
    const T t16 = t11 * t11;
    const T t17 = t10 * t10;
    const T t18 = T(48) * ab_ap * t16 + T(48) * t17 * a_minus_b + T(7) * t15 * ab_ab * t9;
    J_10 = (T(1) / T(384)) * t18 * t9;
    const T t19 = t16 * t6;
    const T t20 = t17 * t7;
    J_12 = (T(1) / T(1280)) * (T(128) * ab_ap * t19 + T(3) * t18 * ab_ab * t9 + T(128) * t20 * a_minus_b) * t9;
  }
  T H_f;
  T H_g;
  const T t21 = t2 - T(2) * zeta2;
  const T t22 = max(T(D - T(2) * zeta2 * ab_ab), T(t1));
  if (t21 >= T(0) && t22 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(10, 12, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t23 = T(1) / zeta2;
    const T H2 = -t23 * (h * J_2 - theta);
    const T H4 = t23 * (H2 - J_4 * h);
    const T H6 = t23 * (H4 - h * J_6);
    const T H8 = t23 * (H6 - h * J_8);
    const T H10 = -t23 * (J_10 * h - H8);
    const T H12 = -t23 * (h * J_12 - H10);
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
