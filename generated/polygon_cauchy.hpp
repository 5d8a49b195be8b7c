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

#include <skelconv/exact_cross.hpp>
#include <skelconv/gauss_moments.hpp>
#include <skelconv/polygon_angle_integrals.hpp>
#include <skelconv/polygon_edge_input.hpp>
#include <skelconv/segment_input.hpp>
#include <skelconv/stable_recurrence.hpp>

namespace skelconv::generated {

/// The terms of one edge for f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−3/2) dQ
/// Operations per edge: 38 +, 59 ×, 1 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 163 +, 199 ×, 23 /, 22 sqrt, 3 atan, 0 log/asinh, 20 other.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ap0 * ab1;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + ap0 * bp0 + bp2 * ap2;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + zeta2;
  const T D = in.s * (zeta2 * ab_ab + in.s * cross_cross);
  const T h = cross1 * in.normal[1] + in.normal[2] * cross2 + cross0 * in.normal[0];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  const T alpha_h = h * in.s;
  T H_f;
  const T t1 = min(T(c), T(q1)) - T(2) * zeta2;
  const T t2 = max(T(D - T(2) * zeta2 * a), T(-b * a_minus_b));
  if (t1 >= T(0) && t2 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(1, 1, alpha_h, a, zeta2, -b, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((r0 * a_minus_b + b * r1) * zeta * alpha_h, r0 * alpha_h * alpha_h * r1 - b * zeta2 * a_minus_b) / zeta;
    H_f = H1;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−3/2) dQ
/// Operations per edge: 51 +, 73 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 519 +, 1059 ×, 145 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = zeta2 + in.s * ap_ap;
  const T D = in.s * (in.s * cross_cross + zeta2 * ab_ab);
  const T h = cross1 * in.normal[1] + in.normal[0] * cross0 + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + in.s * bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))));
  const T t2 = -a_minus_b * b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * t3 * a - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
  } else if (t2 >= T(0) && t4 >= T(0)) {
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
  const T t5 = t3 - T(2) * zeta2;
  const T t6 = max(T(D - T(2) * zeta2 * a), T(t2));
  if (t5 >= T(0) && t6 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t7 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(3, 3, alpha_h, a, zeta2, t7, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * alpha_h * (r1 * b + r0 * a_minus_b), alpha_h * alpha_h * r0 * r1 - zeta2 * a_minus_b * b) / zeta;
    const T H3 = -(alpha_h * J_3 - H1) / zeta2;
    H_g = H3;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_3;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−3/2) dQ
/// Operations per edge: 51 +, 73 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 539 +, 1060 ×, 145 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = (cross_cross * in.s + zeta2 * ab_ab) * in.s;
  const T h = in.normal[1] * cross1 + in.normal[0] * cross0 + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))));
  const T t2 = -a_minus_b * b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * a * t3 - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
  } else if (t2 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(3, 3, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    J_3 = (a_minus_b / r1 + b / r0) / D;
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t5 = t3 - T(2) * zeta2;
  const T t6 = max(T(D - T(2) * zeta2 * a), T(t2));
  if (t5 >= T(0) && t6 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t7 = -b;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(1, 3, alpha_h, a, zeta2, t7, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(alpha_h * (r1 * b + r0 * a_minus_b) * zeta, alpha_h * alpha_h * r0 * r1 - zeta2 * a_minus_b * b) / zeta;
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

/// The terms of one edge for f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−4/2) dQ
/// Operations per edge: 49 +, 65 ×, 2 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 520 +, 1018 ×, 145 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ap2 * ab1 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + zeta2;
  const T D = in.s * (zeta2 * ab_ab + cross_cross * in.s);
  const T h = in.normal[2] * cross2 + in.normal[1] * cross1 + cross0 * in.normal[0];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + zeta2;
  const T c_minus_b = in.s * ap_bp + zeta2;
  T J_2;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))));
  const T t2 = -a_minus_b * b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * t3 * a - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(2, 2, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
  } else if (t2 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 1> M_beyond;
    segment_moments_beyond_end<T>(2, 2, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = sqrt(D);
    const T J2 = atan2(t5, c_minus_b) / t5;
    J_2 = J2;
  }
  const T alpha_h = in.s * h;
  T H_f;
  const T t6 = t3 - T(2) * zeta2;
  const T t7 = max(T(D - T(2) * a * zeta2), T(t2));
  if (t6 >= T(0) && t7 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t8 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(2, 2, alpha_h, a, zeta2, t8, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T H2 = -(J_2 * alpha_h - theta) / zeta2;
    H_f = H2;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−4/2) dQ
/// Operations per edge: 52 +, 72 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 524 +, 1050 ×, 147 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T plain_cross0 = ap2 * ab1 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = zeta2 + ap_ap * in.s;
  const T D = in.s * (zeta2 * ab_ab + in.s * cross_cross);
  const T h = in.normal[2] * cross2 + cross1 * in.normal[1] + cross0 * in.normal[0];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + zeta2;
  const T c_minus_b = in.s * ap_bp + zeta2;
  T J_2;
  T J_4;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-b - T(2) * a))));
  const T t2 = -b * a_minus_b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * t3 * a - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
  } else if (t2 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(2, 4, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = sqrt(D);
    const T t6 = T(1) / t5;
    const T J2 = atan2(t5, c_minus_b) * t6;
    J_2 = J2;
    const T t7 = T(1) / D;
    J_4 = (T(1) / T(2)) * (a_minus_b / q1 + J2 * a + b / c) * t7;
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t8 = t3 - T(2) * zeta2;
  const T t9 = max(T(D - T(2) * zeta2 * a), T(t2));
  if (t8 >= T(0) && t9 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t10 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(4, 4, alpha_h, a, zeta2, t10, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t11 = T(1) / zeta2;
    const T H2 = (theta - J_2 * alpha_h) * t11;
    const T H4 = -t11 * (J_4 * alpha_h - H2);
    H_g = H4;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_4;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−4/2) dQ
/// Operations per edge: 52 +, 72 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 544 +, 1071 ×, 147 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ap2 * ab1 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = in.s * (cross_cross * in.s + zeta2 * ab_ab);
  const T h = in.normal[2] * cross2 + cross0 * in.normal[0] + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + zeta2;
  const T c_minus_b = zeta2 + in.s * ap_bp;
  T J_2;
  T J_4;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))));
  const T t2 = -b * a_minus_b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * a * t3 - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
  } else if (t2 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(2, 4, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = sqrt(D);
    const T t6 = T(1) / t5;
    const T J2 = t6 * atan2(t5, c_minus_b);
    J_2 = J2;
    const T t7 = T(1) / D;
    J_4 = (T(1) / T(2)) * t7 * (a * J2 + a_minus_b / q1 + b / c);
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t8 = t3 - T(2) * zeta2;
  const T t9 = max(T(D - T(2) * a * zeta2), T(t2));
  if (t8 >= T(0) && t9 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t10 = -b;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(2, 4, alpha_h, a, zeta2, t10, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t11 = T(1) / zeta2;
    const T H2 = t11 * (theta - alpha_h * J_2);
    const T H4 = (H2 - alpha_h * J_4) * t11;
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
/// Operations per edge: 51 +, 73 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 519 +, 1059 ×, 145 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + zeta2;
  const T D = in.s * (ab_ab * zeta2 + in.s * cross_cross);
  const T h = cross1 * in.normal[1] + in.normal[0] * cross0 + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-b - T(2) * a))));
  const T t2 = -b * a_minus_b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * t3 * a - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 1> M_flat;
    segment_moments_gauss<T, 20>(3, 3, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
  } else if (t2 >= T(0) && t4 >= T(0)) {
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
  const T t5 = t3 - T(2) * zeta2;
  const T t6 = max(T(D - T(2) * zeta2 * a), T(t2));
  if (t5 >= T(0) && t6 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t7 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(3, 3, alpha_h, a, zeta2, t7, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * alpha_h * (b * r1 + r0 * a_minus_b), alpha_h * alpha_h * r0 * r1 - b * zeta2 * a_minus_b) / zeta;
    const T H3 = -(alpha_h * J_3 - H1) / zeta2;
    H_f = H3;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−5/2) dQ
/// Operations per edge: 54 +, 86 ×, 7 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 523 +, 1111 ×, 147 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + bp2 * ap2;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + zeta2;
  const T D = in.s * (zeta2 * ab_ab + in.s * cross_cross);
  const T h = cross0 * in.normal[0] + cross1 * in.normal[1] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-b - T(2) * a))));
  const T t2 = -b * a_minus_b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * t3 * a - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
  } else if (t2 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(3, 5, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = T(1) / D;
    const T t6 = T(1) / r0;
    const T t7 = T(1) / r1;
    const T t8 = t6 * b + t7 * a_minus_b;
    J_3 = t5 * t8;
    J_5 = (T(1) / T(3)) * t5 * (t6 * b / c + t7 * a_minus_b / q1 + T(2) * t5 * a * t8);
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t9 = t3 - T(2) * zeta2;
  const T t10 = max(T(D - T(2) * zeta2 * a), T(t2));
  if (t9 >= T(0) && t10 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t11 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(5, 5, alpha_h, a, zeta2, t11, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((b * r1 + r0 * a_minus_b) * alpha_h * zeta, r0 * r1 * alpha_h * alpha_h - b * a_minus_b * zeta2) / zeta;
    const T t12 = T(1) / zeta2;
    const T H3 = -(alpha_h * J_3 - H1) * t12;
    const T H5 = t12 * (H3 - J_5 * alpha_h);
    H_g = H5;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_5;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−5/2) dQ
/// Operations per edge: 54 +, 86 ×, 7 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 543 +, 1112 ×, 147 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + zeta2;
  const T D = (zeta2 * ab_ab + cross_cross * in.s) * in.s;
  const T h = cross0 * in.normal[0] + in.normal[1] * cross1 + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))));
  const T t2 = -b * a_minus_b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * a * t3 - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
  } else if (t2 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(3, 5, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = T(1) / D;
    const T t6 = T(1) / r1;
    const T t7 = T(1) / r0;
    const T t8 = t6 * a_minus_b + t7 * b;
    J_3 = t5 * t8;
    J_5 = (T(1) / T(3)) * t5 * (t7 * b / c + t6 * a_minus_b / q1 + T(2) * t5 * a * t8);
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t9 = t3 - T(2) * zeta2;
  const T t10 = max(T(D - T(2) * a * zeta2), T(t2));
  if (t9 >= T(0) && t10 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t11 = -b;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(3, 5, alpha_h, a, zeta2, t11, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(alpha_h * (r0 * a_minus_b + b * r1) * zeta, alpha_h * alpha_h * r0 * r1 - b * a_minus_b * zeta2) / zeta;
    const T t12 = T(1) / zeta2;
    const T H3 = -t12 * (alpha_h * J_3 - H1);
    const T H5 = (H3 - alpha_h * J_5) * t12;
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
/// Operations per edge: 52 +, 72 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 524 +, 1050 ×, 147 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = ap_ap * in.s + zeta2;
  const T D = (ab_ab * zeta2 + cross_cross * in.s) * in.s;
  const T h = in.normal[1] * cross1 + cross2 * in.normal[2] + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + zeta2;
  const T c_minus_b = ap_bp * in.s + zeta2;
  T J_2;
  T J_4;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))));
  const T t2 = -b * a_minus_b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * a * t3 - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(2, 4, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
  } else if (t2 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(2, 4, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = sqrt(D);
    const T t6 = T(1) / t5;
    const T J2 = t6 * atan2(t5, c_minus_b);
    J_2 = J2;
    const T t7 = T(1) / D;
    J_4 = (T(1) / T(2)) * t7 * (b / c + a * J2 + a_minus_b / q1);
  }
  const T alpha_h = h * in.s;
  T H_f;
  const T t8 = t3 - T(2) * zeta2;
  const T t9 = max(T(D - T(2) * a * zeta2), T(t2));
  if (t8 >= T(0) && t9 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t10 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(4, 4, alpha_h, a, zeta2, t10, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t11 = T(1) / zeta2;
    const T H2 = -(J_2 * alpha_h - theta) * t11;
    const T H4 = (H2 - alpha_h * J_4) * t11;
    H_f = H4;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−6/2) dQ
/// Operations per edge: 55 +, 87 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 528 +, 1083 ×, 149 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = (zeta2 * ab_ab + cross_cross * in.s) * in.s;
  const T h = cross2 * in.normal[2] + cross0 * in.normal[0] + in.normal[1] * cross1;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = zeta2 + bp_bp * in.s;
  const T c_minus_b = zeta2 + ap_bp * in.s;
  T J_2;
  T J_4;
  T J_6;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))));
  const T t2 = -a_minus_b * b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * a * t3 - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(2, 6, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
  } else if (t2 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(2, 6, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = sqrt(D);
    const T t6 = T(1) / t5;
    const T J2 = atan2(t5, c_minus_b) * t6;
    J_2 = J2;
    const T t7 = T(1) / D;
    const T t8 = T(1) / q1;
    const T t9 = T(1) / c;
    const T t10 = a_minus_b * t8 + a * J2 + t9 * b;
    J_4 = (T(1) / T(2)) * t7 * t10;
    const T t11 = t9 * t9;
    const T t12 = t8 * t8;
    J_6 = (T(1) / T(8)) * (T(2) * t11 * b + T(3) * t7 * a * t10 + T(2) * a_minus_b * t12) * t7;
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t13 = t3 - T(2) * zeta2;
  const T t14 = max(T(D - T(2) * zeta2 * a), T(t2));
  if (t13 >= T(0) && t14 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t15 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(6, 6, alpha_h, a, zeta2, t15, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t16 = T(1) / zeta2;
    const T H2 = -(J_2 * alpha_h - theta) * t16;
    const T H4 = t16 * (H2 - alpha_h * J_4);
    const T H6 = -t16 * (alpha_h * J_6 - H4);
    H_g = H6;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_6;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−6/2) dQ
/// Operations per edge: 55 +, 87 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 548 +, 1104 ×, 149 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + zeta2;
  const T D = in.s * (in.s * cross_cross + ab_ab * zeta2);
  const T h = in.normal[0] * cross0 + cross1 * in.normal[1] + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = zeta2 + in.s * bp_bp;
  const T c_minus_b = zeta2 + in.s * ap_bp;
  T J_2;
  T J_4;
  T J_6;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-b - T(2) * a))));
  const T t2 = -b * a_minus_b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * t3 * a - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(2, 6, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
  } else if (t2 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(2, 6, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = sqrt(D);
    const T t6 = T(1) / t5;
    const T J2 = atan2(t5, c_minus_b) * t6;
    J_2 = J2;
    const T t7 = T(1) / q1;
    const T t8 = T(1) / c;
    const T t9 = a_minus_b * t7 + b * t8 + J2 * a;
    const T t10 = T(1) / D;
    J_4 = (T(1) / T(2)) * t9 * t10;
    const T t11 = t8 * t8;
    const T t12 = t7 * t7;
    J_6 = (T(1) / T(8)) * t10 * (T(3) * t9 * t10 * a + T(2) * b * t11 + T(2) * a_minus_b * t12);
  }
  const T alpha_h = in.s * h;
  T H_f;
  T H_g;
  const T t13 = t3 - T(2) * zeta2;
  const T t14 = max(T(D - T(2) * zeta2 * a), T(t2));
  if (t13 >= T(0) && t14 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t15 = -b;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(4, 6, alpha_h, a, zeta2, t15, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t16 = T(1) / zeta2;
    const T H2 = -(J_2 * alpha_h - theta) * t16;
    const T H4 = t16 * (H2 - alpha_h * J_4);
    const T H6 = t16 * (H4 - J_6 * alpha_h);
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
/// Operations per edge: 54 +, 86 ×, 7 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 523 +, 1111 ×, 147 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  const T ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + zeta2;
  const T D = in.s * (zeta2 * ab_ab + in.s * cross_cross);
  const T h = in.normal[0] * cross0 + cross1 * in.normal[1] + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + in.s * bp_bp;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-b - T(2) * a))));
  const T t2 = -b * a_minus_b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * t3 * a - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 2> M_flat;
    segment_moments_gauss<T, 20>(3, 5, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
  } else if (t2 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 2> M_beyond;
    segment_moments_beyond_end<T>(3, 5, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = T(1) / r1;
    const T t6 = T(1) / r0;
    const T t7 = a_minus_b * t5 + b * t6;
    const T t8 = T(1) / D;
    J_3 = t7 * t8;
    J_5 = (T(1) / T(3)) * t8 * (a_minus_b * t5 / q1 + b * t6 / c + T(2) * t7 * t8 * a);
  }
  const T alpha_h = in.s * h;
  T H_f;
  const T t9 = t3 - T(2) * zeta2;
  const T t10 = max(T(D - T(2) * zeta2 * a), T(t2));
  if (t9 >= T(0) && t10 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t11 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(5, 5, alpha_h, a, zeta2, t11, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((a_minus_b * r0 + b * r1) * zeta * alpha_h, r1 * alpha_h * alpha_h * r0 - b * a_minus_b * zeta2) / zeta;
    const T t12 = T(1) / zeta2;
    const T H3 = t12 * (H1 - alpha_h * J_3);
    const T H5 = -t12 * (alpha_h * J_5 - H3);
    H_f = H5;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−7/2) dQ
/// Operations per edge: 57 +, 105 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 527 +, 1164 ×, 149 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ap2 * ab1 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + zeta2;
  const T D = in.s * (ab_ab * zeta2 + in.s * cross_cross);
  const T h = cross0 * in.normal[0] + cross1 * in.normal[1] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))));
  const T t2 = -b * a_minus_b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * a * t3 - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(3, 7, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
  } else if (t2 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(3, 7, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = T(1) / D;
    const T t6 = T(1) / r0;
    const T t7 = T(1) / r1;
    const T t8 = b * t6 + t7 * a_minus_b;
    J_3 = t5 * t8;
    const T t9 = t6 * t6;
    const T t10 = t7 * t7;
    const T t11 = b * t6 * t9 + t10 * t7 * a_minus_b + T(2) * t5 * a * t8;
    J_5 = (T(1) / T(3)) * t11 * t5;
    const T t12 = t9 * t9;
    const T t13 = t10 * t10;
    J_7 = (T(1) / T(15)) * t5 * (T(3) * b * t6 * t12 + T(3) * t13 * t7 * a_minus_b + T(4) * t11 * t5 * a);
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t14 = t3 - T(2) * zeta2;
  const T t15 = max(T(D - T(2) * a * zeta2), T(t2));
  if (t14 >= T(0) && t15 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t16 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(7, 7, alpha_h, a, zeta2, t16, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((r0 * a_minus_b + b * r1) * zeta * alpha_h, r0 * alpha_h * alpha_h * r1 - b * zeta2 * a_minus_b) / zeta;
    const T t17 = T(1) / zeta2;
    const T H3 = (H1 - J_3 * alpha_h) * t17;
    const T H5 = (H3 - J_5 * alpha_h) * t17;
    const T H7 = -(J_7 * alpha_h - H5) * t17;
    H_g = H7;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_7;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−7/2) dQ
/// Operations per edge: 57 +, 105 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 547 +, 1165 ×, 149 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + zeta2;
  const T D = in.s * (ab_ab * zeta2 + in.s * cross_cross);
  const T h = in.normal[0] * cross0 + cross1 * in.normal[1] + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = in.s * bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-b - T(2) * a))));
  const T t2 = -b * a_minus_b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * t3 * a - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(3, 7, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
  } else if (t2 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(3, 7, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = T(1) / r1;
    const T t6 = T(1) / r0;
    const T t7 = t5 * a_minus_b + b * t6;
    const T t8 = T(1) / D;
    J_3 = t7 * t8;
    const T t9 = t5 * t5;
    const T t10 = t6 * t6;
    const T t11 = T(2) * t7 * t8 * a + t5 * a_minus_b * t9 + b * t6 * t10;
    J_5 = (T(1) / T(3)) * t11 * t8;
    const T t12 = t10 * t10;
    const T t13 = t9 * t9;
    J_7 = (T(1) / T(15)) * (T(4) * t11 * t8 * a + T(3) * b * t6 * t12 + T(3) * t5 * a_minus_b * t13) * t8;
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t14 = t3 - T(2) * zeta2;
  const T t15 = max(T(D - T(2) * zeta2 * a), T(t2));
  if (t14 >= T(0) && t15 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t16 = -b;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(5, 7, alpha_h, a, zeta2, t16, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(alpha_h * (b * r1 + r0 * a_minus_b) * zeta, r0 * alpha_h * alpha_h * r1 - b * zeta2 * a_minus_b) / zeta;
    const T t17 = T(1) / zeta2;
    const T H3 = (H1 - alpha_h * J_3) * t17;
    const T H5 = -(alpha_h * J_5 - H3) * t17;
    const T H7 = (H5 - J_7 * alpha_h) * t17;
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
/// Operations per edge: 55 +, 87 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 528 +, 1083 ×, 149 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
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
  T J_4;
  T J_6;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))));
  const T t2 = -a_minus_b * b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * t3 * a - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(2, 6, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
  } else if (t2 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(2, 6, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = sqrt(D);
    const T t6 = T(1) / t5;
    const T J2 = t6 * atan2(t5, c_minus_b);
    J_2 = J2;
    const T t7 = T(1) / c;
    const T t8 = T(1) / q1;
    const T t9 = J2 * a + t7 * b + a_minus_b * t8;
    const T t10 = T(1) / D;
    J_4 = (T(1) / T(2)) * t9 * t10;
    const T t11 = t8 * t8;
    const T t12 = t7 * t7;
    J_6 = (T(1) / T(8)) * (T(3) * t9 * t10 * a + T(2) * a_minus_b * t11 + T(2) * t12 * b) * t10;
  }
  const T alpha_h = in.s * h;
  T H_f;
  const T t13 = t3 - T(2) * zeta2;
  const T t14 = max(T(D - T(2) * zeta2 * a), T(t2));
  if (t13 >= T(0) && t14 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t15 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(6, 6, alpha_h, a, zeta2, t15, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t16 = T(1) / zeta2;
    const T H2 = -(J_2 * alpha_h - theta) * t16;
    const T H4 = t16 * (H2 - alpha_h * J_4);
    const T H6 = -t16 * (J_6 * alpha_h - H4);
    H_f = H6;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−8/2) dQ
/// Operations per edge: 58 +, 100 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 532 +, 1117 ×, 151 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap2 * ab2 + ab1 * ap1 + ap0 * ab0;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T plain_cross0 = ap2 * ab1 - ab2 * ap1;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
  const T plain_cross2 = ab0 * ap1 - ap0 * ab1;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + bp1 * ap1;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + zeta2;
  const T D = in.s * (in.s * cross_cross + zeta2 * ab_ab);
  const T h = cross1 * in.normal[1] + cross0 * in.normal[0] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T c_minus_b = in.s * ap_bp + zeta2;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-b - T(2) * a))));
  const T t2 = -b * a_minus_b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * t3 * a - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(2, 8, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
  } else if (t2 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(2, 8, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
    J_8 = M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = sqrt(D);
    const T t6 = T(1) / t5;
    const T J2 = atan2(t5, c_minus_b) * t6;
    J_2 = J2;
    const T t7 = T(1) / q1;
    const T t8 = T(1) / c;
    const T t9 = a_minus_b * t7 + b * t8 + J2 * a;
    const T t10 = T(1) / D;
    J_4 = (T(1) / T(2)) * t9 * t10;
    const T t11 = t8 * t8;
    const T t12 = t7 * t7;
    const T t13 = T(3) * t9 * t10 * a + T(2) * b * t11 + T(2) * a_minus_b * t12;
    J_6 = (T(1) / T(8)) * t13 * t10;
    const T t14 = t12 * t7;
    const T t15 = t11 * t8;
    J_8 = (T(1) / T(48)) * (T(8) * a_minus_b * t14 + T(8) * b * t15 + T(5) * t13 * t10 * a) * t10;
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t16 = t3 - T(2) * zeta2;
  const T t17 = max(T(D - T(2) * zeta2 * a), T(t2));
  if (t16 >= T(0) && t17 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t18 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(8, 8, alpha_h, a, zeta2, t18, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t19 = T(1) / zeta2;
    const T H2 = (theta - J_2 * alpha_h) * t19;
    const T H4 = -(J_4 * alpha_h - H2) * t19;
    const T H6 = (H4 - J_6 * alpha_h) * t19;
    const T H8 = -(J_8 * alpha_h - H6) * t19;
    H_g = H8;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_8;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−8/2) dQ
/// Operations per edge: 58 +, 100 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 552 +, 1138 ×, 151 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab0 * bp0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + bp1 * ap1 + ap2 * bp2;
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = (cross_cross * in.s + zeta2 * ab_ab) * in.s;
  const T h = cross1 * in.normal[1] + cross2 * in.normal[2] + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = bp_bp * in.s + zeta2;
  const T c_minus_b = zeta2 + ap_bp * in.s;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))));
  const T t2 = -a_minus_b * b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * t3 * a - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(2, 8, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
  } else if (t2 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(2, 8, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
    J_8 = M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = sqrt(D);
    const T t6 = T(1) / t5;
    const T J2 = t6 * atan2(t5, c_minus_b);
    J_2 = J2;
    const T t7 = T(1) / q1;
    const T t8 = T(1) / c;
    const T t9 = J2 * a + t7 * a_minus_b + t8 * b;
    const T t10 = T(1) / D;
    J_4 = (T(1) / T(2)) * t9 * t10;
    const T t11 = t8 * t8;
    const T t12 = t7 * t7;
    const T t13 = T(2) * t11 * b + T(2) * t12 * a_minus_b + T(3) * t9 * t10 * a;
    J_6 = (T(1) / T(8)) * t10 * t13;
    const T t14 = t11 * t8;
    const T t15 = t12 * t7;
    J_8 = (T(1) / T(48)) * t10 * (T(5) * t10 * a * t13 + T(8) * t14 * b + T(8) * t15 * a_minus_b);
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t16 = t3 - T(2) * zeta2;
  const T t17 = max(T(D - T(2) * zeta2 * a), T(t2));
  if (t16 >= T(0) && t17 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t18 = -b;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(6, 8, alpha_h, a, zeta2, t18, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t19 = T(1) / zeta2;
    const T H2 = (theta - alpha_h * J_2) * t19;
    const T H4 = (H2 - alpha_h * J_4) * t19;
    const T H6 = (H4 - J_6 * alpha_h) * t19;
    const T H8 = t19 * (H6 - J_8 * alpha_h);
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
/// Operations per edge: 57 +, 105 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 527 +, 1164 ×, 149 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  const T ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = zeta2 + ap_ap * in.s;
  const T D = in.s * (in.s * cross_cross + zeta2 * ab_ab);
  const T h = in.normal[2] * cross2 + cross0 * in.normal[0] + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = in.s * bp_bp + zeta2;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-b - T(2) * a))));
  const T t2 = -b * a_minus_b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * t3 * a - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 3> M_flat;
    segment_moments_gauss<T, 20>(3, 7, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
  } else if (t2 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 3> M_beyond;
    segment_moments_beyond_end<T>(3, 7, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = T(1) / r1;
    const T t6 = T(1) / r0;
    const T t7 = t5 * a_minus_b + b * t6;
    const T t8 = T(1) / D;
    J_3 = t7 * t8;
    const T t9 = t5 * t5;
    const T t10 = t6 * t6;
    const T t11 = t9 * t5 * a_minus_b + T(2) * t7 * t8 * a + b * t6 * t10;
    J_5 = (T(1) / T(3)) * t11 * t8;
    const T t12 = t10 * t10;
    const T t13 = t9 * t9;
    J_7 = (T(1) / T(15)) * (T(3) * b * t6 * t12 + T(4) * t11 * t8 * a + T(3) * t13 * t5 * a_minus_b) * t8;
  }
  const T alpha_h = h * in.s;
  T H_f;
  const T t14 = t3 - T(2) * zeta2;
  const T t15 = max(T(D - T(2) * zeta2 * a), T(t2));
  if (t14 >= T(0) && t15 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t16 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(7, 7, alpha_h, a, zeta2, t16, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * alpha_h * (r0 * a_minus_b + b * r1), r0 * alpha_h * alpha_h * r1 - b * zeta2 * a_minus_b) / zeta;
    const T t17 = T(1) / zeta2;
    const T H3 = -(alpha_h * J_3 - H1) * t17;
    const T H5 = t17 * (H3 - J_5 * alpha_h);
    const T H7 = (H5 - J_7 * alpha_h) * t17;
    H_f = H7;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−9/2) dQ
/// Operations per edge: 60 +, 120 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 531 +, 1217 ×, 151 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = (cross_cross * in.s + ab_ab * zeta2) * in.s;
  const T h = in.normal[0] * cross0 + cross2 * in.normal[2] + in.normal[1] * cross1;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  T J_9;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))));
  const T t2 = -a_minus_b * b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * a * t3 - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(3, 9, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
    J_9 = M_flat[3];
  } else if (t2 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(3, 9, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
    J_9 = M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = T(1) / r1;
    const T t6 = T(1) / r0;
    const T t7 = t5 * a_minus_b + t6 * b;
    const T t8 = T(1) / D;
    J_3 = t7 * t8;
    const T t9 = t5 * t5;
    const T t10 = t6 * t6;
    const T t11 = t5 * a_minus_b * t9 + t10 * t6 * b + T(2) * t7 * t8 * a;
    J_5 = (T(1) / T(3)) * t8 * t11;
    const T t12 = t10 * t10;
    const T t13 = t9 * t9;
    const T t14 = T(4) * t8 * a * t11 + T(3) * t12 * t6 * b + T(3) * t5 * a_minus_b * t13;
    J_7 = (T(1) / T(15)) * t14 * t8;
    const T t15 = t12 * t10;
    const T t16 = t13 * t9;
    J_9 = (T(1) / T(35)) * t8 * (T(2) * t14 * t8 * a + T(5) * t15 * t6 * b + T(5) * t5 * a_minus_b * t16);
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t17 = t3 - T(2) * zeta2;
  const T t18 = max(T(D - T(2) * zeta2 * a), T(t2));
  if (t17 >= T(0) && t18 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t19 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(9, 9, alpha_h, a, zeta2, t19, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(zeta * alpha_h * (r1 * b + r0 * a_minus_b), alpha_h * alpha_h * r0 * r1 - zeta2 * a_minus_b * b) / zeta;
    const T t20 = T(1) / zeta2;
    const T H3 = -t20 * (alpha_h * J_3 - H1);
    const T H5 = t20 * (H3 - alpha_h * J_5);
    const T H7 = -t20 * (alpha_h * J_7 - H5);
    const T H9 = -(alpha_h * J_9 - H7) * t20;
    H_g = H9;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_9;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−9/2) dQ
/// Operations per edge: 60 +, 120 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 551 +, 1218 ×, 151 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  const T ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = (cross_cross * in.s + zeta2 * ab_ab) * in.s;
  const T h = in.normal[0] * cross0 + in.normal[1] * cross1 + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  T J_9;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))));
  const T t2 = -a_minus_b * b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * a * t3 - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(3, 9, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
    J_9 = M_flat[3];
  } else if (t2 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(3, 9, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
    J_9 = M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = T(1) / D;
    const T t6 = T(1) / r1;
    const T t7 = T(1) / r0;
    const T t8 = t6 * a_minus_b + t7 * b;
    J_3 = t5 * t8;
    const T t9 = t6 * t6;
    const T t10 = t7 * t7;
    const T t11 = T(2) * t5 * a * t8 + t6 * a_minus_b * t9 + t10 * t7 * b;
    J_5 = (T(1) / T(3)) * t5 * t11;
    const T t12 = t10 * t10;
    const T t13 = t9 * t9;
    const T t14 = T(3) * t12 * t7 * b + T(3) * t6 * a_minus_b * t13 + T(4) * t5 * a * t11;
    J_7 = (T(1) / T(15)) * t14 * t5;
    const T t15 = t13 * t9;
    const T t16 = t12 * t10;
    J_9 = (T(1) / T(35)) * t5 * (T(2) * t14 * t5 * a + T(5) * t6 * a_minus_b * t15 + T(5) * t16 * t7 * b);
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t17 = t3 - T(2) * zeta2;
  const T t18 = max(T(D - T(2) * zeta2 * a), T(t2));
  if (t17 >= T(0) && t18 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t19 = -b;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(7, 9, alpha_h, a, zeta2, t19, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((r1 * b + r0 * a_minus_b) * zeta * alpha_h, r0 * r1 * alpha_h * alpha_h - zeta2 * a_minus_b * b) / zeta;
    const T t20 = T(1) / zeta2;
    const T H3 = t20 * (H1 - J_3 * alpha_h);
    const T H5 = t20 * (H3 - J_5 * alpha_h);
    const T H7 = -t20 * (J_7 * alpha_h - H5);
    const T H9 = -t20 * (J_9 * alpha_h - H7);
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
/// Operations per edge: 58 +, 100 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 532 +, 1117 ×, 151 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = (zeta2 * ab_ab + cross_cross * in.s) * in.s;
  const T h = in.normal[0] * cross0 + cross1 * in.normal[1] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T c_minus_b = ap_bp * in.s + zeta2;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))));
  const T t2 = -a_minus_b * b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * a * t3 - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(2, 8, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
  } else if (t2 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(2, 8, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_2 = M_beyond[0];
    J_4 = M_beyond[1];
    J_6 = M_beyond[2];
    J_8 = M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = sqrt(D);
    const T t6 = T(1) / t5;
    const T J2 = atan2(t5, c_minus_b) * t6;
    J_2 = J2;
    const T t7 = T(1) / q1;
    const T t8 = T(1) / c;
    const T t9 = J2 * a + a_minus_b * t7 + t8 * b;
    const T t10 = T(1) / D;
    J_4 = (T(1) / T(2)) * t9 * t10;
    const T t11 = t8 * t8;
    const T t12 = t7 * t7;
    const T t13 = T(2) * t11 * b + T(3) * t9 * a * t10 + T(2) * a_minus_b * t12;
    J_6 = (T(1) / T(8)) * t10 * t13;
    const T t14 = t11 * t8;
    const T t15 = t12 * t7;
    J_8 = (T(1) / T(48)) * t10 * (T(8) * t14 * b + T(8) * a_minus_b * t15 + T(5) * a * t10 * t13);
  }
  const T alpha_h = h * in.s;
  T H_f;
  const T t16 = t3 - T(2) * zeta2;
  const T t17 = max(T(D - T(2) * zeta2 * a), T(t2));
  if (t16 >= T(0) && t17 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t18 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(8, 8, alpha_h, a, zeta2, t18, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t19 = T(1) / zeta2;
    const T H2 = t19 * (theta - alpha_h * J_2);
    const T H4 = -(alpha_h * J_4 - H2) * t19;
    const T H6 = -t19 * (J_6 * alpha_h - H4);
    const T H8 = -t19 * (J_8 * alpha_h - H6);
    H_f = H8;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−10/2) dQ
/// Operations per edge: 61 +, 113 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 536 +, 1151 ×, 153 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ap2 * ab1 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + zeta2;
  const T D = in.s * (in.s * cross_cross + ab_ab * zeta2);
  const T h = in.normal[2] * cross2 + cross0 * in.normal[0] + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T c_minus_b = in.s * ap_bp + zeta2;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  T J_10;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))));
  const T t2 = -b * a_minus_b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * a * t3 - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(2, 10, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
    J_10 = M_flat[4];
  } else if (t2 >= T(0) && t4 >= T(0)) {
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
    const T t5 = sqrt(D);
    const T t6 = T(1) / t5;
    const T J2 = atan2(t5, c_minus_b) * t6;
    J_2 = J2;
    const T t7 = T(1) / q1;
    const T t8 = T(1) / c;
    const T t9 = a * J2 + a_minus_b * t7 + b * t8;
    const T t10 = T(1) / D;
    J_4 = (T(1) / T(2)) * t9 * t10;
    const T t11 = t8 * t8;
    const T t12 = t7 * t7;
    const T t13 = T(3) * a * t9 * t10 + T(2) * b * t11 + T(2) * a_minus_b * t12;
    J_6 = (T(1) / T(8)) * t10 * t13;
    const T t14 = t11 * t8;
    const T t15 = t12 * t7;
    const T t16 = T(8) * b * t14 + T(8) * a_minus_b * t15 + T(5) * a * t10 * t13;
    J_8 = (T(1) / T(48)) * t16 * t10;
    const T t17 = t12 * t12;
    const T t18 = t11 * t11;
    J_10 = (T(1) / T(384)) * (T(48) * a_minus_b * t17 + T(48) * b * t18 + T(7) * a * t16 * t10) * t10;
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t19 = t3 - T(2) * zeta2;
  const T t20 = max(T(D - T(2) * a * zeta2), T(t2));
  if (t19 >= T(0) && t20 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t21 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(10, 10, alpha_h, a, zeta2, t21, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t22 = T(1) / zeta2;
    const T H2 = -t22 * (J_2 * alpha_h - theta);
    const T H4 = -(J_4 * alpha_h - H2) * t22;
    const T H6 = t22 * (H4 - J_6 * alpha_h);
    const T H8 = (H6 - J_8 * alpha_h) * t22;
    const T H10 = -(J_10 * alpha_h - H8) * t22;
    H_g = H10;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_10;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−10/2) dQ
/// Operations per edge: 61 +, 113 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 556 +, 1172 ×, 153 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap1 * ab1 + ap0 * ab0;
  const T ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + zeta2;
  const T D = in.s * (zeta2 * ab_ab + in.s * cross_cross);
  const T h = cross1 * in.normal[1] + cross0 * in.normal[0] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T c_minus_b = in.s * ap_bp + zeta2;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  T J_10;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-b - T(2) * a))));
  const T t2 = -b * a_minus_b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * t3 * a - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(2, 10, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
    J_10 = M_flat[4];
  } else if (t2 >= T(0) && t4 >= T(0)) {
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
    const T t5 = sqrt(D);
    const T t6 = T(1) / t5;
    const T J2 = atan2(t5, c_minus_b) * t6;
    J_2 = J2;
    const T t7 = T(1) / D;
    const T t8 = T(1) / q1;
    const T t9 = T(1) / c;
    const T t10 = a_minus_b * t8 + b * t9 + a * J2;
    J_4 = (T(1) / T(2)) * t7 * t10;
    const T t11 = t8 * t8;
    const T t12 = t9 * t9;
    const T t13 = T(3) * t7 * t10 * a + T(2) * a_minus_b * t11 + T(2) * b * t12;
    J_6 = (T(1) / T(8)) * t13 * t7;
    const T t14 = t12 * t9;
    const T t15 = t11 * t8;
    const T t16 = T(5) * t13 * t7 * a + T(8) * b * t14 + T(8) * a_minus_b * t15;
    J_8 = (T(1) / T(48)) * t16 * t7;
    const T t17 = t11 * t11;
    const T t18 = t12 * t12;
    J_10 = (T(1) / T(384)) * t7 * (T(48) * a_minus_b * t17 + T(48) * b * t18 + T(7) * t16 * t7 * a);
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t19 = t3 - T(2) * zeta2;
  const T t20 = max(T(D - T(2) * zeta2 * a), T(t2));
  if (t19 >= T(0) && t20 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t21 = -b;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(8, 10, alpha_h, a, zeta2, t21, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t22 = T(1) / zeta2;
    const T H2 = (theta - J_2 * alpha_h) * t22;
    const T H4 = -t22 * (J_4 * alpha_h - H2);
    const T H6 = -(J_6 * alpha_h - H4) * t22;
    const T H8 = -t22 * (alpha_h * J_8 - H6);
    const T H10 = (H8 - J_10 * alpha_h) * t22;
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
/// Operations per edge: 60 +, 120 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 531 +, 1217 ×, 151 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = (ab_ab * zeta2 + cross_cross * in.s) * in.s;
  const T h = in.normal[1] * cross1 + in.normal[0] * cross0 + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = zeta2 + bp_bp * in.s;
  const T r0 = sqrt(c);
  const T r1 = sqrt(q1);
  T J_3;
  T J_5;
  T J_7;
  T J_9;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))));
  const T t2 = -a_minus_b * b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * a * t3 - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 4> M_flat;
    segment_moments_gauss<T, 20>(3, 9, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
    J_9 = M_flat[3];
  } else if (t2 >= T(0) && t4 >= T(0)) {
    // P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, recurrence (1) downwards (segment_moments_beyond_end)
    std::array<T, 4> M_beyond;
    segment_moments_beyond_end<T>(3, 9, 0, a, b, a_minus_b, D, c, q1, M_beyond.data());
    J_3 = M_beyond[0];
    J_5 = M_beyond[1];
    J_7 = M_beyond[2];
    J_9 = M_beyond[3];
  } else {
    // recurrence (1) upwards from J_1, J_2
    const T t5 = T(1) / r1;
    const T t6 = T(1) / r0;
    const T t7 = a_minus_b * t5 + t6 * b;
    const T t8 = T(1) / D;
    J_3 = t7 * t8;
    const T t9 = t5 * t5;
    const T t10 = t6 * t6;
    const T t11 = a_minus_b * t5 * t9 + t10 * t6 * b + T(2) * t7 * t8 * a;
    J_5 = (T(1) / T(3)) * t11 * t8;
    const T t12 = t10 * t10;
    const T t13 = t9 * t9;
    const T t14 = T(4) * t11 * t8 * a + T(3) * t12 * t6 * b + T(3) * a_minus_b * t5 * t13;
    J_7 = (T(1) / T(15)) * t14 * t8;
    const T t15 = t12 * t10;
    const T t16 = t13 * t9;
    J_9 = (T(1) / T(35)) * t8 * (T(5) * t15 * t6 * b + T(5) * a_minus_b * t5 * t16 + T(2) * t14 * t8 * a);
  }
  const T alpha_h = h * in.s;
  T H_f;
  const T t17 = t3 - T(2) * zeta2;
  const T t18 = max(T(D - T(2) * zeta2 * a), T(t2));
  if (t17 >= T(0) && t18 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t19 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(9, 9, alpha_h, a, zeta2, t19, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(alpha_h * (r0 * a_minus_b + r1 * b) * zeta, alpha_h * alpha_h * r0 * r1 - zeta2 * a_minus_b * b) / zeta;
    const T t20 = T(1) / zeta2;
    const T H3 = (H1 - alpha_h * J_3) * t20;
    const T H5 = -t20 * (alpha_h * J_5 - H3);
    const T H7 = -t20 * (alpha_h * J_7 - H5);
    const T H9 = t20 * (H7 - alpha_h * J_9);
    H_f = H9;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−11/2) dQ
/// Operations per edge: 63 +, 135 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 535 +, 1271 ×, 153 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  const T ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  const T ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
  }
  const T bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  const T ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = (zeta2 * ab_ab + cross_cross * in.s) * in.s;
  const T h = cross2 * in.normal[2] + in.normal[1] * cross1 + in.normal[0] * cross0;
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
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))));
  const T t2 = -b * a_minus_b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * a * t3 - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(3, 11, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
    J_9 = M_flat[3];
    J_11 = M_flat[4];
  } else if (t2 >= T(0) && t4 >= T(0)) {
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
    const T t5 = T(1) / D;
    const T t6 = T(1) / r1;
    const T t7 = T(1) / r0;
    const T t8 = t6 * a_minus_b + t7 * b;
    J_3 = t5 * t8;
    const T t9 = t7 * t7;
    const T t10 = t6 * t6;
    const T t11 = T(2) * t5 * a * t8 + t7 * b * t9 + t10 * t6 * a_minus_b;
    J_5 = (T(1) / T(3)) * t11 * t5;
    const T t12 = t10 * t10;
    const T t13 = t9 * t9;
    const T t14 = T(3) * t12 * t6 * a_minus_b + T(3) * t7 * b * t13 + T(4) * t11 * t5 * a;
    J_7 = (T(1) / T(15)) * t14 * t5;
    const T t15 = t13 * t9;
    const T t16 = t12 * t10;
    const T t17 = T(2) * t14 * t5 * a + T(5) * t7 * b * t15 + T(5) * t16 * t6 * a_minus_b;
    J_9 = (T(1) / T(35)) * t5 * t17;
    const T t18 = t13 * t13;
    const T t19 = t12 * t12;
    J_11 = (T(1) / T(315)) * (T(35) * t7 * b * t18 + T(35) * t19 * t6 * a_minus_b + T(8) * t5 * a * t17) * t5;
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t20 = t3 - T(2) * zeta2;
  const T t21 = max(T(D - T(2) * zeta2 * a), T(t2));
  if (t20 >= T(0) && t21 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t22 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(11, 11, alpha_h, a, zeta2, t22, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2((b * r1 + r0 * a_minus_b) * zeta * alpha_h, r0 * r1 * alpha_h * alpha_h - zeta2 * b * a_minus_b) / zeta;
    const T t23 = T(1) / zeta2;
    const T H3 = t23 * (H1 - J_3 * alpha_h);
    const T H5 = -t23 * (J_5 * alpha_h - H3);
    const T H7 = -t23 * (J_7 * alpha_h - H5);
    const T H9 = t23 * (H7 - J_9 * alpha_h);
    const T H11 = -t23 * (J_11 * alpha_h - H9);
    H_g = H11;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_11;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−11/2) dQ
/// Operations per edge: 63 +, 135 ×, 5 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 555 +, 1272 ×, 153 /, 24 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2];
  }
  const T bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  const T ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  const T ap_bp = ap1 * bp1 + bp0 * ap0 + ap2 * bp2;
  const T zeta2 = in.z * in.z * in.s + T(1);
  const T a = ab_ab * in.s;
  const T b = ab_ap * in.s;
  const T c = zeta2 + ap_ap * in.s;
  const T D = (cross_cross * in.s + ab_ab * zeta2) * in.s;
  const T h = cross2 * in.normal[2] + in.normal[0] * cross0 + cross1 * in.normal[1];
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
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))));
  const T t2 = -b * a_minus_b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * t3 * a - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(3, 11, 0, a, b, c, T(0), T(1), M_flat.data());
    J_3 = M_flat[0];
    J_5 = M_flat[1];
    J_7 = M_flat[2];
    J_9 = M_flat[3];
    J_11 = M_flat[4];
  } else if (t2 >= T(0) && t4 >= T(0)) {
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
    const T t5 = T(1) / r0;
    const T t6 = T(1) / r1;
    const T t7 = t5 * b + t6 * a_minus_b;
    const T t8 = T(1) / D;
    J_3 = t7 * t8;
    const T t9 = t5 * t5;
    const T t10 = t6 * t6;
    const T t11 = T(2) * t7 * t8 * a + t9 * t5 * b + t10 * t6 * a_minus_b;
    J_5 = (T(1) / T(3)) * t8 * t11;
    const T t12 = t9 * t9;
    const T t13 = t10 * t10;
    const T t14 = T(3) * t12 * t5 * b + T(3) * t13 * t6 * a_minus_b + T(4) * t8 * a * t11;
    J_7 = (T(1) / T(15)) * t14 * t8;
    const T t15 = t13 * t10;
    const T t16 = t12 * t9;
    const T t17 = T(2) * t14 * t8 * a + T(5) * t15 * t6 * a_minus_b + T(5) * t16 * t5 * b;
    J_9 = (T(1) / T(35)) * t8 * t17;
    const T t18 = t12 * t12;
    const T t19 = t13 * t13;
    J_11 = (T(1) / T(315)) * t8 * (T(35) * t18 * t5 * b + T(35) * t19 * t6 * a_minus_b + T(8) * t8 * a * t17);
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t20 = t3 - T(2) * zeta2;
  const T t21 = max(T(D - T(2) * zeta2 * a), T(t2));
  if (t20 >= T(0) && t21 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t22 = -b;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(9, 11, alpha_h, a, zeta2, t22, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_1
    const T zeta = sqrt(zeta2);
    const T H1 = atan2(alpha_h * (b * r1 + r0 * a_minus_b) * zeta, alpha_h * alpha_h * r0 * r1 - zeta2 * b * a_minus_b) / zeta;
    const T t23 = T(1) / zeta2;
    const T H3 = t23 * (H1 - alpha_h * J_3);
    const T H5 = (H3 - alpha_h * J_5) * t23;
    const T H7 = -t23 * (alpha_h * J_7 - H5);
    const T H9 = -t23 * (alpha_h * J_9 - H7);
    const T H11 = t23 * (H9 - alpha_h * J_11);
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
/// Operations per edge: 61 +, 113 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 536 +, 1151 ×, 153 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  const T ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  const T plain_cross0 = ap2 * ab1 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + zeta2;
  const T D = (in.s * cross_cross + zeta2 * ab_ab) * in.s;
  const T h = in.normal[2] * cross2 + cross0 * in.normal[0] + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = zeta2 + bp_bp * in.s;
  const T c_minus_b = in.s * ap_bp + zeta2;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  T J_10;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-b - T(2) * a))));
  const T t2 = -b * a_minus_b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * t3 * a - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 5> M_flat;
    segment_moments_gauss<T, 20>(2, 10, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
    J_10 = M_flat[4];
  } else if (t2 >= T(0) && t4 >= T(0)) {
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
    const T t5 = sqrt(D);
    const T t6 = T(1) / t5;
    const T J2 = atan2(t5, c_minus_b) * t6;
    J_2 = J2;
    const T t7 = T(1) / q1;
    const T t8 = T(1) / c;
    const T t9 = a_minus_b * t7 + b * t8 + J2 * a;
    const T t10 = T(1) / D;
    J_4 = (T(1) / T(2)) * t9 * t10;
    const T t11 = t8 * t8;
    const T t12 = t7 * t7;
    const T t13 = T(2) * b * t11 + T(2) * a_minus_b * t12 + T(3) * t9 * t10 * a;
    J_6 = (T(1) / T(8)) * t13 * t10;
    const T t14 = t11 * t8;
    const T t15 = t12 * t7;
    const T t16 = T(8) * b * t14 + T(8) * a_minus_b * t15 + T(5) * t13 * t10 * a;
    J_8 = (T(1) / T(48)) * t16 * t10;
    const T t17 = t12 * t12;
    const T t18 = t11 * t11;
    J_10 = (T(1) / T(384)) * t10 * (T(48) * a_minus_b * t17 + T(48) * b * t18 + T(7) * t16 * t10 * a);
  }
  const T alpha_h = h * in.s;
  T H_f;
  const T t19 = t3 - T(2) * zeta2;
  const T t20 = max(T(D - T(2) * zeta2 * a), T(t2));
  if (t19 >= T(0) && t20 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t21 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(10, 10, alpha_h, a, zeta2, t21, a_minus_b, H_near.data());
    H_f = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t22 = T(1) / zeta2;
    const T H2 = (theta - alpha_h * J_2) * t22;
    const T H4 = -(J_4 * alpha_h - H2) * t22;
    const T H6 = (H4 - J_6 * alpha_h) * t22;
    const T H8 = t22 * (H6 - alpha_h * J_8);
    const T H10 = -(J_10 * alpha_h - H8) * t22;
    H_f = H10;
  }
  out.h = h;
  out.theta = theta;
  out.S_f = H_f;
}

/// The terms of one edge for ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−12/2) dQ
/// Operations per edge: 64 +, 126 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 540 +, 1186 ×, 155 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  const T ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  const T ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1] + exact_cross[0] * exact_cross[0];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + zeta2;
  const T D = (ab_ab * zeta2 + in.s * cross_cross) * in.s;
  const T h = in.normal[2] * cross2 + in.normal[0] * cross0 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -ab_bp * in.s;
  const T q1 = zeta2 + in.s * bp_bp;
  const T c_minus_b = in.s * ap_bp + zeta2;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  T J_10;
  T J_12;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-b - T(2) * a))));
  const T t2 = -b * a_minus_b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * t3 * a - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(2, 12, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
    J_10 = M_flat[4];
    J_12 = M_flat[5];
  } else if (t2 >= T(0) && t4 >= T(0)) {
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
    const T t5 = sqrt(D);
    const T t6 = T(1) / t5;
    const T J2 = atan2(t5, c_minus_b) * t6;
    J_2 = J2;
    const T t7 = T(1) / c;
    const T t8 = T(1) / q1;
    const T t9 = b * t7 + J2 * a + t8 * a_minus_b;
    const T t10 = T(1) / D;
    J_4 = (T(1) / T(2)) * t9 * t10;
    const T t11 = t8 * t8;
    const T t12 = t7 * t7;
    const T t13 = T(2) * t11 * a_minus_b + T(3) * t9 * t10 * a + T(2) * b * t12;
    J_6 = (T(1) / T(8)) * t13 * t10;
    const T t14 = t11 * t8;
    const T t15 = t12 * t7;
    const T t16 = T(8) * t14 * a_minus_b + T(5) * t13 * t10 * a + T(8) * b * t15;
    J_8 = (T(1) / T(48)) * t16 * t10;
    const T t17 = t12 * t12;
    const T t18 = t11 * t11;
    const T t19 = T(7) * t16 * t10 * a + T(48) * b * t17 + T(48) * t18 * a_minus_b;
    J_10 = (T(1) / T(384)) * t19 * t10;
    const T t20 = t18 * t8;
    const T t21 = t17 * t7;
    J_12 = (T(1) / T(1280)) * (T(128) * t20 * a_minus_b + T(3) * t19 * t10 * a + T(128) * b * t21) * t10;
  }
  const T alpha_h = h * in.s;
  T H_g;
  const T t22 = t3 - T(2) * zeta2;
  const T t23 = max(T(D - T(2) * zeta2 * a), T(t2));
  if (t22 >= T(0) && t23 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t24 = -b;
    std::array<T, 1> H_near;
    polygon_edge_H_near_plane<T>(12, 12, alpha_h, a, zeta2, t24, a_minus_b, H_near.data());
    H_g = H_near[0];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t25 = T(1) / zeta2;
    const T H2 = -t25 * (alpha_h * J_2 - theta);
    const T H4 = -(J_4 * alpha_h - H2) * t25;
    const T H6 = -(J_6 * alpha_h - H4) * t25;
    const T H8 = (H6 - J_8 * alpha_h) * t25;
    const T H10 = -(J_10 * alpha_h - H8) * t25;
    const T H12 = -t25 * (J_12 * alpha_h - H10);
    H_g = H12;
  }
  out.h = h;
  out.theta = theta;
  out.S_g = H_g;
  out.J_g = J_12;
}

/// The terms of one edge for f and ∇f (skelconv/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 + s |P − Q|²)^(−12/2) dQ
/// Operations per edge: 64 +, 126 ×, 5 /, 1 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 560 +, 1207 ×, 155 /, 2 sqrt, 3 atan, 2 log/asinh, 20 other.
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
  const T ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  const T ab_ap = ab2 * ap2 + ap0 * ab0 + ap1 * ab1;
  const T ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  const T plain_cross0 = ab1 * ap2 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
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
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
    cross_cross = exact_cross[0] * exact_cross[0] + exact_cross[2] * exact_cross[2] + exact_cross[1] * exact_cross[1];
  }
  const T bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  const T zeta2 = in.s * in.z * in.z + T(1);
  const T a = in.s * ab_ab;
  const T b = in.s * ab_ap;
  const T c = ap_ap * in.s + zeta2;
  const T D = in.s * (zeta2 * ab_ab + in.s * cross_cross);
  const T h = in.normal[2] * cross2 + cross1 * in.normal[1] + cross0 * in.normal[0];
  const T theta = atan2(h, ap_bp);
  const T a_minus_b = -in.s * ab_bp;
  const T q1 = bp_bp * in.s + zeta2;
  const T c_minus_b = in.s * ap_bp + zeta2;
  T J_2;
  T J_4;
  T J_6;
  T J_8;
  T J_10;
  T J_12;
  const T t1 = max(T(D - T(2) * a * a), T(max(T(b - T(3) * a), T(-T(2) * a - b))));
  const T t2 = -b * a_minus_b;
  const T t3 = min(T(c), T(q1));
  const T t4 = (T(7) / T(10)) * a * t3 - D;
  if (t1 >= T(0)) {
    // P far from the line (D ≥ 2a²) or beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2): every moment by segment_moments_gauss<T, 20>
    std::array<T, 6> M_flat;
    segment_moments_gauss<T, 20>(2, 12, 0, a, b, c, T(0), T(1), M_flat.data());
    J_2 = M_flat[0];
    J_4 = M_flat[1];
    J_6 = M_flat[2];
    J_8 = M_flat[3];
    J_10 = M_flat[4];
    J_12 = M_flat[5];
  } else if (t2 >= T(0) && t4 >= T(0)) {
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
    const T t5 = sqrt(D);
    const T t6 = T(1) / t5;
    const T J2 = atan2(t5, c_minus_b) * t6;
    J_2 = J2;
    const T t7 = T(1) / c;
    const T t8 = T(1) / q1;
    const T t9 = b * t7 + t8 * a_minus_b + a * J2;
    const T t10 = T(1) / D;
    J_4 = (T(1) / T(2)) * t9 * t10;
    const T t11 = t8 * t8;
    const T t12 = t7 * t7;
    const T t13 = T(2) * t11 * a_minus_b + T(2) * b * t12 + T(3) * a * t9 * t10;
    J_6 = (T(1) / T(8)) * t13 * t10;
    const T t14 = t12 * t7;
    const T t15 = t11 * t8;
    const T t16 = T(8) * b * t14 + T(8) * t15 * a_minus_b + T(5) * a * t13 * t10;
    J_8 = (T(1) / T(48)) * t16 * t10;
    const T t17 = t12 * t12;
    const T t18 = t11 * t11;
    const T t19 = T(7) * a * t16 * t10 + T(48) * b * t17 + T(48) * t18 * a_minus_b;
    J_10 = (T(1) / T(384)) * t19 * t10;
    const T t20 = t17 * t7;
    const T t21 = t18 * t8;
    J_12 = (T(1) / T(1280)) * (T(128) * b * t20 + T(128) * t21 * a_minus_b + T(3) * a * t19 * t10) * t10;
  }
  const T alpha_h = h * in.s;
  T H_f;
  T H_g;
  const T t22 = t3 - T(2) * zeta2;
  const T t23 = max(T(D - T(2) * a * zeta2), T(t2));
  if (t22 >= T(0) && t23 >= T(0)) {
    // near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, polygon_edge_H_near_plane (20-point Gauss–Legendre)
    const T t24 = -b;
    std::array<T, 2> H_near;
    polygon_edge_H_near_plane<T>(10, 12, alpha_h, a, zeta2, t24, a_minus_b, H_near.data());
    H_f = H_near[0];
    H_g = H_near[1];
  } else {
    // H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_0
    const T t25 = T(1) / zeta2;
    const T H2 = -(alpha_h * J_2 - theta) * t25;
    const T H4 = (H2 - J_4 * alpha_h) * t25;
    const T H6 = -(J_6 * alpha_h - H4) * t25;
    const T H8 = (H6 - alpha_h * J_8) * t25;
    const T H10 = -(J_10 * alpha_h - H8) * t25;
    const T H12 = (H10 - J_12 * alpha_h) * t25;
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
