// generated/polygon_inverse.hpp — polygon edge kernels of the inverse family.
//
// GENERATED FILE: DO NOT EDIT. Regenerate with
//     skelconv-codegen --inverse 1:16 --cauchy 1:16 --compact 2:16 --weights 0:3 --polygon-inverse 3:12 --polygon-cauchy 3:12 --polygon-compact 4:12 --scalis-inverse 2:10 --scalis-cauchy 2:10 --scalis-compact 2:10 --out generated
// Generator: skelconv-codegen 0.1.0 (GiNaC 1.8.6)
// From: codegen/segment_families.cpp (the families) and codegen/segment_moments.cpp
// (recurrence (1) of Hubert & Cani unrolled; docs/mathematics.md §2, Hubert 2012 §3).
// Polygons (docs/mathematics.md §3, Hubert 2012 §5–8): the terms of one edge of the contour sum
// (codegen/polygon_families.cpp), on the segment forms of the edge;
// skelconv/primitives/polygon_field.hpp adds them up.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include <skelconv/detail/exact_cross.hpp>
#include <skelconv/detail/gauss_moments.hpp>
#include <skelconv/detail/polygon_angle_integrals.hpp>
#include <skelconv/primitives/polygon_edge_input.hpp>
#include <skelconv/primitives/segment_input.hpp>
#include <skelconv/detail/stable_recurrence.hpp>
#include <skelconv/detail/support_gap.hpp>

namespace skelconv::generated {

/// The terms of one edge for f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−3) dQ
/// Operations per edge: 43 +, 50 ×, 1 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 174 +, 196 ×, 23 /, 22 sqrt, 3 atan, 0 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i3_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = in.p_lo[0] + ap_hi0;
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = in.p_lo[1] + ap_hi1;
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = ap_hi2 + in.p_lo[2];
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    const T t1 = ab1 * in.p_lo[2] + exact_cross[0] - in.p_lo[1] * ab2;
    cross0 = t1;
    const T t2 = exact_cross[1] + in.p_lo[0] * ab2 - in.p_lo[2] * ab0;
    cross1 = t2;
    const T t3 = in.p_lo[1] * ab0 + exact_cross[2] - ab1 * in.p_lo[0];
    cross2 = t3;
    cross_cross = t2 * t2 + t3 * t3 + t1 * t1;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = bp1 * ap1 + ap2 * bp2 + ap0 * bp0;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = cross_cross + zeta2 * ab_ab;
  const T h = cross1 * in.normal[1] + in.normal[0] * cross0 + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = zeta2 + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T H_f;
  const T t4 = min(T(c), T(q1)) - T(2) * zeta2;
  const T t5 = max(T(D - T(2) * zeta2 * ab_ab), T(-a_minus_b * ab_ap));
  if (t4 >= T(0) && t5 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(1, 1, h, ab_ab, zeta2, -ab_ap, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(h * zeta * (r1 * ab_ap + r0 * a_minus_b), h * h * r0 * r1 - zeta2 * a_minus_b * ab_ap) / zeta;
    H_f = H1;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−3) dQ
/// Operations per edge: 72 +, 78 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 548 +, 1072 ×, 145 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i3_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = ap_hi0 + in.p_lo[0];
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = in.p_lo[1] + ap_hi1;
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = ap_hi2 + in.p_lo[2];
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = bp_hi2 + in.p_lo[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ap2 * ab0;
  const T plain_cross2 = ap1 * ab0 - ab1 * ap0;
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    const T t1 = exact_cross[0] + ab1 * in.p_lo[2] - ab2 * in.p_lo[1];
    cross0 = t1;
    cross1 = exact_cross[1] + ab2 * in.p_lo[0] - ab0 * in.p_lo[2];
    const T t2 = in.p_lo[1] * ab0 + exact_cross[2] - ab1 * in.p_lo[0];
    cross2 = t2;
    const T t3 = ab0 * in.p_lo[2] - exact_cross[1] - ab2 * in.p_lo[0];
    cross_cross = t1 * t1 + t3 * t3 + t2 * t2;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T ap_bp = bp2 * ap2 + ap1 * bp1 + bp0 * ap0;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = zeta2 * ab_ab + cross_cross;
  const T h = cross1 * in.normal[1] + in.normal[0] * cross0 + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-T(2) * ab_ab - ab_ap))))), T(c - zeta2 - (T(15) / T(4)) * ab_ab - ab_ap));
  const T t5 = -a_minus_b * ab_ap;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * ab_ab - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 1> M_flat;
    segment_moments_far_field<T>(3, 3, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(3, 3, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    J_3 = (a_minus_b / r1 + ab_ap / r0) / D;
  }
  T H_g;
  const T t8 = t6 - T(2) * zeta2;
  const T t9 = max(T(D - T(2) * zeta2 * ab_ab), T(t5));
  if (t8 >= T(0) && t9 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t10 = -ab_ap;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(3, 3, h, ab_ab, zeta2, t10, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((r1 * ab_ap + r0 * a_minus_b) * h * zeta, r0 * r1 * h * h - zeta2 * a_minus_b * ab_ap) / zeta;
    const T H3 = -(J_3 * h - H1) / zeta2;
    H_g = H3;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_3;
}

/// The terms of one edge for f and ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−3) dQ
/// Operations per edge: 72 +, 78 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 572 +, 1077 ×, 145 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i3_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = ap_hi0 + in.p_lo[0];
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = in.p_lo[1] + ap_hi1;
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = ap_hi2 + in.p_lo[2];
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = ab1 * in.p_lo[2] + exact_cross[0] - in.p_lo[1] * ab2;
    cross1 = exact_cross[1] + in.p_lo[0] * ab2 - ab0 * in.p_lo[2];
    cross2 = exact_cross[2] + in.p_lo[1] * ab0 - ab1 * in.p_lo[0];
    const T t1 = ab0 * in.p_lo[2] - exact_cross[1] - in.p_lo[0] * ab2;
    const T t2 = ab1 * in.p_lo[0] - exact_cross[2] - in.p_lo[1] * ab0;
    const T t3 = in.p_lo[1] * ab2 - ab1 * in.p_lo[2] - exact_cross[0];
    cross_cross = t1 * t1 + t2 * t2 + t3 * t3;
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = bp1 * ap1 + ap0 * bp0 + bp2 * ap2;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = zeta2 * ab_ab + cross_cross;
  const T h = cross1 * in.normal[1] + in.normal[0] * cross0 + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = zeta2 + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-T(2) * ab_ab - ab_ap))))), T(c - zeta2 - (T(15) / T(4)) * ab_ab - ab_ap));
  const T t5 = -ab_ap * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * ab_ab * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 1> M_flat;
    segment_moments_far_field<T>(3, 3, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(3, 3, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    J_3 = (ab_ap / r0 + a_minus_b / r1) / D;
  }
  T H_f;
  T H_g;
  const T t8 = t6 - T(2) * zeta2;
  const T t9 = max(T(D - T(2) * zeta2 * ab_ab), T(t5));
  if (t8 >= T(0) && t9 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t10 = -ab_ap;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(1, 3, h, ab_ab, zeta2, t10, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(h * (ab_ap * r1 + r0 * a_minus_b) * zeta, h * h * r0 * r1 - zeta2 * ab_ap * a_minus_b) / zeta;
    const T H3 = (H1 - h * J_3) / zeta2;
    H_f = H1;
    H_g = H3;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
  out.S_g = H_g;
  out.J_g = J_3;
}

/// The terms of one edge for f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−4) dQ
/// Operations per edge: 70 +, 69 ×, 2 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 547 +, 1028 ×, 145 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i4_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = ap_hi0 + in.p_lo[0];
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = in.p_lo[1] + ap_hi1;
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = ap_hi2 + in.p_lo[2];
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = bp_hi2 + in.p_lo[2];
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    const T t1 = exact_cross[0] + ab1 * in.p_lo[2] - ab2 * in.p_lo[1];
    cross0 = t1;
    const T t2 = exact_cross[1] + ab2 * in.p_lo[0] - ab0 * in.p_lo[2];
    cross1 = t2;
    const T t3 = ab0 * in.p_lo[1] + exact_cross[2] - ab1 * in.p_lo[0];
    cross2 = t3;
    cross_cross = t1 * t1 + t2 * t2 + t3 * t3;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T ap_bp = ap1 * bp1 + bp0 * ap0 + bp2 * ap2;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = zeta2 * ab_ab + cross_cross;
  const T h = in.normal[2] * cross2 + in.normal[0] * cross0 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T c_minus_b = zeta2 + ap_bp;
  T J_2;
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-ab_ap - T(2) * ab_ab))))), T(c - ab_ap - zeta2 - (T(15) / T(4)) * ab_ab));
  const T t5 = -ab_ap * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * ab_ab - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 1> M_flat;
    segment_moments_far_field<T>(2, 2, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(2, 2, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T J2 = atan2(t8, c_minus_b) / t8;
    J_2 = J2;
  }
  T H_f;
  const T t9 = t6 - T(2) * zeta2;
  const T t10 = max(T(D - T(2) * zeta2 * ab_ab), T(t5));
  if (t9 >= T(0) && t10 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t11 = -ab_ap;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(2, 2, h, ab_ab, zeta2, t11, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T H2 = (theta - h * J_2) / zeta2;
    H_f = H2;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−4) dQ
/// Operations per edge: 73 +, 76 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 551 +, 1060 ×, 147 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i4_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = in.p_lo[0] + ap_hi0;
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = ap_hi1 + in.p_lo[1];
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = in.p_lo[2] + ap_hi2;
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ap1 * ab1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T plain_cross0 = ap2 * ab1 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ap2 * ab0;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    const T t1 = exact_cross[0] + in.p_lo[2] * ab1 - ab2 * in.p_lo[1];
    cross0 = t1;
    const T t2 = in.p_lo[0] * ab2 + exact_cross[1] - in.p_lo[2] * ab0;
    cross1 = t2;
    const T t3 = exact_cross[2] + ab0 * in.p_lo[1] - in.p_lo[0] * ab1;
    cross2 = t3;
    cross_cross = t3 * t3 + t1 * t1 + t2 * t2;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + bp1 * ap1 + bp0 * ap0;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = cross_cross + ab_ab * zeta2;
  const T h = in.normal[1] * cross1 + in.normal[0] * cross0 + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T c_minus_b = ap_bp + zeta2;
  T J_2;
  T J_4;
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-T(2) * ab_ab - ab_ap))))), T(c - (T(15) / T(4)) * ab_ab - ab_ap - zeta2));
  const T t5 = -ab_ap * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * ab_ab - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 2> M_flat;
    segment_moments_far_field<T>(2, 4, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(2, 4, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = t9 * atan2(t8, c_minus_b);
    J_2 = J2;
    const T t10 = T(1) / D;
    J_4 = (T(1) / T(2)) * t10 * (ab_ap / c + a_minus_b / q1 + ab_ab * J2);
  }
  T H_g;
  const T t11 = t6 - T(2) * zeta2;
  const T t12 = max(T(D - T(2) * ab_ab * zeta2), T(t5));
  if (t11 >= T(0) && t12 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t13 = -ab_ap;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(4, 4, h, ab_ab, zeta2, t13, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t14 = T(1) / zeta2;
    const T H2 = -(J_2 * h - theta) * t14;
    const T H4 = (H2 - J_4 * h) * t14;
    H_g = H4;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_4;
}

/// The terms of one edge for f and ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−4) dQ
/// Operations per edge: 73 +, 76 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 575 +, 1085 ×, 147 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i4_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = ap_hi0 + in.p_lo[0];
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = in.p_lo[1] + ap_hi1;
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = in.p_lo[2] + ap_hi2;
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ap1 * ab2;
  const T plain_cross1 = ab2 * ap0 - ap2 * ab0;
  const T plain_cross2 = ap1 * ab0 - ab1 * ap0;
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0] + in.p_lo[2] * ab1 - ab2 * in.p_lo[1];
    const T t1 = ab2 * in.p_lo[0] + exact_cross[1] - in.p_lo[2] * ab0;
    cross1 = t1;
    cross2 = in.p_lo[1] * ab0 + exact_cross[2] - ab1 * in.p_lo[0];
    const T t2 = ab2 * in.p_lo[1] - exact_cross[0] - in.p_lo[2] * ab1;
    const T t3 = ab1 * in.p_lo[0] - in.p_lo[1] * ab0 - exact_cross[2];
    cross_cross = t2 * t2 + t3 * t3 + t1 * t1;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp0 * ab0 + ab1 * bp1;
  const T ap_bp = ap1 * bp1 + bp2 * ap2 + bp0 * ap0;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = zeta2 * ab_ab + cross_cross;
  const T h = in.normal[0] * cross0 + in.normal[2] * cross2 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T c_minus_b = zeta2 + ap_bp;
  T J_2;
  T J_4;
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-T(2) * ab_ab - ab_ap))))), T(c - zeta2 - (T(15) / T(4)) * ab_ab - ab_ap));
  const T t5 = -a_minus_b * ab_ap;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * ab_ab - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 2> M_flat;
    segment_moments_far_field<T>(2, 4, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(2, 4, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = atan2(t8, c_minus_b) * t9;
    J_2 = J2;
    const T t10 = T(1) / D;
    J_4 = (T(1) / T(2)) * (a_minus_b / q1 + J2 * ab_ab + ab_ap / c) * t10;
  }
  T H_f;
  T H_g;
  const T t11 = t6 - T(2) * zeta2;
  const T t12 = max(T(D - T(2) * zeta2 * ab_ab), T(t5));
  if (t11 >= T(0) && t12 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t13 = -ab_ap;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(2, 4, h, ab_ab, zeta2, t13, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t14 = T(1) / zeta2;
    const T H2 = t14 * (theta - h * J_2);
    const T H4 = t14 * (H2 - J_4 * h);
    H_f = H2;
    H_g = H4;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
  out.S_g = H_g;
  out.J_g = J_4;
}

/// The terms of one edge for f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−5) dQ
/// Operations per edge: 72 +, 78 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 546 +, 1070 ×, 145 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i5_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = ap_hi0 + in.p_lo[0];
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = ap_hi1 + in.p_lo[1];
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = bp_hi1 + in.p_lo[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = ap_hi2 + in.p_lo[2];
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    const T t1 = in.p_lo[2] * ab1 + exact_cross[0] - in.p_lo[1] * ab2;
    cross0 = t1;
    const T t2 = exact_cross[1] + ab2 * in.p_lo[0] - ab0 * in.p_lo[2];
    cross1 = t2;
    const T t3 = ab0 * in.p_lo[1] + exact_cross[2] - ab1 * in.p_lo[0];
    cross2 = t3;
    cross_cross = t3 * t3 + t1 * t1 + t2 * t2;
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = bp1 * ap1 + ap0 * bp0 + bp2 * ap2;
  const T zeta2 = in.z * in.z;
  const T c = zeta2 + ap_ap;
  const T D = zeta2 * ab_ab + cross_cross;
  const T h = cross1 * in.normal[1] + in.normal[0] * cross0 + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = zeta2 + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-T(2) * ab_ab - ab_ap))))), T(c - zeta2 - (T(15) / T(4)) * ab_ab - ab_ap));
  const T t5 = -ab_ap * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * ab_ab * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 1> M_flat;
    segment_moments_far_field<T>(3, 3, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(3, 3, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    J_3 = (ab_ap / r0 + a_minus_b / r1) / D;
  }
  T H_f;
  const T t8 = t6 - T(2) * zeta2;
  const T t9 = max(T(D - T(2) * zeta2 * ab_ab), T(t5));
  if (t8 >= T(0) && t9 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t10 = -ab_ap;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(3, 3, h, ab_ab, zeta2, t10, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(h * zeta * (ab_ap * r1 + r0 * a_minus_b), h * h * r0 * r1 - zeta2 * ab_ap * a_minus_b) / zeta;
    const T H3 = -(h * J_3 - H1) / zeta2;
    H_f = H3;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−5) dQ
/// Operations per edge: 75 +, 91 ×, 7 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 550 +, 1122 ×, 147 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i5_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = in.p_lo[0] + ap_hi0;
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = ap_hi1 + in.p_lo[1];
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = in.p_lo[2] + ap_hi2;
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ap1 * ab1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T plain_cross0 = ap2 * ab1 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ap2 * ab0;
  const T plain_cross2 = ab0 * ap1 - ap0 * ab1;
  const T plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    const T t1 = exact_cross[0] + in.p_lo[2] * ab1 - ab2 * in.p_lo[1];
    cross0 = t1;
    const T t2 = in.p_lo[0] * ab2 + exact_cross[1] - ab0 * in.p_lo[2];
    cross1 = t2;
    const T t3 = exact_cross[2] + ab0 * in.p_lo[1] - in.p_lo[0] * ab1;
    cross2 = t3;
    cross_cross = t3 * t3 + t1 * t1 + t2 * t2;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = bp1 * ab1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + bp0 * ap0 + bp1 * ap1;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = cross_cross + zeta2 * ab_ab;
  const T h = in.normal[1] * cross1 + cross2 * in.normal[2] + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-ab_ap - T(2) * ab_ab))))), T(c - ab_ap - zeta2 - (T(15) / T(4)) * ab_ab));
  const T t5 = -ab_ap * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * ab_ab - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 2> M_flat;
    segment_moments_far_field<T>(3, 5, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(3, 5, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / r0;
    const T t9 = T(1) / r1;
    const T t10 = ab_ap * t8 + t9 * a_minus_b;
    const T t11 = T(1) / D;
    J_3 = t10 * t11;
    J_5 = (T(1) / T(3)) * (ab_ap * t8 / c + t9 * a_minus_b / q1 + T(2) * t10 * t11 * ab_ab) * t11;
  }
  T H_g;
  const T t12 = t6 - T(2) * zeta2;
  const T t13 = max(T(D - T(2) * zeta2 * ab_ab), T(t5));
  if (t12 >= T(0) && t13 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t14 = -ab_ap;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(5, 5, h, ab_ab, zeta2, t14, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((ab_ap * r1 + r0 * a_minus_b) * h * zeta, r0 * h * h * r1 - ab_ap * zeta2 * a_minus_b) / zeta;
    const T t15 = T(1) / zeta2;
    const T H3 = t15 * (H1 - J_3 * h);
    const T H5 = -(J_5 * h - H3) * t15;
    H_g = H5;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_5;
}

/// The terms of one edge for f and ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−5) dQ
/// Operations per edge: 75 +, 91 ×, 7 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 574 +, 1127 ×, 147 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i5_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = in.p_lo[0] + ap_hi0;
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = ap_hi1 + in.p_lo[1];
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = in.p_lo[2] + ap_hi2;
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ap1 * ab1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0] + in.p_lo[2] * ab1 - ab2 * in.p_lo[1];
    cross1 = exact_cross[1] + in.p_lo[0] * ab2 - in.p_lo[2] * ab0;
    const T t1 = ab0 * in.p_lo[1] + exact_cross[2] - in.p_lo[0] * ab1;
    cross2 = t1;
    const T t2 = in.p_lo[2] * ab0 - exact_cross[1] - in.p_lo[0] * ab2;
    const T t3 = ab2 * in.p_lo[1] - exact_cross[0] - in.p_lo[2] * ab1;
    cross_cross = t2 * t2 + t3 * t3 + t1 * t1;
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = cross_cross + zeta2 * ab_ab;
  const T h = cross2 * in.normal[2] + in.normal[0] * cross0 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-ab_ap - T(2) * ab_ab))))), T(c - ab_ap - zeta2 - (T(15) / T(4)) * ab_ab));
  const T t5 = -ab_ap * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * ab_ab - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 2> M_flat;
    segment_moments_far_field<T>(3, 5, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(3, 5, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / r0;
    const T t9 = T(1) / r1;
    const T t10 = ab_ap * t8 + t9 * a_minus_b;
    const T t11 = T(1) / D;
    J_3 = t10 * t11;
    J_5 = (T(1) / T(3)) * t11 * (ab_ap * t8 / c + t9 * a_minus_b / q1 + T(2) * t10 * t11 * ab_ab);
  }
  T H_f;
  T H_g;
  const T t12 = t6 - T(2) * zeta2;
  const T t13 = max(T(D - T(2) * zeta2 * ab_ab), T(t5));
  if (t12 >= T(0) && t13 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t14 = -ab_ap;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(3, 5, h, ab_ab, zeta2, t14, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * (r0 * a_minus_b + ab_ap * r1) * h, r0 * h * h * r1 - ab_ap * zeta2 * a_minus_b) / zeta;
    const T t15 = T(1) / zeta2;
    const T H3 = t15 * (H1 - J_3 * h);
    const T H5 = -t15 * (J_5 * h - H3);
    H_f = H3;
    H_g = H5;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
  out.S_g = H_g;
  out.J_g = J_5;
}

/// The terms of one edge for f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−6) dQ
/// Operations per edge: 73 +, 76 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 553 +, 1062 ×, 147 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i6_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = in.p_lo[0] + ap_hi0;
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = in.p_lo[1] + ap_hi1;
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = ap_hi2 + in.p_lo[2];
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
  const T plain_cross2 = ap1 * ab0 - ab1 * ap0;
  const T plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0] + ab1 * in.p_lo[2] - in.p_lo[1] * ab2;
    const T t1 = exact_cross[1] + in.p_lo[0] * ab2 - ab0 * in.p_lo[2];
    cross1 = t1;
    const T t2 = exact_cross[2] + in.p_lo[1] * ab0 - ab1 * in.p_lo[0];
    cross2 = t2;
    const T t3 = in.p_lo[1] * ab2 - exact_cross[0] - ab1 * in.p_lo[2];
    cross_cross = t2 * t2 + t1 * t1 + t3 * t3;
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + bp2 * ap2;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = cross_cross + zeta2 * ab_ab;
  const T h = in.normal[2] * cross2 + cross1 * in.normal[1] + cross0 * in.normal[0];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = zeta2 + bp_bp;
  const T c_minus_b = zeta2 + ap_bp;
  T J_2;
  T J_4;
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-T(2) * ab_ab - ab_ap))))), T(c - zeta2 - (T(15) / T(4)) * ab_ab - ab_ap));
  const T t5 = -a_minus_b * ab_ap;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * ab_ab * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 2> M_flat;
    segment_moments_far_field<T>(2, 4, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(2, 4, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = atan2(t8, c_minus_b) * t9;
    J_2 = J2;
    const T t10 = T(1) / D;
    J_4 = (T(1) / T(2)) * t10 * (ab_ap / c + J2 * ab_ab + a_minus_b / q1);
  }
  T H_f;
  const T t11 = t6 - T(2) * zeta2;
  const T t12 = max(T(D - T(2) * zeta2 * ab_ab), T(t5));
  if (t11 >= T(0) && t12 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t13 = -ab_ap;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(4, 4, h, ab_ab, zeta2, t13, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t14 = T(1) / zeta2;
    const T H2 = t14 * (theta - h * J_2);
    const T H4 = (H2 - h * J_4) * t14;
    H_f = H4;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−6) dQ
/// Operations per edge: 76 +, 91 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 559 +, 1097 ×, 149 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i6_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = in.p_lo[0] + ap_hi0;
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = ap_hi1 + in.p_lo[1];
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = in.p_lo[2] + ap_hi2;
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T plain_cross0 = ap2 * ab1 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ap2 * ab0;
  const T plain_cross2 = ab0 * ap1 - ap0 * ab1;
  const T plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0] + in.p_lo[2] * ab1 - ab2 * in.p_lo[1];
    cross1 = exact_cross[1] + in.p_lo[0] * ab2 - ab0 * in.p_lo[2];
    const T t1 = exact_cross[2] + ab0 * in.p_lo[1] - in.p_lo[0] * ab1;
    cross2 = t1;
    const T t2 = ab2 * in.p_lo[1] - exact_cross[0] - in.p_lo[2] * ab1;
    const T t3 = ab0 * in.p_lo[2] - exact_cross[1] - in.p_lo[0] * ab2;
    cross_cross = t2 * t2 + t3 * t3 + t1 * t1;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = bp1 * ab1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + bp0 * ap0 + bp1 * ap1;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = cross_cross + ab_ab * zeta2;
  const T h = in.normal[0] * cross0 + in.normal[1] * cross1 + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T c_minus_b = ap_bp + zeta2;
  T J_2;
  T J_4;
  T J_6;
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-T(2) * ab_ab - ab_ap))))), T(c - (T(15) / T(4)) * ab_ab - ab_ap - zeta2));
  const T t5 = -a_minus_b * ab_ap;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * ab_ab * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 3> M_flat;
    segment_moments_far_field<T>(2, 6, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(2, 6, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = t9 * atan2(t8, c_minus_b);
    J_2 = J2;
    const T t10 = T(1) / c;
    const T t11 = T(1) / q1;
    const T t12 = t10 * ab_ap + ab_ab * J2 + a_minus_b * t11;
    const T t13 = T(1) / D;
    J_4 = (T(1) / T(2)) * t12 * t13;
    const T t14 = t11 * t11;
    const T t15 = t10 * t10;
    J_6 = (T(1) / T(8)) * (T(2) * a_minus_b * t14 + T(3) * ab_ab * t12 * t13 + T(2) * t15 * ab_ap) * t13;
  }
  T H_g;
  const T t16 = t6 - T(2) * zeta2;
  const T t17 = max(T(D - T(2) * ab_ab * zeta2), T(t5));
  if (t16 >= T(0) && t17 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t18 = -ab_ap;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(6, 6, h, ab_ab, zeta2, t18, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t19 = T(1) / zeta2;
    const T H2 = t19 * (theta - J_2 * h);
    const T H4 = -(J_4 * h - H2) * t19;
    const T H6 = (H4 - h * J_6) * t19;
    H_g = H6;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_6;
}

/// The terms of one edge for f and ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−6) dQ
/// Operations per edge: 76 +, 91 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 579 +, 1118 ×, 149 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i6_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = in.p_lo[0] + ap_hi0;
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = ap_hi1 + in.p_lo[1];
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = in.p_lo[2] + ap_hi2;
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T plain_cross0 = ap2 * ab1 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ap2 * ab0;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0] + in.p_lo[2] * ab1 - ab2 * in.p_lo[1];
    const T t1 = in.p_lo[0] * ab2 + exact_cross[1] - ab0 * in.p_lo[2];
    cross1 = t1;
    cross2 = exact_cross[2] + ab0 * in.p_lo[1] - in.p_lo[0] * ab1;
    const T t2 = ab2 * in.p_lo[1] - exact_cross[0] - in.p_lo[2] * ab1;
    const T t3 = in.p_lo[0] * ab1 - exact_cross[2] - ab0 * in.p_lo[1];
    cross_cross = t2 * t2 + t1 * t1 + t3 * t3;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + bp1 * ap1 + bp0 * ap0;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = cross_cross + ab_ab * zeta2;
  const T h = in.normal[0] * cross0 + cross2 * in.normal[2] + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T c_minus_b = ap_bp + zeta2;
  T J_2;
  T J_4;
  T J_6;
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-T(2) * ab_ab - ab_ap))))), T(c - (T(15) / T(4)) * ab_ab - ab_ap - zeta2));
  const T t5 = -a_minus_b * ab_ap;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * ab_ab * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 3> M_flat;
    segment_moments_far_field<T>(2, 6, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(2, 6, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = t9 * atan2(t8, c_minus_b);
    J_2 = J2;
    const T t10 = T(1) / D;
    const T t11 = T(1) / c;
    const T t12 = T(1) / q1;
    const T t13 = ab_ap * t11 + ab_ab * J2 + a_minus_b * t12;
    J_4 = (T(1) / T(2)) * t10 * t13;
    const T t14 = t12 * t12;
    const T t15 = t11 * t11;
    J_6 = (T(1) / T(8)) * t10 * (T(3) * ab_ab * t10 * t13 + T(2) * a_minus_b * t14 + T(2) * ab_ap * t15);
  }
  T H_f;
  T H_g;
  const T t16 = t6 - T(2) * zeta2;
  const T t17 = max(T(D - T(2) * ab_ab * zeta2), T(t5));
  if (t16 >= T(0) && t17 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t18 = -ab_ap;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(4, 6, h, ab_ab, zeta2, t18, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t19 = T(1) / zeta2;
    const T H2 = -(J_2 * h - theta) * t19;
    const T H4 = -(J_4 * h - H2) * t19;
    const T H6 = (H4 - h * J_6) * t19;
    H_f = H4;
    H_g = H6;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
  out.S_g = H_g;
  out.J_g = J_6;
}

/// The terms of one edge for f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−7) dQ
/// Operations per edge: 75 +, 91 ×, 7 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 550 +, 1122 ×, 147 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i7_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = in.p_lo[0] + ap_hi0;
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = bp_hi0 + in.p_lo[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = in.p_lo[1] + ap_hi1;
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = in.p_lo[2] + ap_hi2;
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = bp_hi2 + in.p_lo[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ap2 * ab1 - ab2 * ap1;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
  const T plain_cross2 = ap1 * ab0 - ap0 * ab1;
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    const T t1 = in.p_lo[2] * ab1 + exact_cross[0] - in.p_lo[1] * ab2;
    cross0 = t1;
    const T t2 = ab2 * in.p_lo[0] + exact_cross[1] - ab0 * in.p_lo[2];
    cross1 = t2;
    const T t3 = exact_cross[2] + in.p_lo[1] * ab0 - in.p_lo[0] * ab1;
    cross2 = t3;
    cross_cross = t1 * t1 + t2 * t2 + t3 * t3;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = bp1 * ab1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap0 * bp0 + bp1 * ap1 + ap2 * bp2;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = cross_cross + ab_ab * zeta2;
  const T h = in.normal[1] * cross1 + cross0 * in.normal[0] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-T(2) * ab_ab - ab_ap))))), T(c - (T(15) / T(4)) * ab_ab - ab_ap - zeta2));
  const T t5 = -a_minus_b * ab_ap;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * ab_ab * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 2> M_flat;
    segment_moments_far_field<T>(3, 5, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(3, 5, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / D;
    const T t9 = T(1) / r1;
    const T t10 = T(1) / r0;
    const T t11 = a_minus_b * t9 + ab_ap * t10;
    J_3 = t8 * t11;
    J_5 = (T(1) / T(3)) * (a_minus_b * t9 / q1 + ab_ap * t10 / c + T(2) * ab_ab * t8 * t11) * t8;
  }
  T H_f;
  const T t12 = t6 - T(2) * zeta2;
  const T t13 = max(T(D - T(2) * ab_ab * zeta2), T(t5));
  if (t12 >= T(0) && t13 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t14 = -ab_ap;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(5, 5, h, ab_ab, zeta2, t14, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((a_minus_b * r0 + ab_ap * r1) * h * zeta, r0 * h * h * r1 - a_minus_b * ab_ap * zeta2) / zeta;
    const T t15 = T(1) / zeta2;
    const T H3 = t15 * (H1 - J_3 * h);
    const T H5 = (H3 - J_5 * h) * t15;
    H_f = H5;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−7) dQ
/// Operations per edge: 78 +, 110 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 558 +, 1179 ×, 149 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i7_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = in.p_lo[0] + ap_hi0;
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = ap_hi1 + in.p_lo[1];
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = in.p_lo[2] + ap_hi2;
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ap1 * ab1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T plain_cross0 = ap2 * ab1 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ap2 * ab0;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0] + in.p_lo[2] * ab1 - ab2 * in.p_lo[1];
    cross1 = exact_cross[1] + in.p_lo[0] * ab2 - ab0 * in.p_lo[2];
    const T t1 = exact_cross[2] + ab0 * in.p_lo[1] - in.p_lo[0] * ab1;
    cross2 = t1;
    const T t2 = ab2 * in.p_lo[1] - exact_cross[0] - in.p_lo[2] * ab1;
    const T t3 = ab0 * in.p_lo[2] - exact_cross[1] - in.p_lo[0] * ab2;
    cross_cross = t2 * t2 + t1 * t1 + t3 * t3;
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + bp0 * ap0 + bp1 * ap1;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = cross_cross + zeta2 * ab_ab;
  const T h = cross2 * in.normal[2] + in.normal[0] * cross0 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-ab_ap - T(2) * ab_ab))))), T(c - ab_ap - zeta2 - (T(73) / T(16)) * ab_ab));
  const T t5 = -a_minus_b * ab_ap;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * ab_ab - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 77/16 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 3> M_flat;
    segment_moments_far_field<T>(3, 7, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(3, 7, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / r0;
    const T t9 = T(1) / r1;
    const T t10 = ab_ap * t8 + a_minus_b * t9;
    const T t11 = T(1) / D;
    J_3 = t10 * t11;
    const T t12 = t8 * t8;
    const T t13 = t9 * t9;
    const T t14 = ab_ap * t8 * t12 + T(2) * t10 * t11 * ab_ab + a_minus_b * t9 * t13;
    J_5 = (T(1) / T(3)) * t11 * t14;
    const T t15 = t13 * t13;
    const T t16 = t12 * t12;
    J_7 = (T(1) / T(15)) * t11 * (T(4) * t11 * t14 * ab_ab + T(3) * a_minus_b * t9 * t15 + T(3) * ab_ap * t8 * t16);
  }
  T H_g;
  const T t17 = t6 - T(2) * zeta2;
  const T t18 = max(T(D - T(2) * zeta2 * ab_ab), T(t5));
  if (t17 >= T(0) && t18 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t19 = -ab_ap;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(7, 7, h, ab_ab, zeta2, t19, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((a_minus_b * r0 + r1 * ab_ap) * h * zeta, r1 * h * h * r0 - a_minus_b * ab_ap * zeta2) / zeta;
    const T t20 = T(1) / zeta2;
    const T H3 = -(J_3 * h - H1) * t20;
    const T H5 = -t20 * (J_5 * h - H3);
    const T H7 = (H5 - h * J_7) * t20;
    H_g = H7;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_7;
}

/// The terms of one edge for f and ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−7) dQ
/// Operations per edge: 78 +, 110 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 576 +, 1178 ×, 149 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i7_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = in.p_lo[0] + ap_hi0;
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = ap_hi1 + in.p_lo[1];
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = in.p_lo[2] + ap_hi2;
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
  const T plain_cross2 = ab0 * ap1 - ap0 * ab1;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    const T t1 = ab1 * in.p_lo[2] + exact_cross[0] - ab2 * in.p_lo[1];
    cross0 = t1;
    cross1 = in.p_lo[0] * ab2 + exact_cross[1] - ab0 * in.p_lo[2];
    const T t2 = exact_cross[2] + ab0 * in.p_lo[1] - ab1 * in.p_lo[0];
    cross2 = t2;
    const T t3 = ab0 * in.p_lo[2] - in.p_lo[0] * ab2 - exact_cross[1];
    cross_cross = t3 * t3 + t1 * t1 + t2 * t2;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = bp1 * ap1 + ap2 * bp2 + ap0 * bp0;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = ab_ab * zeta2 + cross_cross;
  const T h = cross1 * in.normal[1] + in.normal[0] * cross0 + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-T(2) * ab_ab - ab_ap))))), T(c - (T(73) / T(16)) * ab_ab - ab_ap - zeta2));
  const T t5 = -a_minus_b * ab_ap;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * ab_ab * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 77/16 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 3> M_flat;
    segment_moments_far_field<T>(3, 7, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(3, 7, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / r1;
    const T t9 = T(1) / r0;
    const T t10 = t8 * a_minus_b + t9 * ab_ap;
    const T t11 = T(1) / D;
    J_3 = t10 * t11;
    const T t12 = t8 * t8;
    const T t13 = t9 * t9;
    const T t14 = T(2) * ab_ab * t10 * t11 + t8 * a_minus_b * t12 + t9 * t13 * ab_ap;
    J_5 = (T(1) / T(3)) * t14 * t11;
    const T t15 = t13 * t13;
    const T t16 = t12 * t12;
    J_7 = (T(1) / T(15)) * (T(3) * t9 * t15 * ab_ap + T(3) * t8 * a_minus_b * t16 + T(4) * t14 * ab_ab * t11) * t11;
  }
  T H_f;
  T H_g;
  const T t17 = t6 - T(2) * zeta2;
  const T t18 = max(T(D - T(2) * ab_ab * zeta2), T(t5));
  if (t17 >= T(0) && t18 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t19 = -ab_ap;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(5, 7, h, ab_ab, zeta2, t19, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * h * (r1 * ab_ap + r0 * a_minus_b), r0 * r1 * h * h - a_minus_b * ab_ap * zeta2) / zeta;
    const T t20 = T(1) / zeta2;
    const T H3 = -(J_3 * h - H1) * t20;
    const T H5 = (H3 - J_5 * h) * t20;
    const T H7 = (H5 - J_7 * h) * t20;
    H_f = H5;
    H_g = H7;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
  out.S_g = H_g;
  out.J_g = J_7;
}

/// The terms of one edge for f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−8) dQ
/// Operations per edge: 76 +, 91 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 555 +, 1093 ×, 149 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i8_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = in.p_lo[0] + ap_hi0;
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = ap_hi1 + in.p_lo[1];
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = in.p_lo[2] + ap_hi2;
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ab0 * ap0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T plain_cross0 = ap2 * ab1 - ap1 * ab2;
  const T plain_cross1 = ab2 * ap0 - ap2 * ab0;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    const T t1 = in.p_lo[2] * ab1 + exact_cross[0] - ab2 * in.p_lo[1];
    cross0 = t1;
    const T t2 = in.p_lo[0] * ab2 + exact_cross[1] - ab0 * in.p_lo[2];
    cross1 = t2;
    const T t3 = exact_cross[2] + ab0 * in.p_lo[1] - in.p_lo[0] * ab1;
    cross2 = t3;
    cross_cross = t2 * t2 + t1 * t1 + t3 * t3;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = bp1 * ab1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = bp1 * ap1 + ap2 * bp2 + bp0 * ap0;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = cross_cross + ab_ab * zeta2;
  const T h = in.normal[1] * cross1 + cross2 * in.normal[2] + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T c_minus_b = ap_bp + zeta2;
  T J_2;
  T J_4;
  T J_6;
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-T(2) * ab_ab - ab_ap))))), T(c - (T(15) / T(4)) * ab_ab - ab_ap - zeta2));
  const T t5 = -a_minus_b * ab_ap;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * ab_ab * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 3> M_flat;
    segment_moments_far_field<T>(2, 6, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(2, 6, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = t9 * atan2(t8, c_minus_b);
    J_2 = J2;
    const T t10 = T(1) / D;
    const T t11 = T(1) / c;
    const T t12 = T(1) / q1;
    const T t13 = t11 * ab_ap + ab_ab * J2 + a_minus_b * t12;
    J_4 = (T(1) / T(2)) * t10 * t13;
    const T t14 = t12 * t12;
    const T t15 = t11 * t11;
    J_6 = (T(1) / T(8)) * t10 * (T(2) * a_minus_b * t14 + T(3) * ab_ab * t10 * t13 + T(2) * t15 * ab_ap);
  }
  T H_f;
  const T t16 = t6 - T(2) * zeta2;
  const T t17 = max(T(D - T(2) * ab_ab * zeta2), T(t5));
  if (t16 >= T(0) && t17 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t18 = -ab_ap;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(6, 6, h, ab_ab, zeta2, t18, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t19 = T(1) / zeta2;
    const T H2 = -(J_2 * h - theta) * t19;
    const T H4 = (H2 - J_4 * h) * t19;
    const T H6 = (H4 - J_6 * h) * t19;
    H_f = H6;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−8) dQ
/// Operations per edge: 79 +, 104 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 563 +, 1131 ×, 151 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i8_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = in.p_lo[0] + ap_hi0;
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = ap_hi1 + in.p_lo[1];
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = in.p_lo[2] + ap_hi2;
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ap1 * ab1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0] + in.p_lo[2] * ab1 - ab2 * in.p_lo[1];
    const T t1 = in.p_lo[0] * ab2 + exact_cross[1] - in.p_lo[2] * ab0;
    cross1 = t1;
    cross2 = ab0 * in.p_lo[1] + exact_cross[2] - in.p_lo[0] * ab1;
    const T t2 = ab2 * in.p_lo[1] - exact_cross[0] - in.p_lo[2] * ab1;
    const T t3 = in.p_lo[0] * ab1 - ab0 * in.p_lo[1] - exact_cross[2];
    cross_cross = t2 * t2 + t3 * t3 + t1 * t1;
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = bp0 * ap0 + ap1 * bp1 + bp2 * ap2;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = cross_cross + zeta2 * ab_ab;
  const T h = cross1 * in.normal[1] + in.normal[0] * cross0 + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T c_minus_b = zeta2 + ap_bp;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-ab_ap - T(2) * ab_ab))))), T(c - ab_ap - zeta2 - T(6) * ab_ab));
  const T t5 = -ab_ap * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * ab_ab * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 25/4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 4> M_flat;
    segment_moments_far_field<T>(2, 8, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(2, 8, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
    J_8 = M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = t9 * atan2(t8, c_minus_b);
    J_2 = J2;
    const T t10 = T(1) / q1;
    const T t11 = T(1) / c;
    const T t12 = a_minus_b * t10 + J2 * ab_ab + t11 * ab_ap;
    const T t13 = T(1) / D;
    J_4 = (T(1) / T(2)) * t12 * t13;
    const T t14 = t11 * t11;
    const T t15 = t10 * t10;
    const T t16 = T(2) * t14 * ab_ap + T(2) * a_minus_b * t15 + T(3) * t12 * t13 * ab_ab;
    J_6 = (T(1) / T(8)) * t16 * t13;
    const T t17 = t15 * t10;
    const T t18 = t14 * t11;
    J_8 = (T(1) / T(48)) * t13 * (T(8) * a_minus_b * t17 + T(8) * t18 * ab_ap + T(5) * t16 * t13 * ab_ab);
  }
  T H_g;
  const T t19 = t6 - T(2) * zeta2;
  const T t20 = max(T(D - T(2) * zeta2 * ab_ab), T(t5));
  if (t19 >= T(0) && t20 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t21 = -ab_ap;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(8, 8, h, ab_ab, zeta2, t21, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t22 = T(1) / zeta2;
    const T H2 = -t22 * (J_2 * h - theta);
    const T H4 = -(J_4 * h - H2) * t22;
    const T H6 = -(h * J_6 - H4) * t22;
    const T H8 = (H6 - J_8 * h) * t22;
    H_g = H8;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_8;
}

/// The terms of one edge for f and ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−8) dQ
/// Operations per edge: 79 +, 104 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 581 +, 1150 ×, 151 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i8_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = in.p_lo[0] + ap_hi0;
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = ap_hi1 + in.p_lo[1];
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = in.p_lo[2] + ap_hi2;
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T plain_cross0 = ap2 * ab1 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ap2 * ab0;
  const T plain_cross2 = ab0 * ap1 - ap0 * ab1;
  const T plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0] + in.p_lo[2] * ab1 - ab2 * in.p_lo[1];
    const T t1 = in.p_lo[0] * ab2 + exact_cross[1] - ab0 * in.p_lo[2];
    cross1 = t1;
    const T t2 = exact_cross[2] + ab0 * in.p_lo[1] - in.p_lo[0] * ab1;
    cross2 = t2;
    const T t3 = ab2 * in.p_lo[1] - exact_cross[0] - in.p_lo[2] * ab1;
    cross_cross = t3 * t3 + t2 * t2 + t1 * t1;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + bp0 * ap0 + bp1 * ap1;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = cross_cross + ab_ab * zeta2;
  const T h = in.normal[0] * cross0 + in.normal[1] * cross1 + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T c_minus_b = ap_bp + zeta2;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-T(2) * ab_ab - ab_ap))))), T(c - T(6) * ab_ab - ab_ap - zeta2));
  const T t5 = -ab_ap * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * ab_ab * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 25/4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 4> M_flat;
    segment_moments_far_field<T>(2, 8, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(2, 8, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
    J_8 = M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = t9 * atan2(t8, c_minus_b);
    J_2 = J2;
    const T t10 = T(1) / c;
    const T t11 = T(1) / q1;
    const T t12 = t10 * ab_ap + a_minus_b * t11 + ab_ab * J2;
    const T t13 = T(1) / D;
    J_4 = (T(1) / T(2)) * t12 * t13;
    const T t14 = t11 * t11;
    const T t15 = t10 * t10;
    const T t16 = T(3) * ab_ab * t12 * t13 + T(2) * a_minus_b * t14 + T(2) * t15 * ab_ap;
    J_6 = (T(1) / T(8)) * t16 * t13;
    const T t17 = t15 * t10;
    const T t18 = t14 * t11;
    J_8 = (T(1) / T(48)) * (T(5) * ab_ab * t16 * t13 + T(8) * t17 * ab_ap + T(8) * a_minus_b * t18) * t13;
  }
  T H_f;
  T H_g;
  const T t19 = t6 - T(2) * zeta2;
  const T t20 = max(T(D - T(2) * ab_ab * zeta2), T(t5));
  if (t19 >= T(0) && t20 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t21 = -ab_ap;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(6, 8, h, ab_ab, zeta2, t21, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t22 = T(1) / zeta2;
    const T H2 = (theta - J_2 * h) * t22;
    const T H4 = (H2 - J_4 * h) * t22;
    const T H6 = -(h * J_6 - H4) * t22;
    const T H8 = (H6 - J_8 * h) * t22;
    H_f = H6;
    H_g = H8;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
  out.S_g = H_g;
  out.J_g = J_8;
}

/// The terms of one edge for f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−9) dQ
/// Operations per edge: 78 +, 110 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 558 +, 1179 ×, 149 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i9_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = ap_hi0 + in.p_lo[0];
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = ap_hi1 + in.p_lo[1];
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = in.p_lo[2] + ap_hi2;
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ap1 * ab1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0] + in.p_lo[2] * ab1 - ab2 * in.p_lo[1];
    cross1 = exact_cross[1] + ab2 * in.p_lo[0] - ab0 * in.p_lo[2];
    const T t1 = ab0 * in.p_lo[1] + exact_cross[2] - ab1 * in.p_lo[0];
    cross2 = t1;
    const T t2 = ab0 * in.p_lo[2] - exact_cross[1] - ab2 * in.p_lo[0];
    const T t3 = ab2 * in.p_lo[1] - exact_cross[0] - in.p_lo[2] * ab1;
    cross_cross = t1 * t1 + t2 * t2 + t3 * t3;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = bp2 * ap2 + bp0 * ap0 + ap1 * bp1;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = cross_cross + zeta2 * ab_ab;
  const T h = in.normal[0] * cross0 + cross1 * in.normal[1] + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-ab_ap - T(2) * ab_ab))))), T(c - ab_ap - zeta2 - (T(73) / T(16)) * ab_ab));
  const T t5 = -a_minus_b * ab_ap;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * ab_ab * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 77/16 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 3> M_flat;
    segment_moments_far_field<T>(3, 7, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(3, 7, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / D;
    const T t9 = T(1) / r1;
    const T t10 = T(1) / r0;
    const T t11 = a_minus_b * t9 + ab_ap * t10;
    J_3 = t8 * t11;
    const T t12 = t9 * t9;
    const T t13 = t10 * t10;
    const T t14 = a_minus_b * t12 * t9 + ab_ap * t10 * t13 + T(2) * t8 * t11 * ab_ab;
    J_5 = (T(1) / T(3)) * t8 * t14;
    const T t15 = t13 * t13;
    const T t16 = t12 * t12;
    J_7 = (T(1) / T(15)) * t8 * (T(3) * ab_ap * t10 * t15 + T(4) * t8 * t14 * ab_ab + T(3) * a_minus_b * t16 * t9);
  }
  T H_f;
  const T t17 = t6 - T(2) * zeta2;
  const T t18 = max(T(D - T(2) * zeta2 * ab_ab), T(t5));
  if (t17 >= T(0) && t18 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t19 = -ab_ap;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(7, 7, h, ab_ab, zeta2, t19, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((a_minus_b * r0 + ab_ap * r1) * h * zeta, h * h * r0 * r1 - a_minus_b * ab_ap * zeta2) / zeta;
    const T t20 = T(1) / zeta2;
    const T H3 = -(J_3 * h - H1) * t20;
    const T H5 = t20 * (H3 - h * J_5);
    const T H7 = -t20 * (h * J_7 - H5);
    H_f = H7;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−9) dQ
/// Operations per edge: 81 +, 125 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 562 +, 1232 ×, 151 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i9_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = in.p_lo[0] + ap_hi0;
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = ap_hi1 + in.p_lo[1];
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = in.p_lo[2] + ap_hi2;
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ap1 * ab1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0] + in.p_lo[2] * ab1 - ab2 * in.p_lo[1];
    cross1 = exact_cross[1] + in.p_lo[0] * ab2 - ab0 * in.p_lo[2];
    const T t1 = exact_cross[2] + ab0 * in.p_lo[1] - in.p_lo[0] * ab1;
    cross2 = t1;
    const T t2 = ab0 * in.p_lo[2] - exact_cross[1] - in.p_lo[0] * ab2;
    const T t3 = ab2 * in.p_lo[1] - exact_cross[0] - in.p_lo[2] * ab1;
    cross_cross = t1 * t1 + t2 * t2 + t3 * t3;
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + ab2 * bp2;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = cross_cross + ab_ab * zeta2;
  const T h = in.normal[0] * cross0 + cross1 * in.normal[1] + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  T J_9;
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-T(2) * ab_ab - ab_ap))))), T(c - (T(123) / T(16)) * ab_ab - ab_ap - zeta2));
  const T t5 = -ab_ap * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * ab_ab * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 127/16 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 4> M_flat;
    segment_moments_far_field<T>(3, 9, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
    J_9 = M_flat[3];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(3, 9, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
    J_9 = M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / D;
    const T t9 = T(1) / r0;
    const T t10 = T(1) / r1;
    const T t11 = t9 * ab_ap + a_minus_b * t10;
    J_3 = t8 * t11;
    const T t12 = t9 * t9;
    const T t13 = t10 * t10;
    const T t14 = T(2) * ab_ab * t8 * t11 + t12 * t9 * ab_ap + a_minus_b * t10 * t13;
    J_5 = (T(1) / T(3)) * t8 * t14;
    const T t15 = t13 * t13;
    const T t16 = t12 * t12;
    const T t17 = T(3) * a_minus_b * t10 * t15 + T(4) * ab_ab * t8 * t14 + T(3) * t16 * t9 * ab_ap;
    J_7 = (T(1) / T(15)) * t8 * t17;
    const T t18 = t16 * t12;
    const T t19 = t15 * t13;
    J_9 = (T(1) / T(35)) * t8 * (T(5) * t18 * t9 * ab_ap + T(5) * a_minus_b * t10 * t19 + T(2) * ab_ab * t8 * t17);
  }
  T H_g;
  const T t20 = t6 - T(2) * zeta2;
  const T t21 = max(T(D - T(2) * ab_ab * zeta2), T(t5));
  if (t20 >= T(0) && t21 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t22 = -ab_ap;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(9, 9, h, ab_ab, zeta2, t22, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * h * (ab_ap * r1 + r0 * a_minus_b), r0 * r1 * h * h - ab_ap * a_minus_b * zeta2) / zeta;
    const T t23 = T(1) / zeta2;
    const T H3 = -(J_3 * h - H1) * t23;
    const T H5 = -t23 * (J_5 * h - H3);
    const T H7 = -t23 * (h * J_7 - H5);
    const T H9 = -(J_9 * h - H7) * t23;
    H_g = H9;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_9;
}

/// The terms of one edge for f and ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−9) dQ
/// Operations per edge: 81 +, 125 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 582 +, 1233 ×, 151 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i9_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = ap_hi0 + in.p_lo[0];
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = in.p_lo[1] + ap_hi1;
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = ap_hi2 + in.p_lo[2];
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = ab1 * in.p_lo[2] + exact_cross[0] - in.p_lo[1] * ab2;
    const T t1 = exact_cross[1] + in.p_lo[0] * ab2 - in.p_lo[2] * ab0;
    cross1 = t1;
    cross2 = exact_cross[2] + in.p_lo[1] * ab0 - ab1 * in.p_lo[0];
    const T t2 = in.p_lo[1] * ab2 - ab1 * in.p_lo[2] - exact_cross[0];
    const T t3 = ab1 * in.p_lo[0] - exact_cross[2] - in.p_lo[1] * ab0;
    cross_cross = t1 * t1 + t2 * t2 + t3 * t3;
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = zeta2 * ab_ab + cross_cross;
  const T h = in.normal[2] * cross2 + in.normal[0] * cross0 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = zeta2 + bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  T J_9;
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-T(2) * ab_ab - ab_ap))))), T(c - zeta2 - (T(123) / T(16)) * ab_ab - ab_ap));
  const T t5 = -ab_ap * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * ab_ab * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 127/16 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 4> M_flat;
    segment_moments_far_field<T>(3, 9, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
    J_9 = M_flat[3];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(3, 9, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
    J_9 = M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / D;
    const T t9 = T(1) / r0;
    const T t10 = T(1) / r1;
    const T t11 = t9 * ab_ap + t10 * a_minus_b;
    J_3 = t8 * t11;
    const T t12 = t10 * t10;
    const T t13 = t9 * t9;
    const T t14 = T(2) * ab_ab * t8 * t11 + t12 * t10 * a_minus_b + t13 * t9 * ab_ap;
    J_5 = (T(1) / T(3)) * t8 * t14;
    const T t15 = t13 * t13;
    const T t16 = t12 * t12;
    const T t17 = T(4) * ab_ab * t8 * t14 + T(3) * t15 * t9 * ab_ap + T(3) * t16 * t10 * a_minus_b;
    J_7 = (T(1) / T(15)) * t17 * t8;
    const T t18 = t15 * t13;
    const T t19 = t16 * t12;
    J_9 = (T(1) / T(35)) * t8 * (T(5) * t18 * t9 * ab_ap + T(5) * t19 * t10 * a_minus_b + T(2) * t17 * ab_ab * t8);
  }
  T H_f;
  T H_g;
  const T t20 = t6 - T(2) * zeta2;
  const T t21 = max(T(D - T(2) * zeta2 * ab_ab), T(t5));
  if (t20 >= T(0) && t21 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t22 = -ab_ap;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(7, 9, h, ab_ab, zeta2, t22, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(h * (r0 * a_minus_b + ab_ap * r1) * zeta, h * h * r0 * r1 - zeta2 * ab_ap * a_minus_b) / zeta;
    const T t23 = T(1) / zeta2;
    const T H3 = t23 * (H1 - h * J_3);
    const T H5 = -t23 * (J_5 * h - H3);
    const T H7 = t23 * (H5 - h * J_7);
    const T H9 = t23 * (H7 - h * J_9);
    H_f = H7;
    H_g = H9;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
  out.S_g = H_g;
  out.J_g = J_9;
}

/// The terms of one edge for f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−10) dQ
/// Operations per edge: 79 +, 104 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 561 +, 1129 ×, 151 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i10_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = ap_hi0 + in.p_lo[0];
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = in.p_lo[1] + ap_hi1;
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = ap_hi2 + in.p_lo[2];
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
  const T plain_cross2 = ap1 * ab0 - ab1 * ap0;
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    const T t1 = exact_cross[0] + ab1 * in.p_lo[2] - in.p_lo[1] * ab2;
    cross0 = t1;
    const T t2 = exact_cross[1] + in.p_lo[0] * ab2 - ab0 * in.p_lo[2];
    cross1 = t2;
    cross2 = in.p_lo[1] * ab0 + exact_cross[2] - ab1 * in.p_lo[0];
    const T t3 = ab1 * in.p_lo[0] - in.p_lo[1] * ab0 - exact_cross[2];
    cross_cross = t1 * t1 + t2 * t2 + t3 * t3;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + ab1 * bp1;
  const T ap_bp = ap1 * bp1 + bp0 * ap0 + bp2 * ap2;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = zeta2 * ab_ab + cross_cross;
  const T h = in.normal[0] * cross0 + cross1 * in.normal[1] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = zeta2 + bp_bp;
  const T c_minus_b = zeta2 + ap_bp;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-T(2) * ab_ab - ab_ap))))), T(c - zeta2 - T(6) * ab_ab - ab_ap));
  const T t5 = -a_minus_b * ab_ap;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * ab_ab - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 25/4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 4> M_flat;
    segment_moments_far_field<T>(2, 8, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(2, 8, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
    J_8 = M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = atan2(t8, c_minus_b) * t9;
    J_2 = J2;
    const T t10 = T(1) / D;
    const T t11 = T(1) / q1;
    const T t12 = T(1) / c;
    const T t13 = a_minus_b * t11 + t12 * ab_ap + ab_ab * J2;
    J_4 = (T(1) / T(2)) * t10 * t13;
    const T t14 = t12 * t12;
    const T t15 = t11 * t11;
    const T t16 = T(3) * ab_ab * t10 * t13 + T(2) * t14 * ab_ap + T(2) * a_minus_b * t15;
    J_6 = (T(1) / T(8)) * t16 * t10;
    const T t17 = t15 * t11;
    const T t18 = t14 * t12;
    J_8 = (T(1) / T(48)) * (T(8) * a_minus_b * t17 + T(5) * t16 * ab_ab * t10 + T(8) * t18 * ab_ap) * t10;
  }
  T H_f;
  const T t19 = t6 - T(2) * zeta2;
  const T t20 = max(T(D - T(2) * zeta2 * ab_ab), T(t5));
  if (t19 >= T(0) && t20 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t21 = -ab_ap;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(8, 8, h, ab_ab, zeta2, t21, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t22 = T(1) / zeta2;
    const T H2 = -t22 * (h * J_2 - theta);
    const T H4 = (H2 - J_4 * h) * t22;
    const T H6 = -t22 * (h * J_6 - H4);
    const T H8 = t22 * (H6 - h * J_8);
    H_f = H8;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−10) dQ
/// Operations per edge: 82 +, 117 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 565 +, 1163 ×, 153 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i10_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = ap_hi0 + in.p_lo[0];
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = in.p_lo[1] + ap_hi1;
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = in.p_lo[2] + ap_hi2;
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ap2 * ab0;
  const T plain_cross2 = ap1 * ab0 - ap0 * ab1;
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    const T t1 = exact_cross[0] + in.p_lo[2] * ab1 - ab2 * in.p_lo[1];
    cross0 = t1;
    const T t2 = exact_cross[1] + ab2 * in.p_lo[0] - in.p_lo[2] * ab0;
    cross1 = t2;
    cross2 = in.p_lo[1] * ab0 + exact_cross[2] - ab1 * in.p_lo[0];
    const T t3 = ab1 * in.p_lo[0] - in.p_lo[1] * ab0 - exact_cross[2];
    cross_cross = t1 * t1 + t3 * t3 + t2 * t2;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T ap_bp = bp2 * ap2 + ap1 * bp1 + bp0 * ap0;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = zeta2 * ab_ab + cross_cross;
  const T h = in.normal[2] * cross2 + in.normal[0] * cross0 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T c_minus_b = zeta2 + ap_bp;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  T J_10;
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-ab_ap - T(2) * ab_ab))))), T(c - ab_ap - zeta2 - (T(153) / T(16)) * ab_ab));
  const T t5 = -ab_ap * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * ab_ab - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 157/16 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 5> M_flat;
    segment_moments_far_field<T>(2, 10, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
    J_10 = M_flat[4];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(2, 10, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
    J_8 = M_beyond[3];
    J_10 = M_beyond[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = t9 * atan2(t8, c_minus_b);
    J_2 = J2;
    const T t10 = T(1) / D;
    const T t11 = T(1) / q1;
    const T t12 = T(1) / c;
    const T t13 = a_minus_b * t11 + ab_ap * t12 + J2 * ab_ab;
    J_4 = (T(1) / T(2)) * t10 * t13;
    const T t14 = t12 * t12;
    const T t15 = t11 * t11;
    const T t16 = T(2) * ab_ap * t14 + T(2) * a_minus_b * t15 + T(3) * t10 * t13 * ab_ab;
    J_6 = (T(1) / T(8)) * t10 * t16;
    const T t17 = t14 * t12;
    const T t18 = t15 * t11;
    const T t19 = T(8) * ab_ap * t17 + T(5) * t10 * ab_ab * t16 + T(8) * a_minus_b * t18;
    J_8 = (T(1) / T(48)) * t10 * t19;
    const T t20 = t14 * t14;
    const T t21 = t15 * t15;
    J_10 = (T(1) / T(384)) * t10 * (T(48) * ab_ap * t20 + T(7) * t10 * t19 * ab_ab + T(48) * a_minus_b * t21);
  }
  T H_g;
  const T t22 = t6 - T(2) * zeta2;
  const T t23 = max(T(D - T(2) * zeta2 * ab_ab), T(t5));
  if (t22 >= T(0) && t23 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t24 = -ab_ap;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(10, 10, h, ab_ab, zeta2, t24, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t25 = T(1) / zeta2;
    const T H2 = -t25 * (J_2 * h - theta);
    const T H4 = t25 * (H2 - h * J_4);
    const T H6 = -t25 * (h * J_6 - H4);
    const T H8 = t25 * (H6 - h * J_8);
    const T H10 = t25 * (H8 - J_10 * h);
    H_g = H10;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_10;
}

/// The terms of one edge for f and ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−10) dQ
/// Operations per edge: 82 +, 117 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 585 +, 1184 ×, 153 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i10_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = in.p_lo[0] + ap_hi0;
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = ap_hi1 + in.p_lo[1];
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = in.p_lo[2] + ap_hi2;
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T plain_cross0 = ap2 * ab1 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ap2 * ab0;
  const T plain_cross2 = ab0 * ap1 - ap0 * ab1;
  const T plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    const T t1 = exact_cross[0] + in.p_lo[2] * ab1 - ab2 * in.p_lo[1];
    cross0 = t1;
    const T t2 = in.p_lo[0] * ab2 + exact_cross[1] - ab0 * in.p_lo[2];
    cross1 = t2;
    cross2 = ab0 * in.p_lo[1] + exact_cross[2] - in.p_lo[0] * ab1;
    const T t3 = in.p_lo[0] * ab1 - ab0 * in.p_lo[1] - exact_cross[2];
    cross_cross = t3 * t3 + t1 * t1 + t2 * t2;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = bp1 * ab1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = bp1 * ap1 + ap2 * bp2 + bp0 * ap0;
  const T zeta2 = in.z * in.z;
  const T c = zeta2 + ap_ap;
  const T D = cross_cross + ab_ab * zeta2;
  const T h = in.normal[2] * cross2 + cross0 * in.normal[0] + in.normal[1] * cross1;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T c_minus_b = zeta2 + ap_bp;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  T J_10;
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-T(2) * ab_ab - ab_ap))))), T(c - (T(153) / T(16)) * ab_ab - ab_ap - zeta2));
  const T t5 = -ab_ap * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * ab_ab * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 157/16 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 5> M_flat;
    segment_moments_far_field<T>(2, 10, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
    J_10 = M_flat[4];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(2, 10, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
    J_8 = M_beyond[3];
    J_10 = M_beyond[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = t9 * atan2(t8, c_minus_b);
    J_2 = J2;
    const T t10 = T(1) / D;
    const T t11 = T(1) / q1;
    const T t12 = T(1) / c;
    const T t13 = a_minus_b * t11 + ab_ab * J2 + ab_ap * t12;
    J_4 = (T(1) / T(2)) * t10 * t13;
    const T t14 = t12 * t12;
    const T t15 = t11 * t11;
    const T t16 = T(2) * ab_ap * t14 + T(2) * a_minus_b * t15 + T(3) * t10 * ab_ab * t13;
    J_6 = (T(1) / T(8)) * t10 * t16;
    const T t17 = t14 * t12;
    const T t18 = t15 * t11;
    const T t19 = T(8) * ab_ap * t17 + T(5) * t10 * t16 * ab_ab + T(8) * a_minus_b * t18;
    J_8 = (T(1) / T(48)) * t10 * t19;
    const T t20 = t14 * t14;
    const T t21 = t15 * t15;
    J_10 = (T(1) / T(384)) * t10 * (T(48) * ab_ap * t20 + T(7) * t10 * ab_ab * t19 + T(48) * a_minus_b * t21);
  }
  T H_f;
  T H_g;
  const T t22 = t6 - T(2) * zeta2;
  const T t23 = max(T(D - T(2) * ab_ab * zeta2), T(t5));
  if (t22 >= T(0) && t23 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t24 = -ab_ap;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(8, 10, h, ab_ab, zeta2, t24, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t25 = T(1) / zeta2;
    const T H2 = t25 * (theta - J_2 * h);
    const T H4 = t25 * (H2 - h * J_4);
    const T H6 = -t25 * (h * J_6 - H4);
    const T H8 = -t25 * (h * J_8 - H6);
    const T H10 = t25 * (H8 - J_10 * h);
    H_f = H8;
    H_g = H10;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
  out.S_g = H_g;
  out.J_g = J_10;
}

/// The terms of one edge for f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−11) dQ
/// Operations per edge: 81 +, 125 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 558 +, 1228 ×, 151 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i11_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = ap_hi0 + in.p_lo[0];
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = in.p_lo[1] + ap_hi1;
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = in.p_lo[2] + ap_hi2;
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ap2 * ab0;
  const T plain_cross2 = ap1 * ab0 - ap0 * ab1;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    const T t1 = in.p_lo[2] * ab1 + exact_cross[0] - ab2 * in.p_lo[1];
    cross0 = t1;
    const T t2 = ab2 * in.p_lo[0] + exact_cross[1] - in.p_lo[2] * ab0;
    cross1 = t2;
    const T t3 = in.p_lo[1] * ab0 + exact_cross[2] - ab1 * in.p_lo[0];
    cross2 = t3;
    cross_cross = t3 * t3 + t1 * t1 + t2 * t2;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + ap1 * bp1;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = zeta2 * ab_ab + cross_cross;
  const T h = in.normal[0] * cross0 + in.normal[2] * cross2 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  T J_9;
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-T(2) * ab_ab - ab_ap))))), T(c - zeta2 - (T(123) / T(16)) * ab_ab - ab_ap));
  const T t5 = -a_minus_b * ab_ap;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * ab_ab * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 127/16 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 4> M_flat;
    segment_moments_far_field<T>(3, 9, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
    J_9 = M_flat[3];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(3, 9, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
    J_9 = M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / D;
    const T t9 = T(1) / r0;
    const T t10 = T(1) / r1;
    const T t11 = t9 * ab_ap + t10 * a_minus_b;
    J_3 = t8 * t11;
    const T t12 = t9 * t9;
    const T t13 = t10 * t10;
    const T t14 = t12 * t9 * ab_ap + T(2) * t8 * t11 * ab_ab + t10 * a_minus_b * t13;
    J_5 = (T(1) / T(3)) * t8 * t14;
    const T t15 = t13 * t13;
    const T t16 = t12 * t12;
    const T t17 = T(3) * t10 * a_minus_b * t15 + T(3) * t16 * t9 * ab_ap + T(4) * t8 * ab_ab * t14;
    J_7 = (T(1) / T(15)) * t8 * t17;
    const T t18 = t15 * t13;
    const T t19 = t16 * t12;
    J_9 = (T(1) / T(35)) * t8 * (T(5) * t10 * a_minus_b * t18 + T(5) * t19 * t9 * ab_ap + T(2) * t8 * t17 * ab_ab);
  }
  T H_f;
  const T t20 = t6 - T(2) * zeta2;
  const T t21 = max(T(D - T(2) * zeta2 * ab_ab), T(t5));
  if (t20 >= T(0) && t21 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t22 = -ab_ap;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(9, 9, h, ab_ab, zeta2, t22, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((r1 * ab_ap + a_minus_b * r0) * h * zeta, r1 * h * h * r0 - a_minus_b * zeta2 * ab_ap) / zeta;
    const T t23 = T(1) / zeta2;
    const T H3 = (H1 - J_3 * h) * t23;
    const T H5 = t23 * (H3 - J_5 * h);
    const T H7 = t23 * (H5 - h * J_7);
    const T H9 = -t23 * (h * J_9 - H7);
    H_f = H9;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−11) dQ
/// Operations per edge: 84 +, 140 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 564 +, 1284 ×, 153 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i11_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = in.p_lo[0] + ap_hi0;
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = ap_hi1 + in.p_lo[1];
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = bp_hi1 + in.p_lo[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = in.p_lo[2] + ap_hi2;
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ap2 * ab1 - ab2 * ap1;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
  const T plain_cross2 = ab0 * ap1 - ap0 * ab1;
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0] + in.p_lo[2] * ab1 - ab2 * in.p_lo[1];
    const T t1 = exact_cross[1] + in.p_lo[0] * ab2 - ab0 * in.p_lo[2];
    cross1 = t1;
    const T t2 = ab0 * in.p_lo[1] + exact_cross[2] - in.p_lo[0] * ab1;
    cross2 = t2;
    const T t3 = ab2 * in.p_lo[1] - exact_cross[0] - in.p_lo[2] * ab1;
    cross_cross = t1 * t1 + t2 * t2 + t3 * t3;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + bp1 * ap1 + ap2 * bp2;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = ab_ab * zeta2 + cross_cross;
  const T h = cross2 * in.normal[2] + in.normal[0] * cross0 + cross1 * in.normal[1];
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
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-T(2) * ab_ab - ab_ap))))), T(c - (T(93) / T(8)) * ab_ab - ab_ap - zeta2));
  const T t5 = -a_minus_b * ab_ap;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * ab_ab - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 95/8 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 5> M_flat;
    segment_moments_far_field<T>(3, 11, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
    J_9 = M_flat[3];
    J_11 = M_flat[4];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(3, 11, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
    J_9 = M_beyond[3];
    J_11 = M_beyond[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / D;
    const T t9 = T(1) / r0;
    const T t10 = T(1) / r1;
    const T t11 = ab_ap * t9 + t10 * a_minus_b;
    J_3 = t8 * t11;
    const T t12 = t10 * t10;
    const T t13 = t9 * t9;
    const T t14 = t10 * a_minus_b * t12 + t13 * ab_ap * t9 + T(2) * ab_ab * t8 * t11;
    J_5 = (T(1) / T(3)) * t8 * t14;
    const T t15 = t13 * t13;
    const T t16 = t12 * t12;
    const T t17 = T(3) * t15 * ab_ap * t9 + T(4) * ab_ab * t8 * t14 + T(3) * t10 * a_minus_b * t16;
    J_7 = (T(1) / T(15)) * t8 * t17;
    const T t18 = t16 * t12;
    const T t19 = t15 * t13;
    const T t20 = T(5) * t10 * a_minus_b * t18 + T(2) * ab_ab * t8 * t17 + T(5) * t19 * ab_ap * t9;
    J_9 = (T(1) / T(35)) * t8 * t20;
    const T t21 = t15 * t15;
    const T t22 = t16 * t16;
    J_11 = (T(1) / T(315)) * (T(35) * t21 * ab_ap * t9 + T(8) * ab_ab * t8 * t20 + T(35) * t10 * a_minus_b * t22) * t8;
  }
  T H_g;
  const T t23 = t6 - T(2) * zeta2;
  const T t24 = max(T(D - T(2) * ab_ab * zeta2), T(t5));
  if (t23 >= T(0) && t24 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t25 = -ab_ap;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(11, 11, h, ab_ab, zeta2, t25, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * h * (a_minus_b * r0 + r1 * ab_ap), r1 * r0 * h * h - a_minus_b * ab_ap * zeta2) / zeta;
    const T t26 = T(1) / zeta2;
    const T H3 = (H1 - J_3 * h) * t26;
    const T H5 = (H3 - h * J_5) * t26;
    const T H7 = -(J_7 * h - H5) * t26;
    const T H9 = -(J_9 * h - H7) * t26;
    const T H11 = (H9 - J_11 * h) * t26;
    H_g = H11;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_11;
}

/// The terms of one edge for f and ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−11) dQ
/// Operations per edge: 84 +, 140 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 584 +, 1285 ×, 153 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i11_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = ap_hi0 + in.p_lo[0];
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = bp_hi0 + in.p_lo[0];
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = ap_hi1 + in.p_lo[1];
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = in.p_lo[2] + ap_hi2;
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T plain_cross0 = ap2 * ab1 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ap2 * ab0;
  const T plain_cross2 = ab0 * ap1 - ap0 * ab1;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    const T t1 = exact_cross[0] + in.p_lo[2] * ab1 - ab2 * in.p_lo[1];
    cross0 = t1;
    cross1 = ab2 * in.p_lo[0] + exact_cross[1] - ab0 * in.p_lo[2];
    const T t2 = exact_cross[2] + ab0 * in.p_lo[1] - ab1 * in.p_lo[0];
    cross2 = t2;
    const T t3 = ab0 * in.p_lo[2] - ab2 * in.p_lo[0] - exact_cross[1];
    cross_cross = t1 * t1 + t3 * t3 + t2 * t2;
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = bp0 * ap0 + ap2 * bp2 + bp1 * ap1;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = cross_cross + zeta2 * ab_ab;
  const T h = in.normal[0] * cross0 + cross2 * in.normal[2] + in.normal[1] * cross1;
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
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-ab_ap - T(2) * ab_ab))))), T(c - ab_ap - zeta2 - (T(93) / T(8)) * ab_ab));
  const T t5 = -ab_ap * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * ab_ab - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 95/8 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 5> M_flat;
    segment_moments_far_field<T>(3, 11, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
    J_9 = M_flat[3];
    J_11 = M_flat[4];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(3, 11, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
    J_9 = M_beyond[3];
    J_11 = M_beyond[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / D;
    const T t9 = T(1) / r1;
    const T t10 = T(1) / r0;
    const T t11 = t9 * a_minus_b + ab_ap * t10;
    J_3 = t8 * t11;
    const T t12 = t10 * t10;
    const T t13 = t9 * t9;
    const T t14 = ab_ap * t10 * t12 + t13 * t9 * a_minus_b + T(2) * t8 * t11 * ab_ab;
    J_5 = (T(1) / T(3)) * t8 * t14;
    const T t15 = t13 * t13;
    const T t16 = t12 * t12;
    const T t17 = T(3) * t15 * t9 * a_minus_b + T(4) * t8 * t14 * ab_ab + T(3) * ab_ap * t10 * t16;
    J_7 = (T(1) / T(15)) * t8 * t17;
    const T t18 = t15 * t13;
    const T t19 = t16 * t12;
    const T t20 = T(5) * t18 * t9 * a_minus_b + T(2) * t8 * t17 * ab_ab + T(5) * ab_ap * t10 * t19;
    J_9 = (T(1) / T(35)) * t8 * t20;
    const T t21 = t16 * t16;
    const T t22 = t15 * t15;
    J_11 = (T(1) / T(315)) * t8 * (T(8) * t8 * t20 * ab_ab + T(35) * ab_ap * t10 * t21 + T(35) * t22 * t9 * a_minus_b);
  }
  T H_f;
  T H_g;
  const T t23 = t6 - T(2) * zeta2;
  const T t24 = max(T(D - T(2) * zeta2 * ab_ab), T(t5));
  if (t23 >= T(0) && t24 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t25 = -ab_ap;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(9, 11, h, ab_ab, zeta2, t25, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * h * (r0 * a_minus_b + ab_ap * r1), r0 * h * h * r1 - ab_ap * zeta2 * a_minus_b) / zeta;
    const T t26 = T(1) / zeta2;
    const T H3 = -t26 * (J_3 * h - H1);
    const T H5 = -t26 * (h * J_5 - H3);
    const T H7 = t26 * (H5 - h * J_7);
    const T H9 = (H7 - J_9 * h) * t26;
    const T H11 = -(J_11 * h - H9) * t26;
    H_f = H9;
    H_g = H11;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
  out.S_g = H_g;
  out.J_g = J_11;
}

/// The terms of one edge for f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−12) dQ
/// Operations per edge: 82 +, 117 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 563 +, 1161 ×, 153 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i12_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = in.p_lo[0] + ap_hi0;
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = ap_hi1 + in.p_lo[1];
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = bp_hi1 + in.p_lo[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = in.p_lo[2] + ap_hi2;
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ap2 * ab2;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    const T t1 = ab1 * in.p_lo[2] + exact_cross[0] - ab2 * in.p_lo[1];
    cross0 = t1;
    const T t2 = exact_cross[1] + in.p_lo[0] * ab2 - ab0 * in.p_lo[2];
    cross1 = t2;
    const T t3 = ab0 * in.p_lo[1] + exact_cross[2] - ab1 * in.p_lo[0];
    cross2 = t3;
    cross_cross = t2 * t2 + t3 * t3 + t1 * t1;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T ap_bp = bp1 * ap1 + ap0 * bp0 + ap2 * bp2;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = ab_ab * zeta2 + cross_cross;
  const T h = cross1 * in.normal[1] + cross2 * in.normal[2] + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp;
  const T q1 = bp_bp + zeta2;
  const T c_minus_b = ap_bp + zeta2;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  T J_10;
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-T(2) * ab_ab - ab_ap))))), T(c - (T(153) / T(16)) * ab_ab - ab_ap - zeta2));
  const T t5 = -a_minus_b * ab_ap;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * ab_ab * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 157/16 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 5> M_flat;
    segment_moments_far_field<T>(2, 10, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
    J_10 = M_flat[4];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(2, 10, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
    J_8 = M_beyond[3];
    J_10 = M_beyond[4];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = atan2(t8, c_minus_b) * t9;
    J_2 = J2;
    const T t10 = T(1) / c;
    const T t11 = T(1) / q1;
    const T t12 = t10 * ab_ap + a_minus_b * t11 + ab_ab * J2;
    const T t13 = T(1) / D;
    J_4 = (T(1) / T(2)) * t12 * t13;
    const T t14 = t11 * t11;
    const T t15 = t10 * t10;
    const T t16 = T(2) * a_minus_b * t14 + T(3) * ab_ab * t12 * t13 + T(2) * t15 * ab_ap;
    J_6 = (T(1) / T(8)) * t16 * t13;
    const T t17 = t15 * t10;
    const T t18 = t14 * t11;
    const T t19 = T(5) * ab_ab * t16 * t13 + T(8) * t17 * ab_ap + T(8) * a_minus_b * t18;
    J_8 = (T(1) / T(48)) * t13 * t19;
    const T t20 = t15 * t15;
    const T t21 = t14 * t14;
    J_10 = (T(1) / T(384)) * (T(48) * t20 * ab_ap + T(7) * ab_ab * t13 * t19 + T(48) * a_minus_b * t21) * t13;
  }
  T H_f;
  const T t22 = t6 - T(2) * zeta2;
  const T t23 = max(T(D - T(2) * ab_ab * zeta2), T(t5));
  if (t22 >= T(0) && t23 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t24 = -ab_ap;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(10, 10, h, ab_ab, zeta2, t24, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t25 = T(1) / zeta2;
    const T H2 = -(h * J_2 - theta) * t25;
    const T H4 = (H2 - h * J_4) * t25;
    const T H6 = (H4 - h * J_6) * t25;
    const T H8 = -(h * J_8 - H6) * t25;
    const T H10 = (H8 - h * J_10) * t25;
    H_f = H10;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−12) dQ
/// Operations per edge: 85 +, 130 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 569 +, 1198 ×, 155 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i12_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = ap_hi0 + in.p_lo[0];
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = in.p_lo[1] + ap_hi1;
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = ap_hi2 + in.p_lo[2];
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = bp_hi2 + in.p_lo[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ap2 * ab0;
  const T plain_cross2 = ap1 * ab0 - ab1 * ap0;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    const T t1 = exact_cross[0] + ab1 * in.p_lo[2] - ab2 * in.p_lo[1];
    cross0 = t1;
    cross1 = exact_cross[1] + ab2 * in.p_lo[0] - ab0 * in.p_lo[2];
    const T t2 = in.p_lo[1] * ab0 + exact_cross[2] - ab1 * in.p_lo[0];
    cross2 = t2;
    const T t3 = ab0 * in.p_lo[2] - exact_cross[1] - ab2 * in.p_lo[0];
    cross_cross = t2 * t2 + t3 * t3 + t1 * t1;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T ap_bp = ap1 * bp1 + bp2 * ap2 + bp0 * ap0;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = zeta2 * ab_ab + cross_cross;
  const T h = cross1 * in.normal[1] + in.normal[0] * cross0 + in.normal[2] * cross2;
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
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-T(2) * ab_ab - ab_ap))))), T(c - zeta2 - (T(221) / T(16)) * ab_ab - ab_ap));
  const T t5 = -a_minus_b * ab_ap;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * ab_ab - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 225/16 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 6> M_flat;
    segment_moments_far_field<T>(2, 12, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
    J_10 = M_flat[4];
    J_12 = M_flat[5];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(2, 12, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
    J_8 = M_beyond[3];
    J_10 = M_beyond[4];
    J_12 = M_beyond[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = t9 * atan2(t8, c_minus_b);
    J_2 = J2;
    const T t10 = T(1) / D;
    const T t11 = T(1) / c;
    const T t12 = T(1) / q1;
    const T t13 = t11 * ab_ap + t12 * a_minus_b + J2 * ab_ab;
    J_4 = (T(1) / T(2)) * t10 * t13;
    const T t14 = t12 * t12;
    const T t15 = t11 * t11;
    const T t16 = T(3) * t10 * ab_ab * t13 + T(2) * t14 * a_minus_b + T(2) * t15 * ab_ap;
    J_6 = (T(1) / T(8)) * t10 * t16;
    const T t17 = t14 * t12;
    const T t18 = t15 * t11;
    const T t19 = T(5) * t10 * t16 * ab_ab + T(8) * t17 * a_minus_b + T(8) * t18 * ab_ap;
    J_8 = (T(1) / T(48)) * t10 * t19;
    const T t20 = t15 * t15;
    const T t21 = t14 * t14;
    const T t22 = T(7) * t10 * t19 * ab_ab + T(48) * t20 * ab_ap + T(48) * t21 * a_minus_b;
    J_10 = (T(1) / T(384)) * t10 * t22;
    const T t23 = t20 * t11;
    const T t24 = t21 * t12;
    J_12 = (T(1) / T(1280)) * t10 * (T(128) * t23 * ab_ap + T(3) * t10 * t22 * ab_ab + T(128) * t24 * a_minus_b);
  }
  T H_g;
  const T t25 = t6 - T(2) * zeta2;
  const T t26 = max(T(D - T(2) * zeta2 * ab_ab), T(t5));
  if (t25 >= T(0) && t26 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t27 = -ab_ap;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(12, 12, h, ab_ab, zeta2, t27, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t28 = T(1) / zeta2;
    const T H2 = t28 * (theta - h * J_2);
    const T H4 = -(J_4 * h - H2) * t28;
    const T H6 = t28 * (H4 - h * J_6);
    const T H8 = -(h * J_8 - H6) * t28;
    const T H10 = t28 * (H8 - J_10 * h);
    const T H12 = -t28 * (h * J_12 - H10);
    H_g = H12;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_12;
}

/// The terms of one edge for f and ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω |P − Q|^(−12) dQ
/// Operations per edge: 85 +, 130 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 591 +, 1221 ×, 155 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_inverse_i12_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = in.p_lo[0] + ap_hi0;
  const T bp_hi0 = in.p[0] - in.b[0];
  const T bp0 = in.p_lo[0] + bp_hi0;
  const T ab1 = in.b[1] - in.a[1];
  const T ap_hi1 = in.p[1] - in.a[1];
  const T ap1 = in.p_lo[1] + ap_hi1;
  const T bp_hi1 = in.p[1] - in.b[1];
  const T bp1 = in.p_lo[1] + bp_hi1;
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = in.p_lo[2] + ap_hi2;
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ab0 * ap0 + ap1 * ab1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross0;
  T cross1;
  T cross2;
  T cross_cross;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
    cross_cross = plain_cross_cross;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    const T t1 = in.p_lo[2] * ab1 + exact_cross[0] - ab2 * in.p_lo[1];
    cross0 = t1;
    cross1 = in.p_lo[0] * ab2 + exact_cross[1] - in.p_lo[2] * ab0;
    cross2 = ab0 * in.p_lo[1] + exact_cross[2] - in.p_lo[0] * ab1;
    const T t2 = in.p_lo[2] * ab0 - in.p_lo[0] * ab2 - exact_cross[1];
    const T t3 = in.p_lo[0] * ab1 - ab0 * in.p_lo[1] - exact_cross[2];
    cross_cross = t2 * t2 + t3 * t3 + t1 * t1;
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + ap1 * bp1;
  const T zeta2 = in.z * in.z;
  const T c = ap_ap + zeta2;
  const T D = cross_cross + zeta2 * ab_ab;
  const T h = cross1 * in.normal[1] + in.normal[0] * cross0 + in.normal[2] * cross2;
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
  const T t4 = max(T(max(T(D - T(2) * ab_ab * ab_ab), T(max(T(ab_ap - T(3) * ab_ab), T(-ab_ap - T(2) * ab_ab))))), T(c - ab_ap - zeta2 - (T(221) / T(16)) * ab_ab));
  const T t5 = -ab_ap * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * ab_ab - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 225/16 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 6> M_flat;
    segment_moments_far_field<T>(2, 12, 0, ab_ab, ab_ap, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
    J_10 = M_flat[4];
    J_12 = M_flat[5];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(2, 12, 0, ab_ab, ab_ap, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
    J_8 = M_beyond[3];
    J_10 = M_beyond[4];
    J_12 = M_beyond[5];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = t9 * atan2(t8, c_minus_b);
    J_2 = J2;
    const T t10 = T(1) / D;
    const T t11 = T(1) / q1;
    const T t12 = T(1) / c;
    const T t13 = t11 * a_minus_b + ab_ap * t12 + J2 * ab_ab;
    J_4 = (T(1) / T(2)) * t10 * t13;
    const T t14 = t12 * t12;
    const T t15 = t11 * t11;
    const T t16 = T(2) * ab_ap * t14 + T(3) * t10 * t13 * ab_ab + T(2) * t15 * a_minus_b;
    J_6 = (T(1) / T(8)) * t10 * t16;
    const T t17 = t14 * t12;
    const T t18 = t15 * t11;
    const T t19 = T(8) * ab_ap * t17 + T(8) * t18 * a_minus_b + T(5) * t10 * t16 * ab_ab;
    J_8 = (T(1) / T(48)) * t10 * t19;
    const T t20 = t15 * t15;
    const T t21 = t14 * t14;
    const T t22 = T(48) * t20 * a_minus_b + T(48) * ab_ap * t21 + T(7) * t10 * ab_ab * t19;
    J_10 = (T(1) / T(384)) * t10 * t22;
    const T t23 = t21 * t12;
    const T t24 = t20 * t11;
    J_12 = (T(1) / T(1280)) * t10 * (T(128) * ab_ap * t23 + T(128) * t24 * a_minus_b + T(3) * t10 * t22 * ab_ab);
  }
  T H_f;
  T H_g;
  const T t25 = t6 - T(2) * zeta2;
  const T t26 = max(T(D - T(2) * zeta2 * ab_ab), T(t5));
  if (t25 >= T(0) && t26 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t27 = -ab_ap;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(10, 12, h, ab_ab, zeta2, t27, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t28 = T(1) / zeta2;
    const T H2 = -(J_2 * h - theta) * t28;
    const T H4 = t28 * (H2 - J_4 * h);
    const T H6 = (H4 - h * J_6) * t28;
    const T H8 = -t28 * (J_8 * h - H6);
    const T H10 = t28 * (H8 - J_10 * h);
    const T H12 = (H10 - h * J_12) * t28;
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
