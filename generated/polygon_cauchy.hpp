// generated/polygon_cauchy.hpp — polygon edge kernels of the cauchy family.
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
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−3/2) dQ
/// Operations per edge: 44 +, 59 ×, 1 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 177 +, 207 ×, 23 /, 22 sqrt, 3 atan, 0 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i3_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ap2 * ab1 - ap1 * ab2;
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
    const T t1 = in.p_lo[0] * ab2 + exact_cross[1] - ab0 * in.p_lo[2];
    cross1 = t1;
    const T t2 = exact_cross[2] + ab0 * in.p_lo[1] - in.p_lo[0] * ab1;
    cross2 = t2;
    const T t3 = ab2 * in.p_lo[1] - exact_cross[0] - in.p_lo[2] * ab1;
    cross_cross = t3 * t3 + t1 * t1 + t2 * t2;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp1 * ab1 + ab0 * bp0;
  const T ap_bp = bp1 * ap1 + ap0 * bp0 + ap2 * bp2;
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = (zeta2 * ab_ab + cross_cross * in.s) * in.s;
  const T h = in.normal[0] * cross0 + cross2 * in.normal[2] + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  const T alpha_h = h * in.s;
  T H_f;
  const T t4 = min(T(c), T(q1)) - T(2) * zeta2;
  const T t5 = max(T(D - T(2) * zeta2 * a), T(-a_minus_b * b));
  if (t4 >= T(0) && t5 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(1, 1, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * alpha_h * (r1 * b + r0 * a_minus_b), r0 * alpha_h * alpha_h * r1 - zeta2 * a_minus_b * b) / zeta;
    H_f = H1;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−3/2) dQ
/// Operations per edge: 73 +, 87 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 549 +, 1081 ×, 145 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i3_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
    const T t1 = in.p_lo[2] * ab1 + exact_cross[0] - ab2 * in.p_lo[1];
    cross0 = t1;
    cross1 = ab2 * in.p_lo[0] + exact_cross[1] - ab0 * in.p_lo[2];
    const T t2 = exact_cross[2] + ab0 * in.p_lo[1] - ab1 * in.p_lo[0];
    cross2 = t2;
    const T t3 = ab0 * in.p_lo[2] - ab2 * in.p_lo[0] - exact_cross[1];
    cross_cross = t1 * t1 + t2 * t2 + t3 * t3;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = bp2 * ap2 + bp0 * ap0 + ap1 * bp1;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + zeta2;
  const T D = (ab_ab * zeta2 + in.s * cross_cross) * in.s;
  const T h = in.normal[0] * cross0 + cross1 * in.normal[1] + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))))), T(c - (T(15) / T(4)) * a - b - zeta2));
  const T t5 = -a_minus_b * b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * a - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 1> M_flat;
    segment_moments_far_field<T>(3, 3, 0, a, b, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(3, 3, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    J_3 = (a_minus_b / r1 + b / r0) / D;
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t8 = t6 - T(2) * zeta2;
  const T t9 = max(T(D - T(2) * a * zeta2), T(t5));
  if (t8 >= T(0) && t9 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t10 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(3, 3, alpha_h, a, zeta2, t10, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((r1 * b + r0 * a_minus_b) * zeta * alpha_h, r0 * r1 * alpha_h * alpha_h - a_minus_b * b * zeta2) / zeta;
    const T H3 = (H1 - J_3 * alpha_h) / zeta2;
    H_g = H3;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_3;
}

/// The terms of one edge for f and ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−3/2) dQ
/// Operations per edge: 73 +, 87 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 567 +, 1080 ×, 145 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i3_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
    const T t1 = in.p_lo[2] * ab1 + exact_cross[0] - ab2 * in.p_lo[1];
    cross0 = t1;
    const T t2 = ab2 * in.p_lo[0] + exact_cross[1] - in.p_lo[2] * ab0;
    cross1 = t2;
    const T t3 = in.p_lo[1] * ab0 + exact_cross[2] - ab1 * in.p_lo[0];
    cross2 = t3;
    cross_cross = t3 * t3 + t2 * t2 + t1 * t1;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + bp0 * ab0 + ab1 * bp1;
  const T ap_bp = bp2 * ap2 + bp0 * ap0 + ap1 * bp1;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + zeta2;
  const T D = (ab_ab * zeta2 + in.s * cross_cross) * in.s;
  const T h = in.normal[0] * cross0 + in.normal[2] * cross2 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))))), T(c - (T(15) / T(4)) * a - b - zeta2));
  const T t5 = -a_minus_b * b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * a * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 1> M_flat;
    segment_moments_far_field<T>(3, 3, 0, a, b, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(3, 3, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    J_3 = (b / r0 + a_minus_b / r1) / D;
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t8 = t6 - T(2) * zeta2;
  const T t9 = max(T(D - T(2) * a * zeta2), T(t5));
  if (t8 >= T(0) && t9 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t10 = -b;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(1, 3, alpha_h, a, zeta2, t10, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * (r1 * b + a_minus_b * r0) * alpha_h, r1 * alpha_h * alpha_h * r0 - a_minus_b * b * zeta2) / zeta;
    const T H3 = (H1 - alpha_h * J_3) / zeta2;
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
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−4/2) dQ
/// Operations per edge: 71 +, 79 ×, 2 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 552 +, 1042 ×, 145 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i4_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_ap = ab1 * ap1 + ap2 * ab2 + ap0 * ab0;
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
    cross0 = ab1 * in.p_lo[2] + exact_cross[0] - in.p_lo[1] * ab2;
    cross1 = exact_cross[1] + in.p_lo[0] * ab2 - ab0 * in.p_lo[2];
    const T t1 = in.p_lo[1] * ab0 + exact_cross[2] - ab1 * in.p_lo[0];
    cross2 = t1;
    const T t2 = ab0 * in.p_lo[2] - exact_cross[1] - in.p_lo[0] * ab2;
    const T t3 = in.p_lo[1] * ab2 - ab1 * in.p_lo[2] - exact_cross[0];
    cross_cross = t1 * t1 + t2 * t2 + t3 * t3;
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp2 * ab2 + ab0 * bp0;
  const T ap_bp = bp1 * ap1 + ap0 * bp0 + bp2 * ap2;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = zeta2 + in.s * ap_ap;
  const T D = in.s * (in.s * cross_cross + zeta2 * ab_ab);
  const T h = cross2 * in.normal[2] + cross1 * in.normal[1] + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + in.s * bp_bp;
  const T c_minus_b = zeta2 + in.s * ap_bp;
  T J_2;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))))), T(c - zeta2 - (T(15) / T(4)) * a - b));
  const T t5 = -a_minus_b * b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * a - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 1> M_flat;
    segment_moments_far_field<T>(2, 2, 0, a, b, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(2, 2, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T J2 = atan2(t8, c_minus_b) / t8;
    J_2 = J2;
  }
  const T alpha_h = in.s * h;
  T H_f;
  const T t9 = t6 - T(2) * zeta2;
  const T t10 = max(T(D - T(2) * zeta2 * a), T(t5));
  if (t9 >= T(0) && t10 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t11 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(2, 2, alpha_h, a, zeta2, t11, a_minus_b, H_near.data());
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

/// The terms of one edge for ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−4/2) dQ
/// Operations per edge: 74 +, 86 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 554 +, 1072 ×, 147 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i4_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = ap_hi0 + in.p_lo[0];
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
  const T bp2 = in.p_lo[2] + bp_hi2;
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
    const T t1 = exact_cross[0] + in.p_lo[2] * ab1 - ab2 * in.p_lo[1];
    cross0 = t1;
    const T t2 = exact_cross[1] + ab2 * in.p_lo[0] - ab0 * in.p_lo[2];
    cross1 = t2;
    cross2 = exact_cross[2] + ab0 * in.p_lo[1] - ab1 * in.p_lo[0];
    const T t3 = ab1 * in.p_lo[0] - exact_cross[2] - ab0 * in.p_lo[1];
    cross_cross = t3 * t3 + t1 * t1 + t2 * t2;
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = in.s * ap_ap + zeta2;
  const T D = (cross_cross * in.s + zeta2 * ab_ab) * in.s;
  const T h = cross1 * in.normal[1] + cross0 * in.normal[0] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + zeta2;
  const T c_minus_b = zeta2 + in.s * ap_bp;
  T J_2;
  T J_4;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-b - T(2) * a))))), T(c - b - zeta2 - (T(15) / T(4)) * a));
  const T t5 = -b * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * a - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 2> M_flat;
    segment_moments_far_field<T>(2, 4, 0, a, b, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(2, 4, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = atan2(t8, c_minus_b) * t9;
    J_2 = J2;
    const T t10 = T(1) / D;
    J_4 = (T(1) / T(2)) * (a_minus_b / q1 + b / c + a * J2) * t10;
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t11 = t6 - T(2) * zeta2;
  const T t12 = max(T(D - T(2) * zeta2 * a), T(t5));
  if (t11 >= T(0) && t12 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t13 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(4, 4, alpha_h, a, zeta2, t13, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t14 = T(1) / zeta2;
    const T H2 = t14 * (theta - J_2 * alpha_h);
    const T H4 = t14 * (H2 - J_4 * alpha_h);
    H_g = H4;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_4;
}

/// The terms of one edge for f and ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−4/2) dQ
/// Operations per edge: 74 +, 86 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 572 +, 1091 ×, 147 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i4_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + zeta2;
  const T D = (in.s * cross_cross + zeta2 * ab_ab) * in.s;
  const T h = cross1 * in.normal[1] + in.normal[0] * cross0 + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + zeta2;
  const T c_minus_b = zeta2 + in.s * ap_bp;
  T J_2;
  T J_4;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-b - T(2) * a))))), T(c - b - zeta2 - (T(15) / T(4)) * a));
  const T t5 = -b * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * a * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 2> M_flat;
    segment_moments_far_field<T>(2, 4, 0, a, b, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(2, 4, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = atan2(t8, c_minus_b) * t9;
    J_2 = J2;
    const T t10 = T(1) / D;
    J_4 = (T(1) / T(2)) * (b / c + a * J2 + a_minus_b / q1) * t10;
  }
  const T alpha_h = in.s * h;
  T H_f;
  T H_g;
  const T t11 = t6 - T(2) * zeta2;
  const T t12 = max(T(D - T(2) * zeta2 * a), T(t5));
  if (t11 >= T(0) && t12 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t13 = -b;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(2, 4, alpha_h, a, zeta2, t13, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t14 = T(1) / zeta2;
    const T H2 = (theta - J_2 * alpha_h) * t14;
    const T H4 = t14 * (H2 - alpha_h * J_4);
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
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−5/2) dQ
/// Operations per edge: 73 +, 87 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 549 +, 1081 ×, 145 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i5_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
    cross0 = exact_cross[0] + in.p_lo[2] * ab1 - ab2 * in.p_lo[1];
    const T t1 = in.p_lo[0] * ab2 + exact_cross[1] - ab0 * in.p_lo[2];
    cross1 = t1;
    const T t2 = exact_cross[2] + ab0 * in.p_lo[1] - in.p_lo[0] * ab1;
    cross2 = t2;
    const T t3 = ab2 * in.p_lo[1] - exact_cross[0] - in.p_lo[2] * ab1;
    cross_cross = t3 * t3 + t2 * t2 + t1 * t1;
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + bp1 * ab1;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + zeta2;
  const T D = in.s * (zeta2 * ab_ab + cross_cross * in.s);
  const T h = cross2 * in.normal[2] + in.normal[0] * cross0 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))))), T(c - (T(15) / T(4)) * a - b - zeta2));
  const T t5 = -a_minus_b * b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * a * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 1> M_flat;
    segment_moments_far_field<T>(3, 3, 0, a, b, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(3, 3, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    J_3 = (b / r0 + a_minus_b / r1) / D;
  }
  const T alpha_h = h * in.s;
  T H_f;
  const T t8 = t6 - T(2) * zeta2;
  const T t9 = max(T(D - T(2) * a * zeta2), T(t5));
  if (t8 >= T(0) && t9 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t10 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(3, 3, alpha_h, a, zeta2, t10, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(alpha_h * zeta * (r1 * b + r0 * a_minus_b), r0 * r1 * alpha_h * alpha_h - a_minus_b * b * zeta2) / zeta;
    const T H3 = (H1 - J_3 * alpha_h) / zeta2;
    H_f = H3;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−5/2) dQ
/// Operations per edge: 76 +, 100 ×, 7 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 553 +, 1133 ×, 147 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i5_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;
  const T ab0 = in.b[0] - in.a[0];
  const T ap_hi0 = in.p[0] - in.a[0];
  const T ap0 = ap_hi0 + in.p_lo[0];
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
  const T bp2 = in.p_lo[2] + bp_hi2;
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
    const T t1 = in.p_lo[2] * ab1 + exact_cross[0] - ab2 * in.p_lo[1];
    cross0 = t1;
    cross1 = ab2 * in.p_lo[0] + exact_cross[1] - in.p_lo[2] * ab0;
    const T t2 = ab0 * in.p_lo[1] + exact_cross[2] - ab1 * in.p_lo[0];
    cross2 = t2;
    const T t3 = in.p_lo[2] * ab0 - ab2 * in.p_lo[0] - exact_cross[1];
    cross_cross = t2 * t2 + t3 * t3 + t1 * t1;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + ap1 * bp1;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + zeta2;
  const T D = in.s * (ab_ab * zeta2 + cross_cross * in.s);
  const T h = cross1 * in.normal[1] + cross2 * in.normal[2] + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))))), T(c - (T(15) / T(4)) * a - b - zeta2));
  const T t5 = -b * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * a * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 2> M_flat;
    segment_moments_far_field<T>(3, 5, 0, a, b, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(3, 5, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / D;
    const T t9 = T(1) / r1;
    const T t10 = T(1) / r0;
    const T t11 = t9 * a_minus_b + t10 * b;
    J_3 = t8 * t11;
    J_5 = (T(1) / T(3)) * t8 * (t10 * b / c + T(2) * t8 * a * t11 + t9 * a_minus_b / q1);
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t12 = t6 - T(2) * zeta2;
  const T t13 = max(T(D - T(2) * a * zeta2), T(t5));
  if (t12 >= T(0) && t13 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t14 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(5, 5, alpha_h, a, zeta2, t14, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * (r0 * a_minus_b + b * r1) * alpha_h, r0 * r1 * alpha_h * alpha_h - b * a_minus_b * zeta2) / zeta;
    const T t15 = T(1) / zeta2;
    const T H3 = t15 * (H1 - J_3 * alpha_h);
    const T H5 = (H3 - J_5 * alpha_h) * t15;
    H_g = H5;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_5;
}

/// The terms of one edge for f and ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−5/2) dQ
/// Operations per edge: 76 +, 100 ×, 7 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 575 +, 1136 ×, 147 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i5_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_ap = ab0 * ap0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
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
    cross1 = in.p_lo[0] * ab2 + exact_cross[1] - ab0 * in.p_lo[2];
    const T t1 = exact_cross[2] + ab0 * in.p_lo[1] - in.p_lo[0] * ab1;
    cross2 = t1;
    const T t2 = ab0 * in.p_lo[2] - in.p_lo[0] * ab2 - exact_cross[1];
    const T t3 = ab2 * in.p_lo[1] - exact_cross[0] - in.p_lo[2] * ab1;
    cross_cross = t1 * t1 + t2 * t2 + t3 * t3;
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + bp0 * ap0 + bp1 * ap1;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + zeta2;
  const T D = (zeta2 * ab_ab + cross_cross * in.s) * in.s;
  const T h = in.normal[1] * cross1 + in.normal[0] * cross0 + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))))), T(c - (T(15) / T(4)) * a - b - zeta2));
  const T t5 = -b * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * a * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 2> M_flat;
    segment_moments_far_field<T>(3, 5, 0, a, b, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(3, 5, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / D;
    const T t9 = T(1) / r1;
    const T t10 = T(1) / r0;
    const T t11 = t9 * a_minus_b + t10 * b;
    J_3 = t8 * t11;
    J_5 = (T(1) / T(3)) * t8 * (t9 * a_minus_b / q1 + T(2) * t8 * a * t11 + t10 * b / c);
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t12 = t6 - T(2) * zeta2;
  const T t13 = max(T(D - T(2) * a * zeta2), T(t5));
  if (t12 >= T(0) && t13 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t14 = -b;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(3, 5, alpha_h, a, zeta2, t14, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * alpha_h * (r0 * a_minus_b + b * r1), r0 * r1 * alpha_h * alpha_h - b * a_minus_b * zeta2) / zeta;
    const T t15 = T(1) / zeta2;
    const T H3 = (H1 - J_3 * alpha_h) * t15;
    const T H5 = (H3 - J_5 * alpha_h) * t15;
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
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−6/2) dQ
/// Operations per edge: 74 +, 86 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 552 +, 1070 ×, 147 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i6_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ap1 * ab1;
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
    const T t1 = exact_cross[0] + in.p_lo[2] * ab1 - ab2 * in.p_lo[1];
    cross0 = t1;
    const T t2 = in.p_lo[0] * ab2 + exact_cross[1] - ab0 * in.p_lo[2];
    cross1 = t2;
    const T t3 = exact_cross[2] + ab0 * in.p_lo[1] - in.p_lo[0] * ab1;
    cross2 = t3;
    cross_cross = t2 * t2 + t1 * t1 + t3 * t3;
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + ap1 * bp1;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + zeta2;
  const T D = (cross_cross * in.s + zeta2 * ab_ab) * in.s;
  const T h = cross1 * in.normal[1] + in.normal[0] * cross0 + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + zeta2;
  const T c_minus_b = in.s * ap_bp + zeta2;
  T J_2;
  T J_4;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))))), T(c - (T(15) / T(4)) * a - b - zeta2));
  const T t5 = -b * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * a * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 2> M_flat;
    segment_moments_far_field<T>(2, 4, 0, a, b, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(2, 4, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = t9 * atan2(t8, c_minus_b);
    J_2 = J2;
    const T t10 = T(1) / D;
    J_4 = (T(1) / T(2)) * t10 * (a * J2 + b / c + a_minus_b / q1);
  }
  const T alpha_h = h * in.s;
  T H_f;
  const T t11 = t6 - T(2) * zeta2;
  const T t12 = max(T(D - T(2) * a * zeta2), T(t5));
  if (t11 >= T(0) && t12 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t13 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(4, 4, alpha_h, a, zeta2, t13, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t14 = T(1) / zeta2;
    const T H2 = -(J_2 * alpha_h - theta) * t14;
    const T H4 = (H2 - alpha_h * J_4) * t14;
    H_f = H4;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−6/2) dQ
/// Operations per edge: 77 +, 101 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 556 +, 1103 ×, 149 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i6_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T bp2 = bp_hi2 + in.p_lo[2];
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
  const T plain_cross2 = ap1 * ab0 - ab1 * ap0;
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
    const T t1 = ab1 * in.p_lo[2] + exact_cross[0] - in.p_lo[1] * ab2;
    cross0 = t1;
    const T t2 = exact_cross[1] + ab2 * in.p_lo[0] - ab0 * in.p_lo[2];
    cross1 = t2;
    const T t3 = exact_cross[2] + in.p_lo[1] * ab0 - ab1 * in.p_lo[0];
    cross2 = t3;
    cross_cross = t2 * t2 + t3 * t3 + t1 * t1;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + bp0 * ab0;
  const T ap_bp = bp1 * ap1 + ap2 * bp2 + ap0 * bp0;
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = (cross_cross * in.s + zeta2 * ab_ab) * in.s;
  const T h = in.normal[0] * cross0 + cross1 * in.normal[1] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T c_minus_b = zeta2 + ap_bp * in.s;
  T J_2;
  T J_4;
  T J_6;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))))), T(c - zeta2 - (T(15) / T(4)) * a - b));
  const T t5 = -a_minus_b * b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * a * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 3> M_flat;
    segment_moments_far_field<T>(2, 6, 0, a, b, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(2, 6, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
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
    const T t13 = a * J2 + t11 * b + a_minus_b * t12;
    J_4 = (T(1) / T(2)) * t10 * t13;
    const T t14 = t12 * t12;
    const T t15 = t11 * t11;
    J_6 = (T(1) / T(8)) * (T(3) * a * t10 * t13 + T(2) * a_minus_b * t14 + T(2) * t15 * b) * t10;
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t16 = t6 - T(2) * zeta2;
  const T t17 = max(T(D - T(2) * zeta2 * a), T(t5));
  if (t16 >= T(0) && t17 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t18 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(6, 6, alpha_h, a, zeta2, t18, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t19 = T(1) / zeta2;
    const T H2 = -t19 * (J_2 * alpha_h - theta);
    const T H4 = t19 * (H2 - alpha_h * J_4);
    const T H6 = (H4 - J_6 * alpha_h) * t19;
    H_g = H6;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_6;
}

/// The terms of one edge for f and ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−6/2) dQ
/// Operations per edge: 77 +, 101 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 576 +, 1124 ×, 149 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i6_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_ap = ab1 * ap1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ap1 * ab2;
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
    const T t1 = ab1 * in.p_lo[2] + exact_cross[0] - in.p_lo[1] * ab2;
    cross0 = t1;
    const T t2 = exact_cross[1] + in.p_lo[0] * ab2 - ab0 * in.p_lo[2];
    cross1 = t2;
    const T t3 = in.p_lo[1] * ab0 + exact_cross[2] - ab1 * in.p_lo[0];
    cross2 = t3;
    cross_cross = t3 * t3 + t1 * t1 + t2 * t2;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + bp1 * ap1;
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + zeta2;
  const T D = in.s * (cross_cross * in.s + zeta2 * ab_ab);
  const T h = cross2 * in.normal[2] + cross1 * in.normal[1] + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + zeta2;
  const T c_minus_b = zeta2 + ap_bp * in.s;
  T J_2;
  T J_4;
  T J_6;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))))), T(c - zeta2 - (T(15) / T(4)) * a - b));
  const T t5 = -a_minus_b * b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * a * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 3> M_flat;
    segment_moments_far_field<T>(2, 6, 0, a, b, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(2, 6, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = sqrt(D);
    const T t9 = T(1) / t8;
    const T J2 = atan2(t8, c_minus_b) * t9;
    J_2 = J2;
    const T t10 = T(1) / q1;
    const T t11 = T(1) / c;
    const T t12 = J2 * a + a_minus_b * t10 + t11 * b;
    const T t13 = T(1) / D;
    J_4 = (T(1) / T(2)) * t12 * t13;
    const T t14 = t11 * t11;
    const T t15 = t10 * t10;
    J_6 = (T(1) / T(8)) * t13 * (T(2) * t14 * b + T(2) * a_minus_b * t15 + T(3) * t12 * t13 * a);
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t16 = t6 - T(2) * zeta2;
  const T t17 = max(T(D - T(2) * zeta2 * a), T(t5));
  if (t16 >= T(0) && t17 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t18 = -b;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(4, 6, alpha_h, a, zeta2, t18, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t19 = T(1) / zeta2;
    const T H2 = t19 * (theta - J_2 * alpha_h);
    const T H4 = -(alpha_h * J_4 - H2) * t19;
    const T H6 = -(J_6 * alpha_h - H4) * t19;
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
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−7/2) dQ
/// Operations per edge: 76 +, 100 ×, 7 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 555 +, 1135 ×, 147 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i7_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T plain_cross0 = ap2 * ab1 - ap1 * ab2;
  const T plain_cross1 = ab2 * ap0 - ap2 * ab0;
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
    const T t1 = in.p_lo[2] * ab1 + exact_cross[0] - ab2 * in.p_lo[1];
    cross0 = t1;
    cross1 = in.p_lo[0] * ab2 + exact_cross[1] - ab0 * in.p_lo[2];
    cross2 = exact_cross[2] + ab0 * in.p_lo[1] - in.p_lo[0] * ab1;
    const T t2 = in.p_lo[0] * ab1 - exact_cross[2] - ab0 * in.p_lo[1];
    const T t3 = ab0 * in.p_lo[2] - in.p_lo[0] * ab2 - exact_cross[1];
    cross_cross = t1 * t1 + t2 * t2 + t3 * t3;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + bp0 * ap0 + bp1 * ap1;
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = (zeta2 * ab_ab + cross_cross * in.s) * in.s;
  const T h = in.normal[0] * cross0 + cross2 * in.normal[2] + in.normal[1] * cross1;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))))), T(c - zeta2 - (T(15) / T(4)) * a - b));
  const T t5 = -b * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * a * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 2> M_flat;
    segment_moments_far_field<T>(3, 5, 0, a, b, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(3, 5, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / D;
    const T t9 = T(1) / r0;
    const T t10 = T(1) / r1;
    const T t11 = t9 * b + t10 * a_minus_b;
    J_3 = t8 * t11;
    J_5 = (T(1) / T(3)) * (t9 * b / c + t10 * a_minus_b / q1 + T(2) * t8 * a * t11) * t8;
  }
  const T alpha_h = h * in.s;
  T H_f;
  const T t12 = t6 - T(2) * zeta2;
  const T t13 = max(T(D - T(2) * zeta2 * a), T(t5));
  if (t12 >= T(0) && t13 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t14 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(5, 5, alpha_h, a, zeta2, t14, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(alpha_h * (b * r1 + r0 * a_minus_b) * zeta, alpha_h * alpha_h * r0 * r1 - zeta2 * b * a_minus_b) / zeta;
    const T t15 = T(1) / zeta2;
    const T H3 = t15 * (H1 - alpha_h * J_3);
    const T H5 = -t15 * (alpha_h * J_5 - H3);
    H_f = H5;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−7/2) dQ
/// Operations per edge: 79 +, 119 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 559 +, 1188 ×, 149 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i7_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_ap = ab1 * ap1 + ap2 * ab2 + ap0 * ab0;
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
    cross0 = ab1 * in.p_lo[2] + exact_cross[0] - in.p_lo[1] * ab2;
    cross1 = exact_cross[1] + in.p_lo[0] * ab2 - ab0 * in.p_lo[2];
    const T t1 = in.p_lo[1] * ab0 + exact_cross[2] - ab1 * in.p_lo[0];
    cross2 = t1;
    const T t2 = ab0 * in.p_lo[2] - exact_cross[1] - in.p_lo[0] * ab2;
    const T t3 = in.p_lo[1] * ab2 - ab1 * in.p_lo[2] - exact_cross[0];
    cross_cross = t2 * t2 + t3 * t3 + t1 * t1;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = bp1 * ap1 + ap0 * bp0 + ap2 * bp2;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + zeta2;
  const T D = in.s * (in.s * cross_cross + ab_ab * zeta2);
  const T h = cross2 * in.normal[2] + cross1 * in.normal[1] + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = zeta2 + in.s * bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))))), T(c - zeta2 - (T(73) / T(16)) * a - b));
  const T t5 = -a_minus_b * b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * a - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 77/16 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 3> M_flat;
    segment_moments_far_field<T>(3, 7, 0, a, b, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(3, 7, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / r0;
    const T t9 = T(1) / r1;
    const T t10 = t8 * b + t9 * a_minus_b;
    const T t11 = T(1) / D;
    J_3 = t10 * t11;
    const T t12 = t8 * t8;
    const T t13 = t9 * t9;
    const T t14 = T(2) * t10 * t11 * a + t8 * t12 * b + t9 * a_minus_b * t13;
    J_5 = (T(1) / T(3)) * t14 * t11;
    const T t15 = t13 * t13;
    const T t16 = t12 * t12;
    J_7 = (T(1) / T(15)) * (T(3) * t9 * a_minus_b * t15 + T(4) * t14 * t11 * a + T(3) * t8 * t16 * b) * t11;
  }
  const T alpha_h = in.s * h;
  T H_g;
  const T t17 = t6 - T(2) * zeta2;
  const T t18 = max(T(D - T(2) * zeta2 * a), T(t5));
  if (t17 >= T(0) && t18 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t19 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(7, 7, alpha_h, a, zeta2, t19, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * alpha_h * (r1 * b + r0 * a_minus_b), r0 * alpha_h * alpha_h * r1 - zeta2 * a_minus_b * b) / zeta;
    const T t20 = T(1) / zeta2;
    const T H3 = -t20 * (alpha_h * J_3 - H1);
    const T H5 = -t20 * (alpha_h * J_5 - H3);
    const T H7 = t20 * (H5 - J_7 * alpha_h);
    H_g = H7;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_7;
}

/// The terms of one edge for f and ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−7/2) dQ
/// Operations per edge: 79 +, 119 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 575 +, 1185 ×, 149 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i7_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross1 * plain_cross1 + plain_cross2 * plain_cross2;
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
    cross_cross = t2 * t2 + t3 * t3 + t1 * t1;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + ap1 * bp1 + bp2 * ap2;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = zeta2 + ap_ap * in.s;
  const T D = in.s * (ab_ab * zeta2 + cross_cross * in.s);
  const T h = cross1 * in.normal[1] + in.normal[0] * cross0 + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))))), T(c - (T(73) / T(16)) * a - b - zeta2));
  const T t5 = -b * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * a * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 77/16 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 3> M_flat;
    segment_moments_far_field<T>(3, 7, 0, a, b, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(3, 7, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / D;
    const T t9 = T(1) / r0;
    const T t10 = T(1) / r1;
    const T t11 = b * t9 + t10 * a_minus_b;
    J_3 = t8 * t11;
    const T t12 = t9 * t9;
    const T t13 = t10 * t10;
    const T t14 = T(2) * a * t8 * t11 + b * t9 * t12 + t13 * t10 * a_minus_b;
    J_5 = (T(1) / T(3)) * t8 * t14;
    const T t15 = t12 * t12;
    const T t16 = t13 * t13;
    J_7 = (T(1) / T(15)) * t8 * (T(3) * b * t9 * t15 + T(3) * t16 * t10 * a_minus_b + T(4) * a * t8 * t14);
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t17 = t6 - T(2) * zeta2;
  const T t18 = max(T(D - T(2) * a * zeta2), T(t5));
  if (t17 >= T(0) && t18 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t19 = -b;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(5, 7, alpha_h, a, zeta2, t19, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * (r0 * a_minus_b + b * r1) * alpha_h, r0 * alpha_h * alpha_h * r1 - b * zeta2 * a_minus_b) / zeta;
    const T t20 = T(1) / zeta2;
    const T H3 = -(J_3 * alpha_h - H1) * t20;
    const T H5 = -t20 * (J_5 * alpha_h - H3);
    const T H7 = -(J_7 * alpha_h - H5) * t20;
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
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−8/2) dQ
/// Operations per edge: 77 +, 101 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 562 +, 1109 ×, 149 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i8_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
    cross0 = exact_cross[0] + in.p_lo[2] * ab1 - ab2 * in.p_lo[1];
    cross1 = exact_cross[1] + ab2 * in.p_lo[0] - ab0 * in.p_lo[2];
    cross2 = ab0 * in.p_lo[1] + exact_cross[2] - ab1 * in.p_lo[0];
    const T t1 = ab0 * in.p_lo[2] - exact_cross[1] - ab2 * in.p_lo[0];
    const T t2 = ab1 * in.p_lo[0] - ab0 * in.p_lo[1] - exact_cross[2];
    const T t3 = ab2 * in.p_lo[1] - exact_cross[0] - in.p_lo[2] * ab1;
    cross_cross = t1 * t1 + t2 * t2 + t3 * t3;
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = bp0 * ap0 + ap1 * bp1 + bp2 * ap2;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + zeta2;
  const T D = in.s * (cross_cross * in.s + zeta2 * ab_ab);
  const T h = in.normal[0] * cross0 + cross1 * in.normal[1] + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + zeta2;
  const T c_minus_b = in.s * ap_bp + zeta2;
  T J_2;
  T J_4;
  T J_6;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))))), T(c - (T(15) / T(4)) * a - b - zeta2));
  const T t5 = -b * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * a * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 3> M_flat;
    segment_moments_far_field<T>(2, 6, 0, a, b, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(2, 6, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
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
    const T t11 = T(1) / q1;
    const T t12 = T(1) / c;
    const T t13 = a * J2 + t11 * a_minus_b + b * t12;
    J_4 = (T(1) / T(2)) * t10 * t13;
    const T t14 = t12 * t12;
    const T t15 = t11 * t11;
    J_6 = (T(1) / T(8)) * t10 * (T(2) * b * t14 + T(2) * t15 * a_minus_b + T(3) * a * t10 * t13);
  }
  const T alpha_h = h * in.s;
  T H_f;
  const T t16 = t6 - T(2) * zeta2;
  const T t17 = max(T(D - T(2) * a * zeta2), T(t5));
  if (t16 >= T(0) && t17 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t18 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(6, 6, alpha_h, a, zeta2, t18, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t19 = T(1) / zeta2;
    const T H2 = t19 * (theta - J_2 * alpha_h);
    const T H4 = -t19 * (J_4 * alpha_h - H2);
    const T H6 = t19 * (H4 - J_6 * alpha_h);
    H_f = H6;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−8/2) dQ
/// Operations per edge: 80 +, 114 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 560 +, 1137 ×, 151 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i8_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
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
    const T t1 = exact_cross[0] + ab1 * in.p_lo[2] - ab2 * in.p_lo[1];
    cross0 = t1;
    const T t2 = exact_cross[1] + ab2 * in.p_lo[0] - ab0 * in.p_lo[2];
    cross1 = t2;
    const T t3 = in.p_lo[1] * ab0 + exact_cross[2] - ab1 * in.p_lo[0];
    cross2 = t3;
    cross_cross = t2 * t2 + t3 * t3 + t1 * t1;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + bp2 * ap2 + bp0 * ap0;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + zeta2;
  const T D = in.s * (zeta2 * ab_ab + in.s * cross_cross);
  const T h = cross1 * in.normal[1] + in.normal[0] * cross0 + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T c_minus_b = in.s * ap_bp + zeta2;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-b - T(2) * a))))), T(c - b - zeta2 - T(6) * a));
  const T t5 = -a_minus_b * b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * a - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 25/4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 4> M_flat;
    segment_moments_far_field<T>(2, 8, 0, a, b, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(2, 8, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
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
    const T t10 = T(1) / q1;
    const T t11 = T(1) / c;
    const T t12 = a_minus_b * t10 + J2 * a + b * t11;
    const T t13 = T(1) / D;
    J_4 = (T(1) / T(2)) * t12 * t13;
    const T t14 = t11 * t11;
    const T t15 = t10 * t10;
    const T t16 = T(2) * b * t14 + T(3) * t12 * t13 * a + T(2) * a_minus_b * t15;
    J_6 = (T(1) / T(8)) * t16 * t13;
    const T t17 = t14 * t11;
    const T t18 = t15 * t10;
    J_8 = (T(1) / T(48)) * (T(8) * b * t17 + T(5) * t16 * t13 * a + T(8) * a_minus_b * t18) * t13;
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t19 = t6 - T(2) * zeta2;
  const T t20 = max(T(D - T(2) * zeta2 * a), T(t5));
  if (t19 >= T(0) && t20 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t21 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(8, 8, alpha_h, a, zeta2, t21, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t22 = T(1) / zeta2;
    const T H2 = (theta - alpha_h * J_2) * t22;
    const T H4 = -t22 * (J_4 * alpha_h - H2);
    const T H6 = t22 * (H4 - J_6 * alpha_h);
    const T H8 = (H6 - J_8 * alpha_h) * t22;
    H_g = H8;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_8;
}

/// The terms of one edge for f and ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−8/2) dQ
/// Operations per edge: 80 +, 114 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 582 +, 1160 ×, 151 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i8_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
    const T t1 = exact_cross[0] + in.p_lo[2] * ab1 - ab2 * in.p_lo[1];
    cross0 = t1;
    cross1 = exact_cross[1] + in.p_lo[0] * ab2 - ab0 * in.p_lo[2];
    const T t2 = exact_cross[2] + ab0 * in.p_lo[1] - in.p_lo[0] * ab1;
    cross2 = t2;
    const T t3 = ab0 * in.p_lo[2] - exact_cross[1] - in.p_lo[0] * ab2;
    cross_cross = t2 * t2 + t3 * t3 + t1 * t1;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab0 * bp0 + bp1 * ab1 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + bp1 * ap1 + bp0 * ap0;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = (zeta2 * ab_ab + cross_cross * in.s) * in.s;
  const T h = in.normal[0] * cross0 + cross2 * in.normal[2] + in.normal[1] * cross1;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T c_minus_b = ap_bp * in.s + zeta2;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))))), T(c - zeta2 - T(6) * a - b));
  const T t5 = -a_minus_b * b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * a - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 25/4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 4> M_flat;
    segment_moments_far_field<T>(2, 8, 0, a, b, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(2, 8, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
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
    const T t13 = a_minus_b * t11 + b * t12 + J2 * a;
    J_4 = (T(1) / T(2)) * t10 * t13;
    const T t14 = t12 * t12;
    const T t15 = t11 * t11;
    const T t16 = T(3) * t10 * t13 * a + T(2) * b * t14 + T(2) * a_minus_b * t15;
    J_6 = (T(1) / T(8)) * t10 * t16;
    const T t17 = t14 * t12;
    const T t18 = t15 * t11;
    J_8 = (T(1) / T(48)) * t10 * (T(5) * t10 * a * t16 + T(8) * b * t17 + T(8) * a_minus_b * t18);
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t19 = t6 - T(2) * zeta2;
  const T t20 = max(T(D - T(2) * zeta2 * a), T(t5));
  if (t19 >= T(0) && t20 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t21 = -b;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(6, 8, alpha_h, a, zeta2, t21, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t22 = T(1) / zeta2;
    const T H2 = -t22 * (alpha_h * J_2 - theta);
    const T H4 = -t22 * (alpha_h * J_4 - H2);
    const T H6 = t22 * (H4 - alpha_h * J_6);
    const T H8 = t22 * (H6 - J_8 * alpha_h);
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
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−9/2) dQ
/// Operations per edge: 79 +, 119 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 559 +, 1188 ×, 149 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i9_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_ap = ab0 * ap0 + ap1 * ab1 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
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
    cross0 = in.p_lo[2] * ab1 + exact_cross[0] - ab2 * in.p_lo[1];
    cross1 = in.p_lo[0] * ab2 + exact_cross[1] - ab0 * in.p_lo[2];
    const T t1 = exact_cross[2] + ab0 * in.p_lo[1] - in.p_lo[0] * ab1;
    cross2 = t1;
    const T t2 = ab0 * in.p_lo[2] - in.p_lo[0] * ab2 - exact_cross[1];
    const T t3 = ab2 * in.p_lo[1] - in.p_lo[2] * ab1 - exact_cross[0];
    cross_cross = t1 * t1 + t2 * t2 + t3 * t3;
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + bp0 * ap0 + bp1 * ap1;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = (cross_cross * in.s + zeta2 * ab_ab) * in.s;
  const T h = cross2 * in.normal[2] + in.normal[1] * cross1 + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))))), T(c - zeta2 - (T(73) / T(16)) * a - b));
  const T t5 = -a_minus_b * b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * a * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 77/16 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 3> M_flat;
    segment_moments_far_field<T>(3, 7, 0, a, b, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(3, 7, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / D;
    const T t9 = T(1) / r0;
    const T t10 = T(1) / r1;
    const T t11 = b * t9 + t10 * a_minus_b;
    J_3 = t8 * t11;
    const T t12 = t10 * t10;
    const T t13 = t9 * t9;
    const T t14 = t10 * a_minus_b * t12 + T(2) * t8 * a * t11 + t13 * b * t9;
    J_5 = (T(1) / T(3)) * t14 * t8;
    const T t15 = t13 * t13;
    const T t16 = t12 * t12;
    J_7 = (T(1) / T(15)) * t8 * (T(3) * t15 * b * t9 + T(3) * t10 * a_minus_b * t16 + T(4) * t14 * t8 * a);
  }
  const T alpha_h = h * in.s;
  T H_f;
  const T t17 = t6 - T(2) * zeta2;
  const T t18 = max(T(D - T(2) * zeta2 * a), T(t5));
  if (t17 >= T(0) && t18 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t19 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(7, 7, alpha_h, a, zeta2, t19, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * alpha_h * (r1 * b + a_minus_b * r0), alpha_h * alpha_h * r1 * r0 - zeta2 * a_minus_b * b) / zeta;
    const T t20 = T(1) / zeta2;
    const T H3 = t20 * (H1 - alpha_h * J_3);
    const T H5 = -t20 * (alpha_h * J_5 - H3);
    const T H7 = -t20 * (alpha_h * J_7 - H5);
    H_f = H7;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−9/2) dQ
/// Operations per edge: 82 +, 134 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 559 +, 1237 ×, 151 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i9_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_ap = ap2 * ab2 + ab1 * ap1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T plain_cross0 = ab1 * ap2 - ap1 * ab2;
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
    const T t1 = exact_cross[0] + ab1 * in.p_lo[2] - in.p_lo[1] * ab2;
    cross0 = t1;
    const T t2 = exact_cross[1] + in.p_lo[0] * ab2 - ab0 * in.p_lo[2];
    cross1 = t2;
    const T t3 = in.p_lo[1] * ab0 + exact_cross[2] - ab1 * in.p_lo[0];
    cross2 = t3;
    cross_cross = t2 * t2 + t1 * t1 + t3 * t3;
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + bp2 * ab2 + ab0 * bp0;
  const T ap_bp = ap0 * bp0 + bp1 * ap1 + bp2 * ap2;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + zeta2;
  const T D = in.s * (zeta2 * ab_ab + in.s * cross_cross);
  const T h = in.normal[0] * cross0 + in.normal[2] * cross2 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  T J_9;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-b - T(2) * a))))), T(c - b - zeta2 - (T(123) / T(16)) * a));
  const T t5 = -b * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * a - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 127/16 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 4> M_flat;
    segment_moments_far_field<T>(3, 9, 0, a, b, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
    J_9 = M_flat[3];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(3, 9, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
    J_9 = M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / r0;
    const T t9 = T(1) / r1;
    const T t10 = b * t8 + t9 * a_minus_b;
    const T t11 = T(1) / D;
    J_3 = t10 * t11;
    const T t12 = t8 * t8;
    const T t13 = t9 * t9;
    const T t14 = b * t12 * t8 + T(2) * t10 * t11 * a + t13 * t9 * a_minus_b;
    J_5 = (T(1) / T(3)) * t14 * t11;
    const T t15 = t13 * t13;
    const T t16 = t12 * t12;
    const T t17 = T(3) * t15 * t9 * a_minus_b + T(4) * t14 * t11 * a + T(3) * b * t16 * t8;
    J_7 = (T(1) / T(15)) * t17 * t11;
    const T t18 = t15 * t13;
    const T t19 = t16 * t12;
    J_9 = (T(1) / T(35)) * (T(2) * t17 * t11 * a + T(5) * t18 * t9 * a_minus_b + T(5) * b * t19 * t8) * t11;
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t20 = t6 - T(2) * zeta2;
  const T t21 = max(T(D - T(2) * zeta2 * a), T(t5));
  if (t20 >= T(0) && t21 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t22 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(9, 9, alpha_h, a, zeta2, t22, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * alpha_h * (b * r1 + r0 * a_minus_b), alpha_h * alpha_h * r0 * r1 - b * zeta2 * a_minus_b) / zeta;
    const T t23 = T(1) / zeta2;
    const T H3 = -t23 * (alpha_h * J_3 - H1);
    const T H5 = t23 * (H3 - J_5 * alpha_h);
    const T H7 = -t23 * (J_7 * alpha_h - H5);
    const T H9 = -t23 * (alpha_h * J_9 - H7);
    H_g = H9;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_9;
}

/// The terms of one edge for f and ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−9/2) dQ
/// Operations per edge: 82 +, 134 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 579 +, 1238 ×, 151 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i9_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap2 = ap_hi2 + in.p_lo[2];
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = in.p_lo[2] + bp_hi2;
  const T ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ab1 * ap1;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
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
    const T t1 = ab1 * in.p_lo[2] + exact_cross[0] - ab2 * in.p_lo[1];
    cross0 = t1;
    const T t2 = exact_cross[1] + in.p_lo[0] * ab2 - ab0 * in.p_lo[2];
    cross1 = t2;
    const T t3 = exact_cross[2] + ab0 * in.p_lo[1] - ab1 * in.p_lo[0];
    cross2 = t3;
    cross_cross = t3 * t3 + t1 * t1 + t2 * t2;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + bp1 * ap1;
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = (cross_cross * in.s + zeta2 * ab_ab) * in.s;
  const T h = cross2 * in.normal[2] + cross1 * in.normal[1] + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  T J_9;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))))), T(c - zeta2 - (T(123) / T(16)) * a - b));
  const T t5 = -a_minus_b * b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * a - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 127/16 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 4> M_flat;
    segment_moments_far_field<T>(3, 9, 0, a, b, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
    J_9 = M_flat[3];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(3, 9, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
    J_9 = M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / D;
    const T t9 = T(1) / r1;
    const T t10 = T(1) / r0;
    const T t11 = t9 * a_minus_b + t10 * b;
    J_3 = t8 * t11;
    const T t12 = t10 * t10;
    const T t13 = t9 * t9;
    const T t14 = t12 * t10 * b + t13 * t9 * a_minus_b + T(2) * t8 * t11 * a;
    J_5 = (T(1) / T(3)) * t14 * t8;
    const T t15 = t12 * t12;
    const T t16 = t13 * t13;
    const T t17 = T(3) * t15 * t10 * b + T(3) * t16 * t9 * a_minus_b + T(4) * t14 * t8 * a;
    J_7 = (T(1) / T(15)) * t17 * t8;
    const T t18 = t16 * t13;
    const T t19 = t15 * t12;
    J_9 = (T(1) / T(35)) * t8 * (T(5) * t18 * t9 * a_minus_b + T(5) * t19 * t10 * b + T(2) * t17 * t8 * a);
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t20 = t6 - T(2) * zeta2;
  const T t21 = max(T(D - T(2) * zeta2 * a), T(t5));
  if (t20 >= T(0) && t21 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t22 = -b;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(7, 9, alpha_h, a, zeta2, t22, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((r1 * b + r0 * a_minus_b) * alpha_h * zeta, alpha_h * alpha_h * r0 * r1 - zeta2 * a_minus_b * b) / zeta;
    const T t23 = T(1) / zeta2;
    const T H3 = (H1 - alpha_h * J_3) * t23;
    const T H5 = -(alpha_h * J_5 - H3) * t23;
    const T H7 = -(J_7 * alpha_h - H5) * t23;
    const T H9 = -t23 * (alpha_h * J_9 - H7);
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
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−10/2) dQ
/// Operations per edge: 80 +, 114 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 562 +, 1139 ×, 151 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i10_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
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
    const T t1 = in.p_lo[2] * ab1 + exact_cross[0] - ab2 * in.p_lo[1];
    cross0 = t1;
    const T t2 = ab2 * in.p_lo[0] + exact_cross[1] - ab0 * in.p_lo[2];
    cross1 = t2;
    cross2 = exact_cross[2] + ab0 * in.p_lo[1] - in.p_lo[0] * ab1;
    const T t3 = in.p_lo[0] * ab1 - exact_cross[2] - ab0 * in.p_lo[1];
    cross_cross = t3 * t3 + t2 * t2 + t1 * t1;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + bp0 * ap0 + bp1 * ap1;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = in.s * (zeta2 * ab_ab + cross_cross * in.s);
  const T h = in.normal[1] * cross1 + cross0 * in.normal[0] + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T c_minus_b = zeta2 + ap_bp * in.s;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))))), T(c - zeta2 - T(6) * a - b));
  const T t5 = -a_minus_b * b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * a - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 25/4 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 4> M_flat;
    segment_moments_far_field<T>(2, 8, 0, a, b, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(2, 8, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
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
    const T t12 = a_minus_b * t10 + b * t11 + J2 * a;
    const T t13 = T(1) / D;
    J_4 = (T(1) / T(2)) * t12 * t13;
    const T t14 = t11 * t11;
    const T t15 = t10 * t10;
    const T t16 = T(2) * b * t14 + T(3) * t12 * a * t13 + T(2) * a_minus_b * t15;
    J_6 = (T(1) / T(8)) * t13 * t16;
    const T t17 = t14 * t11;
    const T t18 = t15 * t10;
    J_8 = (T(1) / T(48)) * (T(5) * a * t13 * t16 + T(8) * b * t17 + T(8) * a_minus_b * t18) * t13;
  }
  const T alpha_h = h * in.s;
  T H_f;
  const T t19 = t6 - T(2) * zeta2;
  const T t20 = max(T(D - T(2) * zeta2 * a), T(t5));
  if (t19 >= T(0) && t20 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t21 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(8, 8, alpha_h, a, zeta2, t21, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t22 = T(1) / zeta2;
    const T H2 = t22 * (theta - alpha_h * J_2);
    const T H4 = -t22 * (alpha_h * J_4 - H2);
    const T H6 = t22 * (H4 - alpha_h * J_6);
    const T H8 = -t22 * (J_8 * alpha_h - H6);
    H_f = H8;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−10/2) dQ
/// Operations per edge: 83 +, 127 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 566 +, 1173 ×, 153 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i10_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_ap = ap2 * ab2 + ab1 * ap1 + ap0 * ab0;
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
    const T t1 = exact_cross[0] + ab1 * in.p_lo[2] - in.p_lo[1] * ab2;
    cross0 = t1;
    const T t2 = exact_cross[1] + in.p_lo[0] * ab2 - ab0 * in.p_lo[2];
    cross1 = t2;
    cross2 = exact_cross[2] + in.p_lo[1] * ab0 - ab1 * in.p_lo[0];
    const T t3 = ab1 * in.p_lo[0] - exact_cross[2] - in.p_lo[1] * ab0;
    cross_cross = t2 * t2 + t1 * t1 + t3 * t3;
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + bp1 * ap1 + ap0 * bp0;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + zeta2;
  const T D = (in.s * cross_cross + ab_ab * zeta2) * in.s;
  const T h = cross1 * in.normal[1] + in.normal[2] * cross2 + cross0 * in.normal[0];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + zeta2;
  const T c_minus_b = zeta2 + in.s * ap_bp;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  T J_10;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-b - T(2) * a))))), T(c - b - zeta2 - (T(153) / T(16)) * a));
  const T t5 = -b * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * a - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 157/16 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 5> M_flat;
    segment_moments_far_field<T>(2, 10, 0, a, b, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
    J_10 = M_flat[4];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(2, 10, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
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
    const T t10 = T(1) / c;
    const T t11 = T(1) / q1;
    const T t12 = b * t10 + a * J2 + a_minus_b * t11;
    const T t13 = T(1) / D;
    J_4 = (T(1) / T(2)) * t12 * t13;
    const T t14 = t11 * t11;
    const T t15 = t10 * t10;
    const T t16 = T(2) * a_minus_b * t14 + T(2) * b * t15 + T(3) * t12 * a * t13;
    J_6 = (T(1) / T(8)) * t16 * t13;
    const T t17 = t14 * t11;
    const T t18 = t15 * t10;
    const T t19 = T(8) * a_minus_b * t17 + T(8) * b * t18 + T(5) * t16 * a * t13;
    J_8 = (T(1) / T(48)) * t13 * t19;
    const T t20 = t14 * t14;
    const T t21 = t15 * t15;
    J_10 = (T(1) / T(384)) * (T(7) * a * t13 * t19 + T(48) * a_minus_b * t20 + T(48) * b * t21) * t13;
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t22 = t6 - T(2) * zeta2;
  const T t23 = max(T(D - T(2) * zeta2 * a), T(t5));
  if (t22 >= T(0) && t23 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t24 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(10, 10, alpha_h, a, zeta2, t24, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t25 = T(1) / zeta2;
    const T H2 = -t25 * (alpha_h * J_2 - theta);
    const T H4 = -(J_4 * alpha_h - H2) * t25;
    const T H6 = -t25 * (J_6 * alpha_h - H4);
    const T H8 = (H6 - alpha_h * J_8) * t25;
    const T H10 = -t25 * (alpha_h * J_10 - H8);
    H_g = H10;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_10;
}

/// The terms of one edge for f and ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−10/2) dQ
/// Operations per edge: 83 +, 127 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 584 +, 1192 ×, 153 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i10_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
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
    const T t1 = in.p_lo[2] * ab1 + exact_cross[0] - ab2 * in.p_lo[1];
    cross0 = t1;
    const T t2 = in.p_lo[0] * ab2 + exact_cross[1] - ab0 * in.p_lo[2];
    cross1 = t2;
    const T t3 = exact_cross[2] + ab0 * in.p_lo[1] - in.p_lo[0] * ab1;
    cross2 = t3;
    cross_cross = t2 * t2 + t3 * t3 + t1 * t1;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = bp1 * ab1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + bp1 * ap1;
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = in.s * (cross_cross * in.s + ab_ab * zeta2);
  const T h = in.normal[0] * cross0 + cross2 * in.normal[2] + in.normal[1] * cross1;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T c_minus_b = zeta2 + ap_bp * in.s;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  T J_10;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))))), T(c - zeta2 - (T(153) / T(16)) * a - b));
  const T t5 = -b * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * a - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 157/16 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 5> M_flat;
    segment_moments_far_field<T>(2, 10, 0, a, b, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
    J_10 = M_flat[4];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(2, 10, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
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
    const T t11 = T(1) / c;
    const T t12 = T(1) / q1;
    const T t13 = t11 * b + a * J2 + t12 * a_minus_b;
    J_4 = (T(1) / T(2)) * t10 * t13;
    const T t14 = t12 * t12;
    const T t15 = t11 * t11;
    const T t16 = T(3) * t10 * a * t13 + T(2) * t14 * a_minus_b + T(2) * t15 * b;
    J_6 = (T(1) / T(8)) * t10 * t16;
    const T t17 = t14 * t12;
    const T t18 = t15 * t11;
    const T t19 = T(8) * t17 * a_minus_b + T(5) * t10 * a * t16 + T(8) * t18 * b;
    J_8 = (T(1) / T(48)) * t10 * t19;
    const T t20 = t15 * t15;
    const T t21 = t14 * t14;
    J_10 = (T(1) / T(384)) * (T(48) * t20 * b + T(7) * t10 * a * t19 + T(48) * t21 * a_minus_b) * t10;
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t22 = t6 - T(2) * zeta2;
  const T t23 = max(T(D - T(2) * zeta2 * a), T(t5));
  if (t22 >= T(0) && t23 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t24 = -b;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(8, 10, alpha_h, a, zeta2, t24, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t25 = T(1) / zeta2;
    const T H2 = t25 * (theta - J_2 * alpha_h);
    const T H4 = -t25 * (alpha_h * J_4 - H2);
    const T H6 = t25 * (H4 - alpha_h * J_6);
    const T H8 = -t25 * (J_8 * alpha_h - H6);
    const T H10 = -(alpha_h * J_10 - H8) * t25;
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
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−11/2) dQ
/// Operations per edge: 82 +, 134 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 563 +, 1241 ×, 151 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i11_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
    const T t1 = exact_cross[1] + in.p_lo[0] * ab2 - ab0 * in.p_lo[2];
    cross1 = t1;
    cross2 = exact_cross[2] + in.p_lo[1] * ab0 - ab1 * in.p_lo[0];
    const T t2 = in.p_lo[1] * ab2 - ab1 * in.p_lo[2] - exact_cross[0];
    const T t3 = ab1 * in.p_lo[0] - exact_cross[2] - in.p_lo[1] * ab0;
    cross_cross = t1 * t1 + t2 * t2 + t3 * t3;
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + bp2 * ab2 + ab0 * bp0;
  const T ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + zeta2;
  const T D = in.s * (zeta2 * ab_ab + in.s * cross_cross);
  const T h = in.normal[2] * cross2 + in.normal[0] * cross0 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + in.s * bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  T J_9;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-b - T(2) * a))))), T(c - b - zeta2 - (T(123) / T(16)) * a));
  const T t5 = -b * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * a - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 127/16 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 4> M_flat;
    segment_moments_far_field<T>(3, 9, 0, a, b, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
    J_9 = M_flat[3];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(3, 9, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
    J_9 = M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t8 = T(1) / r0;
    const T t9 = T(1) / r1;
    const T t10 = b * t8 + t9 * a_minus_b;
    const T t11 = T(1) / D;
    J_3 = t10 * t11;
    const T t12 = t8 * t8;
    const T t13 = t9 * t9;
    const T t14 = b * t12 * t8 + T(2) * t10 * t11 * a + t13 * t9 * a_minus_b;
    J_5 = (T(1) / T(3)) * t14 * t11;
    const T t15 = t13 * t13;
    const T t16 = t12 * t12;
    const T t17 = T(3) * t15 * t9 * a_minus_b + T(3) * b * t16 * t8 + T(4) * t14 * t11 * a;
    J_7 = (T(1) / T(15)) * t17 * t11;
    const T t18 = t16 * t12;
    const T t19 = t15 * t13;
    J_9 = (T(1) / T(35)) * (T(2) * t17 * t11 * a + T(5) * b * t18 * t8 + T(5) * t19 * t9 * a_minus_b) * t11;
  }
  const T alpha_h = h * in.s;
  T H_f;
  const T t20 = t6 - T(2) * zeta2;
  const T t21 = max(T(D - T(2) * zeta2 * a), T(t5));
  if (t20 >= T(0) && t21 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t22 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(9, 9, alpha_h, a, zeta2, t22, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(alpha_h * zeta * (r0 * a_minus_b + b * r1), alpha_h * alpha_h * r0 * r1 - b * zeta2 * a_minus_b) / zeta;
    const T t23 = T(1) / zeta2;
    const T H3 = -t23 * (alpha_h * J_3 - H1);
    const T H5 = -t23 * (alpha_h * J_5 - H3);
    const T H7 = t23 * (H5 - J_7 * alpha_h);
    const T H9 = -(alpha_h * J_9 - H7) * t23;
    H_f = H9;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−11/2) dQ
/// Operations per edge: 85 +, 149 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 563 +, 1291 ×, 153 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i11_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_ap = ap2 * ab2 + ab1 * ap1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
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
    const T t1 = ab1 * in.p_lo[2] + exact_cross[0] - ab2 * in.p_lo[1];
    cross0 = t1;
    const T t2 = exact_cross[1] + in.p_lo[0] * ab2 - ab0 * in.p_lo[2];
    cross1 = t2;
    const T t3 = ab0 * in.p_lo[1] + exact_cross[2] - ab1 * in.p_lo[0];
    cross2 = t3;
    cross_cross = t1 * t1 + t2 * t2 + t3 * t3;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap0 * bp0 + bp1 * ap1 + ap2 * bp2;
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = (cross_cross * in.s + zeta2 * ab_ab) * in.s;
  const T h = cross1 * in.normal[1] + cross2 * in.normal[2] + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  T J_9;
  T J_11;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))))), T(c - zeta2 - (T(93) / T(8)) * a - b));
  const T t5 = -a_minus_b * b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * a - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 95/8 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 5> M_flat;
    segment_moments_far_field<T>(3, 11, 0, a, b, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
    J_9 = M_flat[3];
    J_11 = M_flat[4];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(3, 11, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
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
    const T t11 = a_minus_b * t9 + t10 * b;
    J_3 = t8 * t11;
    const T t12 = t9 * t9;
    const T t13 = t10 * t10;
    const T t14 = T(2) * t8 * a * t11 + a_minus_b * t12 * t9 + t13 * t10 * b;
    J_5 = (T(1) / T(3)) * t14 * t8;
    const T t15 = t13 * t13;
    const T t16 = t12 * t12;
    const T t17 = T(4) * t14 * t8 * a + T(3) * t15 * t10 * b + T(3) * a_minus_b * t16 * t9;
    J_7 = (T(1) / T(15)) * t8 * t17;
    const T t18 = t16 * t12;
    const T t19 = t15 * t13;
    const T t20 = T(5) * a_minus_b * t18 * t9 + T(2) * t8 * a * t17 + T(5) * t19 * t10 * b;
    J_9 = (T(1) / T(35)) * t20 * t8;
    const T t21 = t15 * t15;
    const T t22 = t16 * t16;
    J_11 = (T(1) / T(315)) * (T(35) * t21 * t10 * b + T(8) * t20 * t8 * a + T(35) * a_minus_b * t22 * t9) * t8;
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t23 = t6 - T(2) * zeta2;
  const T t24 = max(T(D - T(2) * zeta2 * a), T(t5));
  if (t23 >= T(0) && t24 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t25 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(11, 11, alpha_h, a, zeta2, t25, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * alpha_h * (a_minus_b * r0 + b * r1), alpha_h * alpha_h * r0 * r1 - a_minus_b * zeta2 * b) / zeta;
    const T t26 = T(1) / zeta2;
    const T H3 = t26 * (H1 - alpha_h * J_3);
    const T H5 = -t26 * (alpha_h * J_5 - H3);
    const T H7 = -t26 * (alpha_h * J_7 - H5);
    const T H9 = t26 * (H7 - alpha_h * J_9);
    const T H11 = -t26 * (alpha_h * J_11 - H9);
    H_g = H11;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_11;
}

/// The terms of one edge for f and ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−11/2) dQ
/// Operations per edge: 85 +, 149 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 589 +, 1298 ×, 153 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i11_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T bp1 = bp_hi1 + in.p_lo[1];
  const T ab2 = in.b[2] - in.a[2];
  const T ap_hi2 = in.p[2] - in.a[2];
  const T ap2 = in.p_lo[2] + ap_hi2;
  const T bp_hi2 = in.p[2] - in.b[2];
  const T bp2 = bp_hi2 + in.p_lo[2];
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T plain_cross0 = ap2 * ab1 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
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
    cross0 = in.p_lo[2] * ab1 + exact_cross[0] - ab2 * in.p_lo[1];
    cross1 = exact_cross[1] + in.p_lo[0] * ab2 - ab0 * in.p_lo[2];
    cross2 = ab0 * in.p_lo[1] + exact_cross[2] - in.p_lo[0] * ab1;
    const T t1 = in.p_lo[0] * ab1 - ab0 * in.p_lo[1] - exact_cross[2];
    const T t2 = ab0 * in.p_lo[2] - exact_cross[1] - in.p_lo[0] * ab2;
    const T t3 = ab2 * in.p_lo[1] - in.p_lo[2] * ab1 - exact_cross[0];
    cross_cross = t1 * t1 + t2 * t2 + t3 * t3;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = bp2 * ap2 + bp0 * ap0 + ap1 * bp1;
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + zeta2;
  const T D = in.s * (zeta2 * ab_ab + cross_cross * in.s);
  const T h = in.normal[2] * cross2 + cross0 * in.normal[0] + in.normal[1] * cross1;
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
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))))), T(c - (T(93) / T(8)) * a - b - zeta2));
  const T t5 = -b * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * a * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 95/8 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 5> M_flat;
    segment_moments_far_field<T>(3, 11, 0, a, b, c, c - zeta2, M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
    J_9 = M_flat[3];
    J_11 = M_flat[4];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(3, 11, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
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
    const T t11 = t9 * a_minus_b + t10 * b;
    J_3 = t8 * t11;
    const T t12 = t9 * t9;
    const T t13 = t10 * t10;
    const T t14 = t9 * a_minus_b * t12 + T(2) * a * t8 * t11 + t10 * b * t13;
    J_5 = (T(1) / T(3)) * t14 * t8;
    const T t15 = t13 * t13;
    const T t16 = t12 * t12;
    const T t17 = T(3) * t10 * b * t15 + T(4) * t14 * a * t8 + T(3) * t9 * a_minus_b * t16;
    J_7 = (T(1) / T(15)) * t8 * t17;
    const T t18 = t15 * t13;
    const T t19 = t16 * t12;
    const T t20 = T(5) * t10 * b * t18 + T(2) * a * t8 * t17 + T(5) * t9 * a_minus_b * t19;
    J_9 = (T(1) / T(35)) * t8 * t20;
    const T t21 = t15 * t15;
    const T t22 = t16 * t16;
    J_11 = (T(1) / T(315)) * t8 * (T(8) * a * t8 * t20 + T(35) * t10 * b * t21 + T(35) * t9 * a_minus_b * t22);
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t23 = t6 - T(2) * zeta2;
  const T t24 = max(T(D - T(2) * a * zeta2), T(t5));
  if (t23 >= T(0) && t24 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t25 = -b;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(9, 11, alpha_h, a, zeta2, t25, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * (b * r1 + r0 * a_minus_b) * alpha_h, r0 * r1 * alpha_h * alpha_h - b * a_minus_b * zeta2) / zeta;
    const T t26 = T(1) / zeta2;
    const T H3 = -(J_3 * alpha_h - H1) * t26;
    const T H5 = -t26 * (J_5 * alpha_h - H3);
    const T H7 = (H5 - alpha_h * J_7) * t26;
    const T H9 = -(alpha_h * J_9 - H7) * t26;
    const T H11 = -(J_11 * alpha_h - H9) * t26;
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
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−12/2) dQ
/// Operations per edge: 83 +, 127 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 566 +, 1173 ×, 153 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i12_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_ap = ap2 * ab2 + ab1 * ap1 + ap0 * ab0;
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
    cross0 = exact_cross[0] + ab1 * in.p_lo[2] - in.p_lo[1] * ab2;
    const T t1 = exact_cross[1] + in.p_lo[0] * ab2 - in.p_lo[2] * ab0;
    cross1 = t1;
    const T t2 = in.p_lo[1] * ab0 + exact_cross[2] - ab1 * in.p_lo[0];
    cross2 = t2;
    const T t3 = in.p_lo[1] * ab2 - exact_cross[0] - ab1 * in.p_lo[2];
    cross_cross = t1 * t1 + t2 * t2 + t3 * t3;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = bp1 * ap1 + ap2 * bp2 + ap0 * bp0;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + zeta2;
  const T D = in.s * (ab_ab * zeta2 + in.s * cross_cross);
  const T h = cross2 * in.normal[2] + cross1 * in.normal[1] + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = zeta2 + in.s * bp_bp;
  const T c_minus_b = zeta2 + in.s * ap_bp;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  T J_10;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-b - T(2) * a))))), T(c - b - zeta2 - (T(153) / T(16)) * a));
  const T t5 = -b * a_minus_b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * a - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 157/16 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 5> M_flat;
    segment_moments_far_field<T>(2, 10, 0, a, b, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
    J_10 = M_flat[4];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 5> M_beyond;
    segment_moments_beyond_end<T>(2, 10, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
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
    const T t10 = T(1) / q1;
    const T t11 = T(1) / c;
    const T t12 = a_minus_b * t10 + b * t11 + a * J2;
    const T t13 = T(1) / D;
    J_4 = (T(1) / T(2)) * t12 * t13;
    const T t14 = t11 * t11;
    const T t15 = t10 * t10;
    const T t16 = T(2) * b * t14 + T(3) * t12 * t13 * a + T(2) * a_minus_b * t15;
    J_6 = (T(1) / T(8)) * t16 * t13;
    const T t17 = t14 * t11;
    const T t18 = t15 * t10;
    const T t19 = T(5) * t16 * t13 * a + T(8) * b * t17 + T(8) * a_minus_b * t18;
    J_8 = (T(1) / T(48)) * t19 * t13;
    const T t20 = t15 * t15;
    const T t21 = t14 * t14;
    J_10 = (T(1) / T(384)) * t13 * (T(48) * a_minus_b * t20 + T(7) * t19 * t13 * a + T(48) * b * t21);
  }
  const T alpha_h = h * in.s;
  T H_f;
  const T t22 = t6 - T(2) * zeta2;
  const T t23 = max(T(D - T(2) * zeta2 * a), T(t5));
  if (t22 >= T(0) && t23 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t24 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(10, 10, alpha_h, a, zeta2, t24, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t25 = T(1) / zeta2;
    const T H2 = t25 * (theta - J_2 * alpha_h);
    const T H4 = -t25 * (alpha_h * J_4 - H2);
    const T H6 = -(J_6 * alpha_h - H4) * t25;
    const T H8 = -t25 * (J_8 * alpha_h - H6);
    const T H10 = -(alpha_h * J_10 - H8) * t25;
    H_f = H10;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−12/2) dQ
/// Operations per edge: 86 +, 140 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 568 +, 1206 ×, 155 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i12_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
    const T t1 = in.p_lo[2] * ab1 + exact_cross[0] - ab2 * in.p_lo[1];
    cross0 = t1;
    const T t2 = in.p_lo[0] * ab2 + exact_cross[1] - ab0 * in.p_lo[2];
    cross1 = t2;
    const T t3 = ab0 * in.p_lo[1] + exact_cross[2] - in.p_lo[0] * ab1;
    cross2 = t3;
    cross_cross = t1 * t1 + t3 * t3 + t2 * t2;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + bp1 * ap1 + bp0 * ap0;
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = (zeta2 * ab_ab + cross_cross * in.s) * in.s;
  const T h = in.normal[0] * cross0 + in.normal[1] * cross1 + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T c_minus_b = zeta2 + ap_bp * in.s;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  T J_10;
  T J_12;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))))), T(c - zeta2 - (T(221) / T(16)) * a - b));
  const T t5 = -a_minus_b * b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * a * t6 - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 225/16 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 6> M_flat;
    segment_moments_far_field<T>(2, 12, 0, a, b, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
    J_10 = M_flat[4];
    J_12 = M_flat[5];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(2, 12, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
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
    const T t13 = a * J2 + b * t11 + a_minus_b * t12;
    J_4 = (T(1) / T(2)) * t10 * t13;
    const T t14 = t12 * t12;
    const T t15 = t11 * t11;
    const T t16 = T(2) * a_minus_b * t14 + T(3) * t10 * a * t13 + T(2) * b * t15;
    J_6 = (T(1) / T(8)) * t16 * t10;
    const T t17 = t14 * t12;
    const T t18 = t15 * t11;
    const T t19 = T(8) * a_minus_b * t17 + T(8) * b * t18 + T(5) * t16 * t10 * a;
    J_8 = (T(1) / T(48)) * t10 * t19;
    const T t20 = t15 * t15;
    const T t21 = t14 * t14;
    const T t22 = T(48) * b * t20 + T(48) * a_minus_b * t21 + T(7) * t10 * a * t19;
    J_10 = (T(1) / T(384)) * t22 * t10;
    const T t23 = t21 * t12;
    const T t24 = t20 * t11;
    J_12 = (T(1) / T(1280)) * t10 * (T(128) * a_minus_b * t23 + T(128) * b * t24 + T(3) * t22 * t10 * a);
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t25 = t6 - T(2) * zeta2;
  const T t26 = max(T(D - T(2) * zeta2 * a), T(t5));
  if (t25 >= T(0) && t26 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t27 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(12, 12, alpha_h, a, zeta2, t27, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t28 = T(1) / zeta2;
    const T H2 = -t28 * (J_2 * alpha_h - theta);
    const T H4 = -t28 * (alpha_h * J_4 - H2);
    const T H6 = t28 * (H4 - alpha_h * J_6);
    const T H8 = -t28 * (J_8 * alpha_h - H6);
    const T H10 = t28 * (H8 - alpha_h * J_10);
    const T H12 = t28 * (H10 - alpha_h * J_12);
    H_g = H12;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_12;
}

/// The terms of one edge for f and ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−12/2) dQ
/// Operations per edge: 86 +, 140 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 592 +, 1231 ×, 155 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
template <class T>
void polygon_edge_cauchy_i12_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ab_ap = ab0 * ap0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
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
    cross0 = exact_cross[0] + in.p_lo[2] * ab1 - ab2 * in.p_lo[1];
    const T t1 = in.p_lo[0] * ab2 + exact_cross[1] - ab0 * in.p_lo[2];
    cross1 = t1;
    cross2 = exact_cross[2] + ab0 * in.p_lo[1] - in.p_lo[0] * ab1;
    const T t2 = in.p_lo[0] * ab1 - exact_cross[2] - ab0 * in.p_lo[1];
    const T t3 = ab2 * in.p_lo[1] - exact_cross[0] - in.p_lo[2] * ab1;
    cross_cross = t2 * t2 + t1 * t1 + t3 * t3;
  }
  const T bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  const T ab_bp = bp1 * ab1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + bp1 * ap1 + bp0 * ap0;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + zeta2;
  const T D = (zeta2 * ab_ab + cross_cross * in.s) * in.s;
  const T h = in.normal[0] * cross0 + in.normal[1] * cross1 + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + zeta2;
  const T c_minus_b = ap_bp * in.s + zeta2;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  T J_10;
  T J_12;
  const T t4 = max(T(max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))))), T(c - (T(221) / T(16)) * a - b - zeta2));
  const T t5 = -a_minus_b * b;
  const T t6 = min(T(c), T(q1));
  const T t7 = (T(7) / T(10)) * t6 * a - D;
  if (t4 >= T(0)) {
    // P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the midpoint (|P − M|² ≥ 225/16 |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, or segment_moments_gauss<T, 20>)
    std::array<T, 6> M_flat;
    segment_moments_far_field<T>(2, 12, 0, a, b, c, c - zeta2, M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
    J_10 = M_flat[4];
    J_12 = M_flat[5];
  } else if (t5 >= T(0) && t7 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 6> M_beyond;
    segment_moments_beyond_end<T>(2, 12, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
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
    const T J2 = atan2(t8, c_minus_b) * t9;
    J_2 = J2;
    const T t10 = T(1) / D;
    const T t11 = T(1) / q1;
    const T t12 = T(1) / c;
    const T t13 = a * J2 + a_minus_b * t11 + t12 * b;
    J_4 = (T(1) / T(2)) * t10 * t13;
    const T t14 = t12 * t12;
    const T t15 = t11 * t11;
    const T t16 = T(2) * t14 * b + T(2) * a_minus_b * t15 + T(3) * t10 * a * t13;
    J_6 = (T(1) / T(8)) * t10 * t16;
    const T t17 = t14 * t12;
    const T t18 = t15 * t11;
    const T t19 = T(8) * t17 * b + T(8) * a_minus_b * t18 + T(5) * t10 * a * t16;
    J_8 = (T(1) / T(48)) * t19 * t10;
    const T t20 = t14 * t14;
    const T t21 = t15 * t15;
    const T t22 = T(7) * t19 * t10 * a + T(48) * t20 * b + T(48) * a_minus_b * t21;
    J_10 = (T(1) / T(384)) * t10 * t22;
    const T t23 = t20 * t12;
    const T t24 = t21 * t11;
    J_12 = (T(1) / T(1280)) * t10 * (T(3) * t10 * a * t22 + T(128) * t23 * b + T(128) * a_minus_b * t24);
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t25 = t6 - T(2) * zeta2;
  const T t26 = max(T(D - T(2) * a * zeta2), T(t5));
  if (t25 >= T(0) && t26 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t27 = -b;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(10, 12, alpha_h, a, zeta2, t27, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t28 = T(1) / zeta2;
    const T H2 = -t28 * (alpha_h * J_2 - theta);
    const T H4 = -(alpha_h * J_4 - H2) * t28;
    const T H6 = (H4 - alpha_h * J_6) * t28;
    const T H8 = -(alpha_h * J_8 - H6) * t28;
    const T H10 = -(alpha_h * J_10 - H8) * t28;
    const T H12 = -(alpha_h * J_12 - H10) * t28;
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
