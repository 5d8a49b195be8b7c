// generated/polygon_compact.hpp — polygon edge kernels of the compact family.
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
///     C(P) = ∬_Ω (1 − |P − Q|²/R²)^(4/2) dQ
/// Operations per edge: 87 +, 144 ×, 3 /, 0 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 845 +, 1006 ×, 92 /, 5 sqrt, 1 atan, 0 log/asinh.
template <class T>
void polygon_edge_compact_i4_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
  }
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T zeta2 = T(1) - inv_R2 * in.z * in.z;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = zeta2 - inv_R2 * ap_ap;
  const T h = cross0 * in.normal[0] + in.normal[2] * cross2 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  T J_minus4;
  T J_minus2;
  T J_minus0;
  {
    // even degree: the integrand is a polynomial of degree 4, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 3> M_exact;
    segment_moments_gauss<T, 7>(-4, 0, 0, a, b, c, in.t0, in.t1, M_exact.data());
    J_minus4 = M_exact[0];
    J_minus2 = M_exact[1];
    J_minus0 = M_exact[2];
  }
  const T plane_slope0 = in.t0 * ab_ab - ab_ap;
  const T plane_slope1 = ab_ab * in.t1 - ab_ap;
  T theta_in;
  T G_f;
  const T t1 = (T(1) / T(4)) * zeta2 * ab_ab;
  const T t2 = t1 - inv_R2 * h * h;
  const T t3 = max(T(t1 - inv_R2 * h * h - inv_R2 * min(T(plane_slope0 * plane_slope0), T(plane_slope1 * plane_slope1))), T(-plane_slope1 * plane_slope0));
  if (t2 >= T(0) && t3 >= T(0)) {
    // chord within half the disc radius of P̄: θ_in = atan2(…), G^(p) − w^p θ_in = −(h/R²) Σ_k w^k J_{−2(p−1−k)}
    const T t4 = in.t1 - T(1);
    theta_in = atan2(-(in.t0 - in.t1) * h, ap_bp + in.t0 * t4 * ab_ab - ab_ap * t4 - ab_bp * in.t0);
    G_f = -inv_R2 * (J_minus0 * zeta2 * zeta2 + J_minus4 + zeta2 * J_minus2) * h;
  } else {
    // chord near the rim of the support disc: G^(p) = sgn(h) ∫ q^p du/(1 + u²), u = tan φ, polygon_edge_G_compact_chord (Gauss–Legendre panels)
    const T t5 = in.point[2] - in.a[2];
    const T t6 = in.point[0] - in.a[0];
    const T t7 = in.a[1] - in.point[1];
    const T t8 = (T(17) / T(16)) * in.R * in.R - t5 * t5 - t6 * t6 - t7 * t7;
    std::array<T, 1> gap_A{};  // 0 where the call is not made
    if (in.t0 <= T(0) && t8 >= T(0)) {
      exact_point_support_gap<T>(in.a[0], in.a[1], in.a[2], in.point[0], in.point[1], in.point[2], in.R, gap_A.data());
    }
    std::array<T, 1> gap_B{};  // 0 where the call is not made
    if (in.t1 >= T(1)) {
      exact_point_support_gap<T>(in.b[0], in.b[1], in.b[2], in.point[0], in.point[1], in.point[2], in.R, gap_B.data());
    }
    std::array<T, 1> G_chord;
    polygon_edge_G_compact_chord<T>(3, 3, h, ab_ab, zeta2, inv_R2, plane_slope0, plane_slope1, in.t0, in.t1, gap_A[0], gap_B[0], G_chord.data());
    theta_in = T(0);
    G_f = G_chord[0];
  }
  out.h = h;
  out.theta = theta;
  out.theta_in = theta_in;
  out.S_f = G_f;
}

/// The terms of one edge for ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 − |P − Q|²/R²)^(4/2) dQ
/// Operations per edge: 86 +, 142 ×, 3 /, 0 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 845 +, 926 ×, 92 /, 5 sqrt, 1 atan, 0 log/asinh.
template <class T>
void polygon_edge_compact_i4_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross0;
  T cross1;
  T cross2;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
  }
  const T ab_bp = bp0 * ab0 + ab1 * bp1 + ab2 * bp2;
  const T ap_bp = bp0 * ap0 + ap1 * bp1 + ap2 * bp2;
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T zeta2 = T(1) - in.z * in.z * inv_R2;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = zeta2 - inv_R2 * ap_ap;
  const T h = cross2 * in.normal[2] + in.normal[0] * cross0 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  T J_minus4;
  T J_minus2;
  T J_minus0;
  {
    // even degree: the integrand is a polynomial of degree 4, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 3> M_exact;
    segment_moments_gauss<T, 7>(-4, 0, 0, a, b, c, in.t0, in.t1, M_exact.data());
    J_minus4 = M_exact[0];
    J_minus2 = M_exact[1];
    J_minus0 = M_exact[2];
  }
  const T plane_slope0 = in.t0 * ab_ab - ab_ap;
  const T plane_slope1 = ab_ab * in.t1 - ab_ap;
  T theta_in;
  T G_g;
  const T t1 = (T(1) / T(4)) * ab_ab * zeta2;
  const T t2 = t1 - h * h * inv_R2;
  const T t3 = max(T(t1 - h * h * inv_R2 - inv_R2 * min(T(plane_slope0 * plane_slope0), T(plane_slope1 * plane_slope1))), T(-plane_slope0 * plane_slope1));
  if (t2 >= T(0) && t3 >= T(0)) {
    // chord within half the disc radius of P̄: θ_in = atan2(…), G^(p) − w^p θ_in = −(h/R²) Σ_k w^k J_{−2(p−1−k)}
    const T t4 = in.t1 - T(1);
    theta_in = atan2(-h * (in.t0 - in.t1), ap_bp + in.t0 * ab_ab * t4 - ab_ap * t4 - in.t0 * ab_bp);
    G_g = -(J_minus0 * zeta2 + J_minus2) * h * inv_R2;
  } else {
    // chord near the rim of the support disc: G^(p) = sgn(h) ∫ q^p du/(1 + u²), u = tan φ, polygon_edge_G_compact_chord (Gauss–Legendre panels)
    const T t5 = in.point[1] - in.a[1];
    const T t6 = in.point[0] - in.a[0];
    const T t7 = in.point[2] - in.a[2];
    const T t8 = (T(17) / T(16)) * in.R * in.R - t5 * t5 - t6 * t6 - t7 * t7;
    std::array<T, 1> gap_A{};  // 0 where the call is not made
    if (in.t0 <= T(0) && t8 >= T(0)) {
      exact_point_support_gap<T>(in.a[0], in.a[1], in.a[2], in.point[0], in.point[1], in.point[2], in.R, gap_A.data());
    }
    std::array<T, 1> gap_B{};  // 0 where the call is not made
    if (in.t1 >= T(1)) {
      exact_point_support_gap<T>(in.b[0], in.b[1], in.b[2], in.point[0], in.point[1], in.point[2], in.R, gap_B.data());
    }
    std::array<T, 1> G_chord;
    polygon_edge_G_compact_chord<T>(2, 2, h, ab_ab, zeta2, inv_R2, plane_slope0, plane_slope1, in.t0, in.t1, gap_A[0], gap_B[0], G_chord.data());
    theta_in = T(0);
    G_g = G_chord[0];
  }
  out.h = h;
  out.theta = theta;
  out.theta_in = theta_in;
  out.S_g = G_g;
  out.J_g = J_minus4;
}

/// The terms of one edge for f and ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 − |P − Q|²/R²)^(4/2) dQ
/// Operations per edge: 88 +, 147 ×, 3 /, 0 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 925 +, 1086 ×, 92 /, 5 sqrt, 1 atan, 0 log/asinh.
template <class T>
void polygon_edge_compact_i4_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
  }
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T zeta2 = T(1) - inv_R2 * in.z * in.z;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = zeta2 - inv_R2 * ap_ap;
  const T h = cross0 * in.normal[0] + in.normal[2] * cross2 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  T J_minus4;
  T J_minus2;
  T J_minus0;
  {
    // even degree: the integrand is a polynomial of degree 4, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 3> M_exact;
    segment_moments_gauss<T, 7>(-4, 0, 0, a, b, c, in.t0, in.t1, M_exact.data());
    J_minus4 = M_exact[0];
    J_minus2 = M_exact[1];
    J_minus0 = M_exact[2];
  }
  const T plane_slope0 = in.t0 * ab_ab - ab_ap;
  const T plane_slope1 = ab_ab * in.t1 - ab_ap;
  T theta_in;
  T G_f;
  T G_g;
  const T t1 = (T(1) / T(4)) * zeta2 * ab_ab;
  const T t2 = t1 - inv_R2 * h * h;
  const T t3 = max(T(t1 - inv_R2 * min(T(plane_slope0 * plane_slope0), T(plane_slope1 * plane_slope1)) - inv_R2 * h * h), T(-plane_slope1 * plane_slope0));
  if (t2 >= T(0) && t3 >= T(0)) {
    // chord within half the disc radius of P̄: θ_in = atan2(…), G^(p) − w^p θ_in = −(h/R²) Σ_k w^k J_{−2(p−1−k)}
    const T t4 = in.t1 - T(1);
    theta_in = atan2(-(in.t0 - in.t1) * h, ap_bp + in.t0 * t4 * ab_ab - ab_bp * in.t0 - t4 * ab_ap);
    G_f = -inv_R2 * (zeta2 * J_minus2 + J_minus0 * zeta2 * zeta2 + J_minus4) * h;
    G_g = -(J_minus0 * zeta2 + J_minus2) * inv_R2 * h;
  } else {
    // chord near the rim of the support disc: G^(p) = sgn(h) ∫ q^p du/(1 + u²), u = tan φ, polygon_edge_G_compact_chord (Gauss–Legendre panels)
    const T t5 = in.point[2] - in.a[2];
    const T t6 = in.a[1] - in.point[1];
    const T t7 = in.point[0] - in.a[0];
    const T t8 = (T(17) / T(16)) * in.R * in.R - t5 * t5 - t6 * t6 - t7 * t7;
    std::array<T, 1> gap_A{};  // 0 where the call is not made
    if (in.t0 <= T(0) && t8 >= T(0)) {
      exact_point_support_gap<T>(in.a[0], in.a[1], in.a[2], in.point[0], in.point[1], in.point[2], in.R, gap_A.data());
    }
    std::array<T, 1> gap_B{};  // 0 where the call is not made
    if (in.t1 >= T(1)) {
      exact_point_support_gap<T>(in.b[0], in.b[1], in.b[2], in.point[0], in.point[1], in.point[2], in.R, gap_B.data());
    }
    std::array<T, 2> G_chord;
    polygon_edge_G_compact_chord<T>(2, 3, h, ab_ab, zeta2, inv_R2, plane_slope0, plane_slope1, in.t0, in.t1, gap_A[0], gap_B[0], G_chord.data());
    theta_in = T(0);
    G_f = G_chord[1];
    G_g = G_chord[0];
  }
  out.h = h;
  out.theta = theta;
  out.theta_in = theta_in;
  out.S_f = G_f;
  out.S_g = G_g;
  out.J_g = J_minus4;
}

/// The terms of one edge for f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 − |P − Q|²/R²)^(6/2) dQ
/// Operations per edge: 95 +, 161 ×, 3 /, 0 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 852 +, 1100 ×, 92 /, 5 sqrt, 1 atan, 0 log/asinh.
template <class T>
void polygon_edge_compact_i6_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross0;
  T cross1;
  T cross2;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
  }
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T zeta2 = T(1) - inv_R2 * in.z * in.z;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = zeta2 - inv_R2 * ap_ap;
  const T h = in.normal[1] * cross1 + cross2 * in.normal[2] + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  T J_minus6;
  T J_minus4;
  T J_minus2;
  T J_minus0;
  {
    // even degree: the integrand is a polynomial of degree 6, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 7>(-6, 0, 0, a, b, c, in.t0, in.t1, M_exact.data());
    J_minus6 = M_exact[0];
    J_minus4 = M_exact[1];
    J_minus2 = M_exact[2];
    J_minus0 = M_exact[3];
  }
  const T plane_slope0 = in.t0 * ab_ab - ab_ap;
  const T plane_slope1 = in.t1 * ab_ab - ab_ap;
  T theta_in;
  T G_f;
  const T t1 = (T(1) / T(4)) * zeta2 * ab_ab;
  const T t2 = t1 - h * h * inv_R2;
  const T t3 = max(T(t1 - inv_R2 * min(T(plane_slope0 * plane_slope0), T(plane_slope1 * plane_slope1)) - h * h * inv_R2), T(-plane_slope1 * plane_slope0));
  if (t2 >= T(0) && t3 >= T(0)) {
    // chord within half the disc radius of P̄: θ_in = atan2(…), G^(p) − w^p θ_in = −(h/R²) Σ_k w^k J_{−2(p−1−k)}
    const T t4 = in.t1 - T(1);
    theta_in = atan2(-h * (in.t0 - in.t1), ap_bp + in.t0 * t4 * ab_ab - ab_ap * t4 - in.t0 * ab_bp);
    const T t5 = zeta2 * zeta2;
    const T t6 = t5 * zeta2;
    G_f = -h * (J_minus2 * zeta2 * zeta2 + J_minus4 * zeta2 + J_minus6 + t6 * J_minus0) * inv_R2;
  } else {
    // chord near the rim of the support disc: G^(p) = sgn(h) ∫ q^p du/(1 + u²), u = tan φ, polygon_edge_G_compact_chord (Gauss–Legendre panels)
    const T t7 = in.point[2] - in.a[2];
    const T t8 = in.point[0] - in.a[0];
    const T t9 = in.point[1] - in.a[1];
    const T t10 = (T(17) / T(16)) * in.R * in.R - t7 * t7 - t8 * t8 - t9 * t9;
    std::array<T, 1> gap_A{};  // 0 where the call is not made
    if (in.t0 <= T(0) && t10 >= T(0)) {
      exact_point_support_gap<T>(in.a[0], in.a[1], in.a[2], in.point[0], in.point[1], in.point[2], in.R, gap_A.data());
    }
    std::array<T, 1> gap_B{};  // 0 where the call is not made
    if (in.t1 >= T(1)) {
      exact_point_support_gap<T>(in.b[0], in.b[1], in.b[2], in.point[0], in.point[1], in.point[2], in.R, gap_B.data());
    }
    std::array<T, 1> G_chord;
    polygon_edge_G_compact_chord<T>(4, 4, h, ab_ab, zeta2, inv_R2, plane_slope0, plane_slope1, in.t0, in.t1, gap_A[0], gap_B[0], G_chord.data());
    theta_in = T(0);
    G_f = G_chord[0];
  }
  out.h = h;
  out.theta = theta;
  out.theta_in = theta_in;
  out.S_f = G_f;
}

/// The terms of one edge for ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 − |P − Q|²/R²)^(6/2) dQ
/// Operations per edge: 94 +, 158 ×, 3 /, 0 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 852 +, 1020 ×, 92 /, 5 sqrt, 1 atan, 0 log/asinh.
template <class T>
void polygon_edge_compact_i6_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross0;
  T cross1;
  T cross2;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
  }
  const T ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T zeta2 = T(1) - inv_R2 * in.z * in.z;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = zeta2 - inv_R2 * ap_ap;
  const T h = cross2 * in.normal[2] + in.normal[0] * cross0 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  T J_minus6;
  T J_minus4;
  T J_minus2;
  T J_minus0;
  {
    // even degree: the integrand is a polynomial of degree 6, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 7>(-6, 0, 0, a, b, c, in.t0, in.t1, M_exact.data());
    J_minus6 = M_exact[0];
    J_minus4 = M_exact[1];
    J_minus2 = M_exact[2];
    J_minus0 = M_exact[3];
  }
  const T plane_slope0 = ab_ab * in.t0 - ab_ap;
  const T plane_slope1 = ab_ab * in.t1 - ab_ap;
  T theta_in;
  T G_g;
  const T t1 = (T(1) / T(4)) * ab_ab * zeta2;
  const T t2 = t1 - h * h * inv_R2;
  const T t3 = max(T(t1 - inv_R2 * min(T(plane_slope0 * plane_slope0), T(plane_slope1 * plane_slope1)) - h * h * inv_R2), T(-plane_slope0 * plane_slope1));
  if (t2 >= T(0) && t3 >= T(0)) {
    // chord within half the disc radius of P̄: θ_in = atan2(…), G^(p) − w^p θ_in = −(h/R²) Σ_k w^k J_{−2(p−1−k)}
    const T t4 = in.t1 - T(1);
    theta_in = atan2(-h * (in.t0 - in.t1), ap_bp + t4 * ab_ab * in.t0 - t4 * ab_ap - in.t0 * ab_bp);
    G_g = -h * (zeta2 * zeta2 * J_minus0 + J_minus4 + J_minus2 * zeta2) * inv_R2;
  } else {
    // chord near the rim of the support disc: G^(p) = sgn(h) ∫ q^p du/(1 + u²), u = tan φ, polygon_edge_G_compact_chord (Gauss–Legendre panels)
    const T t5 = in.point[2] - in.a[2];
    const T t6 = in.a[0] - in.point[0];
    const T t7 = in.point[1] - in.a[1];
    const T t8 = (T(17) / T(16)) * in.R * in.R - t5 * t5 - t6 * t6 - t7 * t7;
    std::array<T, 1> gap_A{};  // 0 where the call is not made
    if (in.t0 <= T(0) && t8 >= T(0)) {
      exact_point_support_gap<T>(in.a[0], in.a[1], in.a[2], in.point[0], in.point[1], in.point[2], in.R, gap_A.data());
    }
    std::array<T, 1> gap_B{};  // 0 where the call is not made
    if (in.t1 >= T(1)) {
      exact_point_support_gap<T>(in.b[0], in.b[1], in.b[2], in.point[0], in.point[1], in.point[2], in.R, gap_B.data());
    }
    std::array<T, 1> G_chord;
    polygon_edge_G_compact_chord<T>(3, 3, h, ab_ab, zeta2, inv_R2, plane_slope0, plane_slope1, in.t0, in.t1, gap_A[0], gap_B[0], G_chord.data());
    theta_in = T(0);
    G_g = G_chord[0];
  }
  out.h = h;
  out.theta = theta;
  out.theta_in = theta_in;
  out.S_g = G_g;
  out.J_g = J_minus6;
}

/// The terms of one edge for f and ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 − |P − Q|²/R²)^(6/2) dQ
/// Operations per edge: 97 +, 164 ×, 3 /, 0 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 932 +, 1180 ×, 92 /, 5 sqrt, 1 atan, 0 log/asinh.
template <class T>
void polygon_edge_compact_i6_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross0;
  T cross1;
  T cross2;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
  }
  const T ab_bp = bp0 * ab0 + ab2 * bp2 + bp1 * ab1;
  const T ap_bp = ap2 * bp2 + bp1 * ap1 + bp0 * ap0;
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T zeta2 = T(1) - in.z * in.z * inv_R2;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = zeta2 - inv_R2 * ap_ap;
  const T h = cross2 * in.normal[2] + cross1 * in.normal[1] + in.normal[0] * cross0;
  const T theta = atan2(h, ap_bp);
  T J_minus6;
  T J_minus4;
  T J_minus2;
  T J_minus0;
  {
    // even degree: the integrand is a polynomial of degree 6, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 4> M_exact;
    segment_moments_gauss<T, 7>(-6, 0, 0, a, b, c, in.t0, in.t1, M_exact.data());
    J_minus6 = M_exact[0];
    J_minus4 = M_exact[1];
    J_minus2 = M_exact[2];
    J_minus0 = M_exact[3];
  }
  const T plane_slope0 = ab_ab * in.t0 - ab_ap;
  const T plane_slope1 = ab_ab * in.t1 - ab_ap;
  T theta_in;
  T G_f;
  T G_g;
  const T t1 = (T(1) / T(4)) * ab_ab * zeta2;
  const T t2 = t1 - h * h * inv_R2;
  const T t3 = max(T(t1 - min(T(plane_slope0 * plane_slope0), T(plane_slope1 * plane_slope1)) * inv_R2 - h * h * inv_R2), T(-plane_slope0 * plane_slope1));
  if (t2 >= T(0) && t3 >= T(0)) {
    // chord within half the disc radius of P̄: θ_in = atan2(…), G^(p) − w^p θ_in = −(h/R²) Σ_k w^k J_{−2(p−1−k)}
    const T t4 = in.t1 - T(1);
    theta_in = atan2(-h * (in.t0 - in.t1), ap_bp + ab_ab * in.t0 * t4 - ab_bp * in.t0 - t4 * ab_ap);
    const T t5 = zeta2 * zeta2;
    const T t6 = t5 * zeta2;
    G_f = -(J_minus4 * zeta2 + J_minus6 + J_minus2 * t5 + J_minus0 * t6) * h * inv_R2;
    G_g = -h * inv_R2 * (J_minus4 + J_minus0 * t5 + J_minus2 * zeta2);
  } else {
    // chord near the rim of the support disc: G^(p) = sgn(h) ∫ q^p du/(1 + u²), u = tan φ, polygon_edge_G_compact_chord (Gauss–Legendre panels)
    const T t7 = in.point[1] - in.a[1];
    const T t8 = in.point[2] - in.a[2];
    const T t9 = in.point[0] - in.a[0];
    const T t10 = (T(17) / T(16)) * in.R * in.R - t7 * t7 - t8 * t8 - t9 * t9;
    std::array<T, 1> gap_A{};  // 0 where the call is not made
    if (in.t0 <= T(0) && t10 >= T(0)) {
      exact_point_support_gap<T>(in.a[0], in.a[1], in.a[2], in.point[0], in.point[1], in.point[2], in.R, gap_A.data());
    }
    std::array<T, 1> gap_B{};  // 0 where the call is not made
    if (in.t1 >= T(1)) {
      exact_point_support_gap<T>(in.b[0], in.b[1], in.b[2], in.point[0], in.point[1], in.point[2], in.R, gap_B.data());
    }
    std::array<T, 2> G_chord;
    polygon_edge_G_compact_chord<T>(3, 4, h, ab_ab, zeta2, inv_R2, plane_slope0, plane_slope1, in.t0, in.t1, gap_A[0], gap_B[0], G_chord.data());
    theta_in = T(0);
    G_f = G_chord[1];
    G_g = G_chord[0];
  }
  out.h = h;
  out.theta = theta;
  out.theta_in = theta_in;
  out.S_f = G_f;
  out.S_g = G_g;
  out.J_g = J_minus6;
}

/// The terms of one edge for f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 − |P − Q|²/R²)^(8/2) dQ
/// Operations per edge: 103 +, 176 ×, 3 /, 0 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 859 +, 1194 ×, 92 /, 5 sqrt, 1 atan, 0 log/asinh.
template <class T>
void polygon_edge_compact_i8_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross0;
  T cross1;
  T cross2;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
  }
  const T ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T zeta2 = T(1) - inv_R2 * in.z * in.z;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = zeta2 - inv_R2 * ap_ap;
  const T h = cross2 * in.normal[2] + in.normal[0] * cross0 + in.normal[1] * cross1;
  const T theta = atan2(h, ap_bp);
  T J_minus8;
  T J_minus6;
  T J_minus4;
  T J_minus2;
  T J_minus0;
  {
    // even degree: the integrand is a polynomial of degree 8, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 5> M_exact;
    segment_moments_gauss<T, 7>(-8, 0, 0, a, b, c, in.t0, in.t1, M_exact.data());
    J_minus8 = M_exact[0];
    J_minus6 = M_exact[1];
    J_minus4 = M_exact[2];
    J_minus2 = M_exact[3];
    J_minus0 = M_exact[4];
  }
  const T plane_slope0 = ab_ab * in.t0 - ab_ap;
  const T plane_slope1 = ab_ab * in.t1 - ab_ap;
  T theta_in;
  T G_f;
  const T t1 = (T(1) / T(4)) * ab_ab * zeta2;
  const T t2 = t1 - h * h * inv_R2;
  const T t3 = max(T(t1 - inv_R2 * min(T(plane_slope0 * plane_slope0), T(plane_slope1 * plane_slope1)) - h * h * inv_R2), T(-plane_slope1 * plane_slope0));
  if (t2 >= T(0) && t3 >= T(0)) {
    // chord within half the disc radius of P̄: θ_in = atan2(…), G^(p) − w^p θ_in = −(h/R²) Σ_k w^k J_{−2(p−1−k)}
    const T t4 = in.t1 - T(1);
    theta_in = atan2(-h * (in.t0 - in.t1), ap_bp + ab_ab * t4 * in.t0 - in.t0 * ab_bp - ab_ap * t4);
    const T t5 = zeta2 * zeta2;
    const T t6 = t5 * t5;
    const T t7 = t5 * zeta2;
    G_f = -(J_minus8 + J_minus0 * t6 + t7 * J_minus2 + J_minus4 * t5 + J_minus6 * zeta2) * h * inv_R2;
  } else {
    // chord near the rim of the support disc: G^(p) = sgn(h) ∫ q^p du/(1 + u²), u = tan φ, polygon_edge_G_compact_chord (Gauss–Legendre panels)
    const T t8 = in.point[2] - in.a[2];
    const T t9 = in.point[1] - in.a[1];
    const T t10 = in.point[0] - in.a[0];
    const T t11 = (T(17) / T(16)) * in.R * in.R - t8 * t8 - t9 * t9 - t10 * t10;
    std::array<T, 1> gap_A{};  // 0 where the call is not made
    if (in.t0 <= T(0) && t11 >= T(0)) {
      exact_point_support_gap<T>(in.a[0], in.a[1], in.a[2], in.point[0], in.point[1], in.point[2], in.R, gap_A.data());
    }
    std::array<T, 1> gap_B{};  // 0 where the call is not made
    if (in.t1 >= T(1)) {
      exact_point_support_gap<T>(in.b[0], in.b[1], in.b[2], in.point[0], in.point[1], in.point[2], in.R, gap_B.data());
    }
    std::array<T, 1> G_chord;
    polygon_edge_G_compact_chord<T>(5, 5, h, ab_ab, zeta2, inv_R2, plane_slope0, plane_slope1, in.t0, in.t1, gap_A[0], gap_B[0], G_chord.data());
    theta_in = T(0);
    G_f = G_chord[0];
  }
  out.h = h;
  out.theta = theta;
  out.theta_in = theta_in;
  out.S_f = G_f;
}

/// The terms of one edge for ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 − |P − Q|²/R²)^(8/2) dQ
/// Operations per edge: 102 +, 174 ×, 3 /, 0 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 859 +, 1114 ×, 92 /, 5 sqrt, 1 atan, 0 log/asinh.
template <class T>
void polygon_edge_compact_i8_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ap0 * ab1;
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross0;
  T cross1;
  T cross2;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
  }
  const T ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  const T ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T zeta2 = T(1) - in.z * in.z * inv_R2;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = zeta2 - ap_ap * inv_R2;
  const T h = in.normal[1] * cross1 + in.normal[2] * cross2 + cross0 * in.normal[0];
  const T theta = atan2(h, ap_bp);
  T J_minus8;
  T J_minus6;
  T J_minus4;
  T J_minus2;
  T J_minus0;
  {
    // even degree: the integrand is a polynomial of degree 8, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 5> M_exact;
    segment_moments_gauss<T, 7>(-8, 0, 0, a, b, c, in.t0, in.t1, M_exact.data());
    J_minus8 = M_exact[0];
    J_minus6 = M_exact[1];
    J_minus4 = M_exact[2];
    J_minus2 = M_exact[3];
    J_minus0 = M_exact[4];
  }
  const T plane_slope0 = in.t0 * ab_ab - ab_ap;
  const T plane_slope1 = in.t1 * ab_ab - ab_ap;
  T theta_in;
  T G_g;
  const T t1 = (T(1) / T(4)) * zeta2 * ab_ab;
  const T t2 = t1 - h * h * inv_R2;
  const T t3 = max(T(t1 - h * h * inv_R2 - min(T(plane_slope0 * plane_slope0), T(plane_slope1 * plane_slope1)) * inv_R2), T(-plane_slope0 * plane_slope1));
  if (t2 >= T(0) && t3 >= T(0)) {
    // chord within half the disc radius of P̄: θ_in = atan2(…), G^(p) − w^p θ_in = −(h/R²) Σ_k w^k J_{−2(p−1−k)}
    const T t4 = in.t1 - T(1);
    theta_in = atan2(-h * (in.t0 - in.t1), ap_bp + in.t0 * ab_ab * t4 - t4 * ab_ap - in.t0 * ab_bp);
    const T t5 = zeta2 * zeta2;
    const T t6 = t5 * zeta2;
    G_g = -h * inv_R2 * (t6 * J_minus0 + J_minus4 * zeta2 + t5 * J_minus2 + J_minus6);
  } else {
    // chord near the rim of the support disc: G^(p) = sgn(h) ∫ q^p du/(1 + u²), u = tan φ, polygon_edge_G_compact_chord (Gauss–Legendre panels)
    const T t7 = in.a[0] - in.point[0];
    const T t8 = in.a[1] - in.point[1];
    const T t9 = in.point[2] - in.a[2];
    const T t10 = (T(17) / T(16)) * in.R * in.R - t7 * t7 - t8 * t8 - t9 * t9;
    std::array<T, 1> gap_A{};  // 0 where the call is not made
    if (in.t0 <= T(0) && t10 >= T(0)) {
      exact_point_support_gap<T>(in.a[0], in.a[1], in.a[2], in.point[0], in.point[1], in.point[2], in.R, gap_A.data());
    }
    std::array<T, 1> gap_B{};  // 0 where the call is not made
    if (in.t1 >= T(1)) {
      exact_point_support_gap<T>(in.b[0], in.b[1], in.b[2], in.point[0], in.point[1], in.point[2], in.R, gap_B.data());
    }
    std::array<T, 1> G_chord;
    polygon_edge_G_compact_chord<T>(4, 4, h, ab_ab, zeta2, inv_R2, plane_slope0, plane_slope1, in.t0, in.t1, gap_A[0], gap_B[0], G_chord.data());
    theta_in = T(0);
    G_g = G_chord[0];
  }
  out.h = h;
  out.theta = theta;
  out.theta_in = theta_in;
  out.S_g = G_g;
  out.J_g = J_minus8;
}

/// The terms of one edge for f and ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 − |P − Q|²/R²)^(8/2) dQ
/// Operations per edge: 106 +, 181 ×, 3 /, 0 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 939 +, 1274 ×, 92 /, 5 sqrt, 1 atan, 0 log/asinh.
template <class T>
void polygon_edge_compact_i8_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
  }
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T zeta2 = T(1) - in.z * in.z * inv_R2;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = zeta2 - inv_R2 * ap_ap;
  const T h = in.normal[0] * cross0 + cross1 * in.normal[1] + cross2 * in.normal[2];
  const T theta = atan2(h, ap_bp);
  T J_minus8;
  T J_minus6;
  T J_minus4;
  T J_minus2;
  T J_minus0;
  {
    // even degree: the integrand is a polynomial of degree 8, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 5> M_exact;
    segment_moments_gauss<T, 7>(-8, 0, 0, a, b, c, in.t0, in.t1, M_exact.data());
    J_minus8 = M_exact[0];
    J_minus6 = M_exact[1];
    J_minus4 = M_exact[2];
    J_minus2 = M_exact[3];
    J_minus0 = M_exact[4];
  }
  const T plane_slope0 = ab_ab * in.t0 - ab_ap;
  const T plane_slope1 = in.t1 * ab_ab - ab_ap;
  T theta_in;
  T G_f;
  T G_g;
  const T t1 = (T(1) / T(4)) * ab_ab * zeta2;
  const T t2 = t1 - inv_R2 * h * h;
  const T t3 = max(T(t1 - inv_R2 * h * h - min(T(plane_slope0 * plane_slope0), T(plane_slope1 * plane_slope1)) * inv_R2), T(-plane_slope1 * plane_slope0));
  if (t2 >= T(0) && t3 >= T(0)) {
    // chord within half the disc radius of P̄: θ_in = atan2(…), G^(p) − w^p θ_in = −(h/R²) Σ_k w^k J_{−2(p−1−k)}
    const T t4 = in.t1 - T(1);
    theta_in = atan2(h * (in.t1 - in.t0), t4 * ab_ab * in.t0 + ap_bp - t4 * ab_ap - ab_bp * in.t0);
    const T t5 = zeta2 * zeta2;
    const T t6 = t5 * zeta2;
    const T t7 = t5 * t5;
    G_f = -inv_R2 * (J_minus2 * t6 + J_minus8 + J_minus0 * t7 + J_minus6 * zeta2 + t5 * J_minus4) * h;
    G_g = -(zeta2 * J_minus4 + J_minus2 * t5 + J_minus0 * t6 + J_minus6) * inv_R2 * h;
  } else {
    // chord near the rim of the support disc: G^(p) = sgn(h) ∫ q^p du/(1 + u²), u = tan φ, polygon_edge_G_compact_chord (Gauss–Legendre panels)
    const T t8 = in.point[2] - in.a[2];
    const T t9 = in.point[0] - in.a[0];
    const T t10 = in.point[1] - in.a[1];
    const T t11 = (T(17) / T(16)) * in.R * in.R - t8 * t8 - t9 * t9 - t10 * t10;
    std::array<T, 1> gap_A{};  // 0 where the call is not made
    if (in.t0 <= T(0) && t11 >= T(0)) {
      exact_point_support_gap<T>(in.a[0], in.a[1], in.a[2], in.point[0], in.point[1], in.point[2], in.R, gap_A.data());
    }
    std::array<T, 1> gap_B{};  // 0 where the call is not made
    if (in.t1 >= T(1)) {
      exact_point_support_gap<T>(in.b[0], in.b[1], in.b[2], in.point[0], in.point[1], in.point[2], in.R, gap_B.data());
    }
    std::array<T, 2> G_chord;
    polygon_edge_G_compact_chord<T>(4, 5, h, ab_ab, zeta2, inv_R2, plane_slope0, plane_slope1, in.t0, in.t1, gap_A[0], gap_B[0], G_chord.data());
    theta_in = T(0);
    G_f = G_chord[1];
    G_g = G_chord[0];
  }
  out.h = h;
  out.theta = theta;
  out.theta_in = theta_in;
  out.S_f = G_f;
  out.S_g = G_g;
  out.J_g = J_minus8;
}

/// The terms of one edge for f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 − |P − Q|²/R²)^(10/2) dQ
/// Operations per edge: 111 +, 192 ×, 3 /, 0 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 866 +, 1288 ×, 92 /, 5 sqrt, 1 atan, 0 log/asinh.
template <class T>
void polygon_edge_compact_i10_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  const T plain_cross0 = ap2 * ab1 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ap2 * ab0;
  const T plain_cross2 = ap1 * ab0 - ap0 * ab1;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross0;
  T cross1;
  T cross2;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
  }
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T zeta2 = T(1) - inv_R2 * in.z * in.z;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = zeta2 - inv_R2 * ap_ap;
  const T h = cross2 * in.normal[2] + cross0 * in.normal[0] + in.normal[1] * cross1;
  const T theta = atan2(h, ap_bp);
  T J_minus10;
  T J_minus8;
  T J_minus6;
  T J_minus4;
  T J_minus2;
  T J_minus0;
  {
    // even degree: the integrand is a polynomial of degree 10, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 6> M_exact;
    segment_moments_gauss<T, 7>(-10, 0, 0, a, b, c, in.t0, in.t1, M_exact.data());
    J_minus10 = M_exact[0];
    J_minus8 = M_exact[1];
    J_minus6 = M_exact[2];
    J_minus4 = M_exact[3];
    J_minus2 = M_exact[4];
    J_minus0 = M_exact[5];
  }
  const T plane_slope0 = in.t0 * ab_ab - ab_ap;
  const T plane_slope1 = in.t1 * ab_ab - ab_ap;
  T theta_in;
  T G_f;
  const T t1 = (T(1) / T(4)) * zeta2 * ab_ab;
  const T t2 = t1 - h * h * inv_R2;
  const T t3 = max(T(t1 - inv_R2 * min(T(plane_slope0 * plane_slope0), T(plane_slope1 * plane_slope1)) - h * h * inv_R2), T(-plane_slope0 * plane_slope1));
  if (t2 >= T(0) && t3 >= T(0)) {
    // chord within half the disc radius of P̄: θ_in = atan2(…), G^(p) − w^p θ_in = −(h/R²) Σ_k w^k J_{−2(p−1−k)}
    const T t4 = in.t1 - T(1);
    theta_in = atan2(-h * (in.t0 - in.t1), ap_bp + in.t0 * t4 * ab_ab - in.t0 * ab_bp - ab_ap * t4);
    const T t5 = zeta2 * zeta2;
    const T t6 = t5 * zeta2;
    const T t7 = t5 * t5;
    const T t8 = t7 * zeta2;
    G_f = -h * inv_R2 * (t6 * J_minus4 + t7 * J_minus2 + J_minus0 * t8 + J_minus10 + J_minus8 * zeta2 + J_minus6 * t5);
  } else {
    // chord near the rim of the support disc: G^(p) = sgn(h) ∫ q^p du/(1 + u²), u = tan φ, polygon_edge_G_compact_chord (Gauss–Legendre panels)
    const T t9 = in.point[0] - in.a[0];
    const T t10 = in.point[2] - in.a[2];
    const T t11 = in.point[1] - in.a[1];
    const T t12 = (T(17) / T(16)) * in.R * in.R - t9 * t9 - t10 * t10 - t11 * t11;
    std::array<T, 1> gap_A{};  // 0 where the call is not made
    if (in.t0 <= T(0) && t12 >= T(0)) {
      exact_point_support_gap<T>(in.a[0], in.a[1], in.a[2], in.point[0], in.point[1], in.point[2], in.R, gap_A.data());
    }
    std::array<T, 1> gap_B{};  // 0 where the call is not made
    if (in.t1 >= T(1)) {
      exact_point_support_gap<T>(in.b[0], in.b[1], in.b[2], in.point[0], in.point[1], in.point[2], in.R, gap_B.data());
    }
    std::array<T, 1> G_chord;
    polygon_edge_G_compact_chord<T>(6, 6, h, ab_ab, zeta2, inv_R2, plane_slope0, plane_slope1, in.t0, in.t1, gap_A[0], gap_B[0], G_chord.data());
    theta_in = T(0);
    G_f = G_chord[0];
  }
  out.h = h;
  out.theta = theta;
  out.theta_in = theta_in;
  out.S_f = G_f;
}

/// The terms of one edge for ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 − |P − Q|²/R²)^(10/2) dQ
/// Operations per edge: 110 +, 191 ×, 3 /, 0 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 866 +, 1208 ×, 92 /, 5 sqrt, 1 atan, 0 log/asinh.
template <class T>
void polygon_edge_compact_i10_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T plain_cross0 = ab1 * ap2 - ab2 * ap1;
  const T plain_cross1 = ab2 * ap0 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ab1 * ap0;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross0;
  T cross1;
  T cross2;
  const T t0 = T(256) * plain_cross_cross - ab_ab * ap_ap;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
  }
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T zeta2 = T(1) - in.z * in.z * inv_R2;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = zeta2 - inv_R2 * ap_ap;
  const T h = cross2 * in.normal[2] + in.normal[0] * cross0 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  T J_minus10;
  T J_minus8;
  T J_minus6;
  T J_minus4;
  T J_minus2;
  T J_minus0;
  {
    // even degree: the integrand is a polynomial of degree 10, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 6> M_exact;
    segment_moments_gauss<T, 7>(-10, 0, 0, a, b, c, in.t0, in.t1, M_exact.data());
    J_minus10 = M_exact[0];
    J_minus8 = M_exact[1];
    J_minus6 = M_exact[2];
    J_minus4 = M_exact[3];
    J_minus2 = M_exact[4];
    J_minus0 = M_exact[5];
  }
  const T plane_slope0 = in.t0 * ab_ab - ab_ap;
  const T plane_slope1 = in.t1 * ab_ab - ab_ap;
  T theta_in;
  T G_g;
  const T t1 = (T(1) / T(4)) * ab_ab * zeta2;
  const T t2 = t1 - h * h * inv_R2;
  const T t3 = max(T(t1 - min(T(plane_slope0 * plane_slope0), T(plane_slope1 * plane_slope1)) * inv_R2 - h * h * inv_R2), T(-plane_slope0 * plane_slope1));
  if (t2 >= T(0) && t3 >= T(0)) {
    // chord within half the disc radius of P̄: θ_in = atan2(…), G^(p) − w^p θ_in = −(h/R²) Σ_k w^k J_{−2(p−1−k)}
    const T t4 = in.t1 - T(1);
    theta_in = atan2(-h * (in.t0 - in.t1), ap_bp + in.t0 * ab_ab * t4 - t4 * ab_ap - in.t0 * ab_bp);
    const T t5 = zeta2 * zeta2;
    const T t6 = t5 * zeta2;
    const T t7 = t5 * t5;
    G_g = -h * inv_R2 * (J_minus4 * zeta2 * zeta2 + J_minus2 * t6 + J_minus0 * t7 + J_minus8 + J_minus6 * zeta2);
  } else {
    // chord near the rim of the support disc: G^(p) = sgn(h) ∫ q^p du/(1 + u²), u = tan φ, polygon_edge_G_compact_chord (Gauss–Legendre panels)
    const T t8 = in.point[2] - in.a[2];
    const T t9 = in.point[0] - in.a[0];
    const T t10 = in.point[1] - in.a[1];
    const T t11 = (T(17) / T(16)) * in.R * in.R - t8 * t8 - t9 * t9 - t10 * t10;
    std::array<T, 1> gap_A{};  // 0 where the call is not made
    if (in.t0 <= T(0) && t11 >= T(0)) {
      exact_point_support_gap<T>(in.a[0], in.a[1], in.a[2], in.point[0], in.point[1], in.point[2], in.R, gap_A.data());
    }
    std::array<T, 1> gap_B{};  // 0 where the call is not made
    if (in.t1 >= T(1)) {
      exact_point_support_gap<T>(in.b[0], in.b[1], in.b[2], in.point[0], in.point[1], in.point[2], in.R, gap_B.data());
    }
    std::array<T, 1> G_chord;
    polygon_edge_G_compact_chord<T>(5, 5, h, ab_ab, zeta2, inv_R2, plane_slope0, plane_slope1, in.t0, in.t1, gap_A[0], gap_B[0], G_chord.data());
    theta_in = T(0);
    G_g = G_chord[0];
  }
  out.h = h;
  out.theta = theta;
  out.theta_in = theta_in;
  out.S_g = G_g;
  out.J_g = J_minus10;
}

/// The terms of one edge for f and ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 − |P − Q|²/R²)^(10/2) dQ
/// Operations per edge: 115 +, 198 ×, 3 /, 0 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 946 +, 1368 ×, 92 /, 5 sqrt, 1 atan, 0 log/asinh.
template <class T>
void polygon_edge_compact_i10_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
  }
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T zeta2 = T(1) - inv_R2 * in.z * in.z;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = zeta2 - inv_R2 * ap_ap;
  const T h = cross0 * in.normal[0] + cross1 * in.normal[1] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  T J_minus10;
  T J_minus8;
  T J_minus6;
  T J_minus4;
  T J_minus2;
  T J_minus0;
  {
    // even degree: the integrand is a polynomial of degree 10, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 6> M_exact;
    segment_moments_gauss<T, 7>(-10, 0, 0, a, b, c, in.t0, in.t1, M_exact.data());
    J_minus10 = M_exact[0];
    J_minus8 = M_exact[1];
    J_minus6 = M_exact[2];
    J_minus4 = M_exact[3];
    J_minus2 = M_exact[4];
    J_minus0 = M_exact[5];
  }
  const T plane_slope0 = in.t0 * ab_ab - ab_ap;
  const T plane_slope1 = in.t1 * ab_ab - ab_ap;
  T theta_in;
  T G_f;
  T G_g;
  const T t1 = (T(1) / T(4)) * zeta2 * ab_ab;
  const T t2 = t1 - h * h * inv_R2;
  const T t3 = max(T(t1 - h * h * inv_R2 - inv_R2 * min(T(plane_slope0 * plane_slope0), T(plane_slope1 * plane_slope1))), T(-plane_slope0 * plane_slope1));
  if (t2 >= T(0) && t3 >= T(0)) {
    // chord within half the disc radius of P̄: θ_in = atan2(…), G^(p) − w^p θ_in = −(h/R²) Σ_k w^k J_{−2(p−1−k)}
    const T t4 = in.t1 - T(1);
    theta_in = atan2(-h * (in.t0 - in.t1), t4 * in.t0 * ab_ab + ap_bp - in.t0 * ab_bp - ab_ap * t4);
    const T t5 = zeta2 * zeta2;
    const T t6 = t5 * zeta2;
    const T t7 = t5 * t5;
    const T t8 = t7 * zeta2;
    G_f = -h * inv_R2 * (t6 * J_minus4 + zeta2 * J_minus8 + J_minus0 * t8 + t7 * J_minus2 + J_minus10 + J_minus6 * t5);
    G_g = -h * inv_R2 * (J_minus0 * t7 + t5 * J_minus4 + t6 * J_minus2 + J_minus6 * zeta2 + J_minus8);
  } else {
    // chord near the rim of the support disc: G^(p) = sgn(h) ∫ q^p du/(1 + u²), u = tan φ, polygon_edge_G_compact_chord (Gauss–Legendre panels)
    const T t9 = in.point[0] - in.a[0];
    const T t10 = in.point[2] - in.a[2];
    const T t11 = in.a[1] - in.point[1];
    const T t12 = (T(17) / T(16)) * in.R * in.R - t9 * t9 - t10 * t10 - t11 * t11;
    std::array<T, 1> gap_A{};  // 0 where the call is not made
    if (in.t0 <= T(0) && t12 >= T(0)) {
      exact_point_support_gap<T>(in.a[0], in.a[1], in.a[2], in.point[0], in.point[1], in.point[2], in.R, gap_A.data());
    }
    std::array<T, 1> gap_B{};  // 0 where the call is not made
    if (in.t1 >= T(1)) {
      exact_point_support_gap<T>(in.b[0], in.b[1], in.b[2], in.point[0], in.point[1], in.point[2], in.R, gap_B.data());
    }
    std::array<T, 2> G_chord;
    polygon_edge_G_compact_chord<T>(5, 6, h, ab_ab, zeta2, inv_R2, plane_slope0, plane_slope1, in.t0, in.t1, gap_A[0], gap_B[0], G_chord.data());
    theta_in = T(0);
    G_f = G_chord[1];
    G_g = G_chord[0];
  }
  out.h = h;
  out.theta = theta;
  out.theta_in = theta_in;
  out.S_f = G_f;
  out.S_g = G_g;
  out.J_g = J_minus10;
}

/// The terms of one edge for f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 − |P − Q|²/R²)^(12/2) dQ
/// Operations per edge: 119 +, 208 ×, 3 /, 0 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 873 +, 1382 ×, 92 /, 5 sqrt, 1 atan, 0 log/asinh.
template <class T>
void polygon_edge_compact_i12_f(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T plain_cross0 = ap2 * ab1 - ap1 * ab2;
  const T plain_cross1 = ap0 * ab2 - ab0 * ap2;
  const T plain_cross2 = ab0 * ap1 - ap0 * ab1;
  const T plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  T cross0;
  T cross1;
  T cross2;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
  }
  const T ab_bp = ab0 * bp0 + bp2 * ab2 + bp1 * ab1;
  const T ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T zeta2 = T(1) - inv_R2 * in.z * in.z;
  const T a = -inv_R2 * ab_ab;
  const T b = -inv_R2 * ab_ap;
  const T c = zeta2 - inv_R2 * ap_ap;
  const T h = in.normal[2] * cross2 + in.normal[1] * cross1 + cross0 * in.normal[0];
  const T theta = atan2(h, ap_bp);
  T J_minus12;
  T J_minus10;
  T J_minus8;
  T J_minus6;
  T J_minus4;
  T J_minus2;
  T J_minus0;
  {
    // even degree: the integrand is a polynomial of degree 12, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 7> M_exact;
    segment_moments_gauss<T, 7>(-12, 0, 0, a, b, c, in.t0, in.t1, M_exact.data());
    J_minus12 = M_exact[0];
    J_minus10 = M_exact[1];
    J_minus8 = M_exact[2];
    J_minus6 = M_exact[3];
    J_minus4 = M_exact[4];
    J_minus2 = M_exact[5];
    J_minus0 = M_exact[6];
  }
  const T plane_slope0 = in.t0 * ab_ab - ab_ap;
  const T plane_slope1 = in.t1 * ab_ab - ab_ap;
  T theta_in;
  T G_f;
  const T t1 = (T(1) / T(4)) * zeta2 * ab_ab;
  const T t2 = t1 - h * h * inv_R2;
  const T t3 = max(T(t1 - inv_R2 * min(T(plane_slope0 * plane_slope0), T(plane_slope1 * plane_slope1)) - h * h * inv_R2), T(-plane_slope0 * plane_slope1));
  if (t2 >= T(0) && t3 >= T(0)) {
    // chord within half the disc radius of P̄: θ_in = atan2(…), G^(p) − w^p θ_in = −(h/R²) Σ_k w^k J_{−2(p−1−k)}
    const T t4 = in.t1 - T(1);
    theta_in = atan2(-h * (in.t0 - in.t1), t4 * in.t0 * ab_ab + ap_bp - ab_ap * t4 - in.t0 * ab_bp);
    const T t5 = zeta2 * zeta2;
    const T t6 = t5 * t5;
    const T t7 = t6 * zeta2;
    const T t8 = t5 * zeta2;
    const T t9 = t8 * t8;
    G_f = -h * inv_R2 * (t7 * J_minus2 + zeta2 * J_minus10 + t8 * J_minus6 + t6 * J_minus4 + J_minus12 + J_minus8 * t5 + J_minus0 * t9);
  } else {
    // chord near the rim of the support disc: G^(p) = sgn(h) ∫ q^p du/(1 + u²), u = tan φ, polygon_edge_G_compact_chord (Gauss–Legendre panels)
    const T t10 = in.point[1] - in.a[1];
    const T t11 = in.point[2] - in.a[2];
    const T t12 = in.point[0] - in.a[0];
    const T t13 = (T(17) / T(16)) * in.R * in.R - t10 * t10 - t11 * t11 - t12 * t12;
    std::array<T, 1> gap_A{};  // 0 where the call is not made
    if (in.t0 <= T(0) && t13 >= T(0)) {
      exact_point_support_gap<T>(in.a[0], in.a[1], in.a[2], in.point[0], in.point[1], in.point[2], in.R, gap_A.data());
    }
    std::array<T, 1> gap_B{};  // 0 where the call is not made
    if (in.t1 >= T(1)) {
      exact_point_support_gap<T>(in.b[0], in.b[1], in.b[2], in.point[0], in.point[1], in.point[2], in.R, gap_B.data());
    }
    std::array<T, 1> G_chord;
    polygon_edge_G_compact_chord<T>(7, 7, h, ab_ab, zeta2, inv_R2, plane_slope0, plane_slope1, in.t0, in.t1, gap_A[0], gap_B[0], G_chord.data());
    theta_in = T(0);
    G_f = G_chord[0];
  }
  out.h = h;
  out.theta = theta;
  out.theta_in = theta_in;
  out.S_f = G_f;
}

/// The terms of one edge for ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 − |P − Q|²/R²)^(12/2) dQ
/// Operations per edge: 118 +, 206 ×, 3 /, 0 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 873 +, 1302 ×, 92 /, 5 sqrt, 1 atan, 0 log/asinh.
template <class T>
void polygon_edge_compact_i12_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  T cross0;
  T cross1;
  T cross2;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
  }
  const T ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  const T ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T zeta2 = T(1) - in.z * in.z * inv_R2;
  const T a = -ab_ab * inv_R2;
  const T b = -inv_R2 * ab_ap;
  const T c = zeta2 - ap_ap * inv_R2;
  const T h = in.normal[0] * cross0 + in.normal[2] * cross2 + cross1 * in.normal[1];
  const T theta = atan2(h, ap_bp);
  T J_minus12;
  T J_minus10;
  T J_minus8;
  T J_minus6;
  T J_minus4;
  T J_minus2;
  T J_minus0;
  {
    // even degree: the integrand is a polynomial of degree 12, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 7> M_exact;
    segment_moments_gauss<T, 7>(-12, 0, 0, a, b, c, in.t0, in.t1, M_exact.data());
    J_minus12 = M_exact[0];
    J_minus10 = M_exact[1];
    J_minus8 = M_exact[2];
    J_minus6 = M_exact[3];
    J_minus4 = M_exact[4];
    J_minus2 = M_exact[5];
    J_minus0 = M_exact[6];
  }
  const T plane_slope0 = ab_ab * in.t0 - ab_ap;
  const T plane_slope1 = ab_ab * in.t1 - ab_ap;
  T theta_in;
  T G_g;
  const T t1 = (T(1) / T(4)) * zeta2 * ab_ab;
  const T t2 = t1 - h * h * inv_R2;
  const T t3 = max(T(t1 - h * h * inv_R2 - inv_R2 * min(T(plane_slope0 * plane_slope0), T(plane_slope1 * plane_slope1))), T(-plane_slope0 * plane_slope1));
  if (t2 >= T(0) && t3 >= T(0)) {
    // chord within half the disc radius of P̄: θ_in = atan2(…), G^(p) − w^p θ_in = −(h/R²) Σ_k w^k J_{−2(p−1−k)}
    const T t4 = in.t1 - T(1);
    theta_in = atan2(-(in.t0 - in.t1) * h, t4 * ab_ab * in.t0 + ap_bp - ab_bp * in.t0 - t4 * ab_ap);
    const T t5 = zeta2 * zeta2;
    const T t6 = t5 * zeta2;
    const T t7 = t5 * t5;
    const T t8 = t7 * zeta2;
    G_g = -(t6 * J_minus4 + t8 * J_minus0 + J_minus10 + zeta2 * J_minus8 + t5 * J_minus6 + t7 * J_minus2) * h * inv_R2;
  } else {
    // chord near the rim of the support disc: G^(p) = sgn(h) ∫ q^p du/(1 + u²), u = tan φ, polygon_edge_G_compact_chord (Gauss–Legendre panels)
    const T t9 = in.point[1] - in.a[1];
    const T t10 = in.point[2] - in.a[2];
    const T t11 = in.point[0] - in.a[0];
    const T t12 = (T(17) / T(16)) * in.R * in.R - t9 * t9 - t10 * t10 - t11 * t11;
    std::array<T, 1> gap_A{};  // 0 where the call is not made
    if (in.t0 <= T(0) && t12 >= T(0)) {
      exact_point_support_gap<T>(in.a[0], in.a[1], in.a[2], in.point[0], in.point[1], in.point[2], in.R, gap_A.data());
    }
    std::array<T, 1> gap_B{};  // 0 where the call is not made
    if (in.t1 >= T(1)) {
      exact_point_support_gap<T>(in.b[0], in.b[1], in.b[2], in.point[0], in.point[1], in.point[2], in.R, gap_B.data());
    }
    std::array<T, 1> G_chord;
    polygon_edge_G_compact_chord<T>(6, 6, h, ab_ab, zeta2, inv_R2, plane_slope0, plane_slope1, in.t0, in.t1, gap_A[0], gap_B[0], G_chord.data());
    theta_in = T(0);
    G_g = G_chord[0];
  }
  out.h = h;
  out.theta = theta;
  out.theta_in = theta_in;
  out.S_g = G_g;
  out.J_g = J_minus12;
}

/// The terms of one edge for f and ∇f (skelconv/primitives/polygon_field.hpp adds them up), where
///     C(P) = ∬_Ω (1 − |P − Q|²/R²)^(12/2) dQ
/// Operations per edge: 124 +, 215 ×, 3 /, 0 sqrt, 2 atan, 0 log/asinh (generic form).
/// Longest path: 953 +, 1462 ×, 92 /, 5 sqrt, 1 atan, 0 log/asinh.
template <class T>
void polygon_edge_compact_i12_f_and_grad(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {
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
  const T plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  T cross0;
  T cross1;
  T cross2;
  const T t0 = T(256) * plain_cross_cross - ap_ap * ab_ab;
  if (t0 >= T(0)) {
    // P away from the line (sin∠(AB, AP) ≥ 1/16)
    cross0 = plain_cross0;
    cross1 = plain_cross1;
    cross2 = plain_cross2;
  } else {
    // P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)
    std::array<T, 3> exact_cross;
    segment_exact_cross<T>(in.a[0], in.a[1], in.a[2], in.b[0], in.b[1], in.b[2], in.p[0], in.p[1], in.p[2], exact_cross.data());
    cross0 = exact_cross[0];
    cross1 = exact_cross[1];
    cross2 = exact_cross[2];
  }
  const T ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  const T ap_bp = bp1 * ap1 + bp2 * ap2 + ap0 * bp0;
  const T inv_R = T(1) / in.R;
  const T inv_R2 = inv_R * inv_R;
  const T zeta2 = T(1) - in.z * in.z * inv_R2;
  const T a = -ab_ab * inv_R2;
  const T b = -ab_ap * inv_R2;
  const T c = zeta2 - ap_ap * inv_R2;
  const T h = cross1 * in.normal[1] + cross0 * in.normal[0] + in.normal[2] * cross2;
  const T theta = atan2(h, ap_bp);
  T J_minus12;
  T J_minus10;
  T J_minus8;
  T J_minus6;
  T J_minus4;
  T J_minus2;
  T J_minus0;
  {
    // even degree: the integrand is a polynomial of degree 12, integrated exactly by segment_moments_gauss<T, 7>
    std::array<T, 7> M_exact;
    segment_moments_gauss<T, 7>(-12, 0, 0, a, b, c, in.t0, in.t1, M_exact.data());
    J_minus12 = M_exact[0];
    J_minus10 = M_exact[1];
    J_minus8 = M_exact[2];
    J_minus6 = M_exact[3];
    J_minus4 = M_exact[4];
    J_minus2 = M_exact[5];
    J_minus0 = M_exact[6];
  }
  const T plane_slope0 = ab_ab * in.t0 - ab_ap;
  const T plane_slope1 = ab_ab * in.t1 - ab_ap;
  T theta_in;
  T G_f;
  T G_g;
  const T t1 = (T(1) / T(4)) * zeta2 * ab_ab;
  const T t2 = t1 - h * h * inv_R2;
  const T t3 = max(T(t1 - h * h * inv_R2 - min(T(plane_slope0 * plane_slope0), T(plane_slope1 * plane_slope1)) * inv_R2), T(-plane_slope0 * plane_slope1));
  if (t2 >= T(0) && t3 >= T(0)) {
    // chord within half the disc radius of P̄: θ_in = atan2(…), G^(p) − w^p θ_in = −(h/R²) Σ_k w^k J_{−2(p−1−k)}
    const T t4 = in.t1 - T(1);
    theta_in = atan2(-(in.t0 - in.t1) * h, ap_bp + ab_ab * t4 * in.t0 - ab_bp * in.t0 - t4 * ab_ap);
    const T t5 = zeta2 * zeta2;
    const T t6 = t5 * t5;
    const T t7 = t6 * zeta2;
    const T t8 = t5 * zeta2;
    const T t9 = t8 * t8;
    G_f = -(t7 * J_minus2 + t9 * J_minus0 + J_minus12 + t6 * J_minus4 + zeta2 * J_minus10 + t8 * J_minus6 + t5 * J_minus8) * h * inv_R2;
    G_g = -(zeta2 * J_minus8 + t7 * J_minus0 + t6 * J_minus2 + t8 * J_minus4 + t5 * J_minus6 + J_minus10) * h * inv_R2;
  } else {
    // chord near the rim of the support disc: G^(p) = sgn(h) ∫ q^p du/(1 + u²), u = tan φ, polygon_edge_G_compact_chord (Gauss–Legendre panels)
    const T t10 = in.point[0] - in.a[0];
    const T t11 = in.point[1] - in.a[1];
    const T t12 = in.point[2] - in.a[2];
    const T t13 = (T(17) / T(16)) * in.R * in.R - t10 * t10 - t11 * t11 - t12 * t12;
    std::array<T, 1> gap_A{};  // 0 where the call is not made
    if (in.t0 <= T(0) && t13 >= T(0)) {
      exact_point_support_gap<T>(in.a[0], in.a[1], in.a[2], in.point[0], in.point[1], in.point[2], in.R, gap_A.data());
    }
    std::array<T, 1> gap_B{};  // 0 where the call is not made
    if (in.t1 >= T(1)) {
      exact_point_support_gap<T>(in.b[0], in.b[1], in.b[2], in.point[0], in.point[1], in.point[2], in.R, gap_B.data());
    }
    std::array<T, 2> G_chord;
    polygon_edge_G_compact_chord<T>(6, 7, h, ab_ab, zeta2, inv_R2, plane_slope0, plane_slope1, in.t0, in.t1, gap_A[0], gap_B[0], G_chord.data());
    theta_in = T(0);
    G_f = G_chord[1];
    G_g = G_chord[0];
  }
  out.h = h;
  out.theta = theta;
  out.theta_in = theta_in;
  out.S_f = G_f;
  out.S_g = G_g;
  out.J_g = J_minus12;
}

}  // namespace skelconv::generated
