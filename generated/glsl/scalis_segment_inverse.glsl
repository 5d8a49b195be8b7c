// generated/glsl/scalis_segment_inverse.glsl - SCALIS segment kernels of the inverse family in GLSL (float; ES 3.00 and 4.50), generic forms only.
//
// GENERATED FILE: DO NOT EDIT. Regenerate with
//     skelconv-codegen --inverse 1:16 --cauchy 1:16 --compact 2:16 --weights 0:3 --polygon-inverse 3:12 --polygon-cauchy 3:12 --polygon-compact 4:12 --scalis-inverse 2:10 --scalis-cauchy 2:10 --out generated
// Generator: skelconv-codegen 0.1.0 (GiNaC 1.8.6)
// From: codegen/segment_families.cpp (the families) and codegen/segment_moments.cpp
// (recurrence (1) of Hubert & Cani unrolled; SPEC sec. 2, Hubert 2012 sec. 3).
// Unnormalised, as generated/scalis_segment_inverse.hpp: f = c F / h is the caller's
// (skelconv/primitives/scalis_segment.hpp).

#ifndef SKELCONV_SCALIS_SEGMENT_INPUT
#define SKELCONV_SCALIS_SEGMENT_INPUT
// The segment AB, the query point p, the radii tau0 at A and tau1 at B
// (>= 0, not both 0) and the kernel scale sigma (SPEC sec. 4).
struct ScalisSegmentInput {
  vec3 a;
  vec3 b;
  vec3 p;
  float tau0;
  float tau1;
  float sigma;
};
#endif

#ifndef SKELCONV_GLSL_HELPERS
#define SKELCONV_GLSL_HELPERS
// asinh without the losses of log(x + sqrt(x^2 + 1)), the form GPU
// libraries may use: odd symmetry (no cancellation for x < 0), log1p of
// u = |x| + x^2 / (1 + sqrt(1 + x^2)) by Kahan's log(1 + u) u / ((1 + u) - 1)
// (no loss for small |x|), and log(2|x|) where x^2 would overflow (|x| >
// 1e18: there sqrt(1 + x^2) = |x| in float).
float skelconv_asinh(float x) {
  float ax = abs(x);
  if (ax > 1e18) return sign(x) * (log(ax) + 0.69314718);
  float u = ax + ax * ax / (1.0 + sqrt(1.0 + ax * ax));
  float w = 1.0 + u;
  float l = w == 1.0 ? u : log(w) * u / (w - 1.0);
  return sign(x) * l;
}
#endif

// the field, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (d/sigma)^(-2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^2 |AB| int_0^1 tau^1 (|P - Gamma|^2)^(-2/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 27 +, 32 *, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float scalis_segment_inverse_i2_f(ScalisSegmentInput si) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float ab0 = end_b[0] - end_a[0];
  float ap0 = si.p[0] - end_a[0];
  float bp0 = si.p[0] - end_b[0];
  float ab1 = end_b[1] - end_a[1];
  float ap1 = si.p[1] - end_a[1];
  float bp1 = si.p[1] - end_b[1];
  float ab2 = end_b[2] - end_a[2];
  float ap2 = si.p[2] - end_a[2];
  float bp2 = si.p[2] - end_b[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  float ab_ap = ap0 * ab0 + ab2 * ap2 + ab1 * ap1;
  float ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ap0 * ab1;
  float plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ap_bp = bp1 * ap1 + ap0 * bp0 + bp2 * ap2;
  float length = sqrt(ab_ab);
  float log_ratio = log(bp_bp / ap_ap);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float J2 = atan(t0, ap_bp) / t0;
    F = tau_lo * J2 + (float(1) / float(2)) * delta_tau * (float(2) * J2 * ab_ap + log_ratio) / ab_ab;
  }
  f = si.sigma * si.sigma * F * length;
  return f;
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (d/sigma)^(-2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^2 |AB| int_0^1 tau^1 (|P - Gamma|^2)^(-2/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 43 +, 71 *, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float scalis_segment_inverse_i2_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float ab0 = end_b[0] - end_a[0];
  float ap0 = si.p[0] - end_a[0];
  float bp0 = si.p[0] - end_b[0];
  float ab1 = end_b[1] - end_a[1];
  float ap1 = si.p[1] - end_a[1];
  float bp1 = si.p[1] - end_b[1];
  float ab2 = end_b[2] - end_a[2];
  float ap2 = si.p[2] - end_a[2];
  float bp2 = si.p[2] - end_b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ab2 * ap0 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  float foot0;
  float foot1;
  float foot2;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
    float t0 = float(1) / ab_ab;
    foot0 = ap0 - t0 * ab0 * ab_ap;
    foot1 = ap1 - t0 * ab1 * ab_ap;
    foot2 = ap2 - t0 * ab2 * ab_ap;
  }
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = ab2 * bp2 + bp0 * ab0 + bp1 * ab1;
  float ap_bp = ap2 * bp2 + bp1 * ap1 + bp0 * ap0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float t1 = float(1) / ap_ap;
  float log_ratio = log(bp_bp * t1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t2 = sqrt(cross_cross);
    float t3 = float(1) / t2;
    float J2 = atan(t2, ap_bp) * t3;
    float t4 = float(1) / ab_ab;
    F = tau_lo * J2 + (float(1) / float(2)) * delta_tau * t4 * (log_ratio + float(2) * ab_ap * J2);
    float t5 = float(1) / cross_cross;
    float t6 = float(1) / bp_bp;
    float t7 = t6 * a_minus_b + ab_ab * J2 + ab_ap * t1;
    G_ap = (float(1) / float(2)) * tau_lo * t5 * t7 + (float(1) / float(2)) * delta_tau * t4 * (t1 + t5 * t7 * ab_ap - t6);
    G_E = (float(1) / float(2)) * t4 * (delta_tau * J2 + tau_lo * t1 - (delta_tau + tau_lo) * t6);
  }
  float t8 = si.sigma * si.sigma;
  float g_factor = -float(2) * length * t8;
  f = length * t8 * F;
  grad[0] = g_factor * (G_ap * foot0 - ab0 * G_E);
  grad[1] = -(ab1 * G_E - foot1 * G_ap) * g_factor;
  grad[2] = -g_factor * (ab2 * G_E - G_ap * foot2);
  return f;
}

// the field, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (d/sigma)^(-3), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^3 |AB| int_0^1 tau^2 (|P - Gamma|^2)^(-3/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 33 +, 52 *, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
float scalis_segment_inverse_i3_f(ScalisSegmentInput si) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float ab0 = end_b[0] - end_a[0];
  float ap0 = si.p[0] - end_a[0];
  float bp0 = si.p[0] - end_b[0];
  float ab1 = end_b[1] - end_a[1];
  float ap1 = si.p[1] - end_a[1];
  float bp1 = si.p[1] - end_b[1];
  float ab2 = end_b[2] - end_a[2];
  float ap2 = si.p[2] - end_a[2];
  float bp2 = si.p[2] - end_b[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  float ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ab2 * ap0 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t0 = float(1) / cross_cross;
    X = (a_minus_b * r0 + ab_ap * r1) * length * t0;
  }
  float t1 = float(1) / length;
  float J1 = t1 * skelconv_asinh(X);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t2 = float(1) / r0;
    float t3 = float(1) / r1;
    float t4 = t2 * ab_ap + a_minus_b * t3;
    float t5 = float(1) / cross_cross;
    float t6 = float(1) / ab_ab;
    float t7 = t3 - t2 - t4 * t5 * ab_ap;
    F = t4 * tau_lo * tau_lo * t5 - delta_tau * delta_tau * t6 * (float(2) * t6 * t7 * ab_ap + t4 * t5 * ap_ap - J1) - float(2) * delta_tau * tau_lo * t6 * t7;
  }
  float t8 = si.sigma * si.sigma;
  float t9 = t8 * si.sigma;
  f = F * length * t9;
  return f;
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (d/sigma)^(-3), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^3 |AB| int_0^1 tau^2 (|P - Gamma|^2)^(-3/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 52 +, 116 *, 7 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
float scalis_segment_inverse_i3_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float ab0 = end_b[0] - end_a[0];
  float ap0 = si.p[0] - end_a[0];
  float bp0 = si.p[0] - end_b[0];
  float ab1 = end_b[1] - end_a[1];
  float ap1 = si.p[1] - end_a[1];
  float bp1 = si.p[1] - end_b[1];
  float ab2 = end_b[2] - end_a[2];
  float ap2 = si.p[2] - end_a[2];
  float bp2 = si.p[2] - end_b[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  float ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  float ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  float plain_cross0 = ap2 * ab1 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ap2 * ab0;
  float plain_cross2 = ap1 * ab0 - ap0 * ab1;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  float foot0;
  float foot1;
  float foot2;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
    float t0 = float(1) / ab_ab;
    foot0 = ap0 - ab_ap * t0 * ab0;
    foot1 = ap1 - ab_ap * t0 * ab1;
    foot2 = ap2 - ab_ap * t0 * ab2;
  }
  float bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t1 = float(1) / cross_cross;
    X = (a_minus_b * r0 + ab_ap * r1) * length * t1;
  }
  float t2 = float(1) / length;
  float J1 = t2 * skelconv_asinh(X);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t3 = float(1) / r1;
    float t4 = float(1) / r0;
    float t5 = a_minus_b * t3 + ab_ap * t4;
    float t6 = tau_lo * tau_lo;
    float t7 = float(1) / cross_cross;
    float t8 = t3 - t4 - ab_ap * t5 * t7;
    float t9 = float(1) / ab_ab;
    float t10 = delta_tau * delta_tau;
    F = t5 * t6 * t7 - float(2) * delta_tau * tau_lo * t8 * t9 - (ap_ap * t5 * t7 + float(2) * ab_ap * t8 * t9 - J1) * t10 * t9;
    float t11 = t4 * t4;
    float t12 = t3 * t3;
    float t13 = ab_ap * t11 * t4 + t12 * a_minus_b * t3 + float(2) * t5 * ab_ab * t7;
    float t14 = t12 * t3 - ab_ap * t13 * t7 - t11 * t4;
    G_ap = (float(1) / float(3)) * t13 * t6 * t7 - (float(1) / float(3)) * t10 * t9 * (t13 * ap_ap * t7 + float(2) * ab_ap * t14 * t9 - float(3) * t5 * t7) - (float(2) / float(3)) * t14 * delta_tau * tau_lo * t9;
    float t15 = t4 * t4;
    float t16 = t15 * t4;
    float t17 = t3 * t3;
    float t18 = t17 * t3;
    G_E = (float(1) / float(3)) * (t16 * t6 + float(2) * t5 * delta_tau * tau_lo * t7 - (float(2) * delta_tau * tau_lo + t10 + t6) * t18 - float(2) * t10 * t8 * t9) * t9;
  }
  float t19 = si.sigma * si.sigma;
  float t20 = t19 * si.sigma;
  float g_factor = -float(3) * length * t20;
  f = length * t20 * F;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = g_factor * (foot1 * G_ap - G_E * ab1);
  grad[2] = g_factor * (G_ap * foot2 - G_E * ab2);
  return f;
}

// the field, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (d/sigma)^(-4), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^4 |AB| int_0^1 tau^3 (|P - Gamma|^2)^(-4/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 39 +, 71 *, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float scalis_segment_inverse_i4_f(ScalisSegmentInput si) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float ab0 = end_b[0] - end_a[0];
  float ap0 = si.p[0] - end_a[0];
  float bp0 = si.p[0] - end_b[0];
  float ab1 = end_b[1] - end_a[1];
  float ap1 = si.p[1] - end_a[1];
  float bp1 = si.p[1] - end_b[1];
  float ab2 = end_b[2] - end_a[2];
  float ap2 = si.p[2] - end_a[2];
  float bp2 = si.p[2] - end_b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  float ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ab2 * ap0 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  float ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float t0 = float(1) / ap_ap;
  float log_ratio = log(bp_bp * t0);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, ap_bp);
    float t3 = float(1) / ab_ab;
    float t4 = float(1) / cross_cross;
    float t5 = float(1) / bp_bp;
    float t6 = ab_ap * t0 + t5 * a_minus_b + ab_ab * J2;
    float t7 = t0 + t4 * ab_ap * t6 - t5;
    float t8 = tau_lo * tau_lo;
    float t9 = t8 * tau_lo;
    float t10 = t4 * t6 * ap_ap - float(2) * J2 - float(2) * t3 * ab_ap * t7;
    float t11 = delta_tau * delta_tau;
    float t12 = t11 * delta_tau;
    F = (float(3) / float(2)) * tau_lo * tau_lo * t3 * t7 * delta_tau + (float(1) / float(2)) * t9 * t4 * t6 - (float(1) / float(2)) * t3 * (float(2) * t3 * ab_ap * t10 + t3 * t7 * ap_ap - t3 * (log_ratio + float(2) * ab_ap * J2)) * t12 - (float(3) / float(2)) * tau_lo * t3 * t10 * t11;
  }
  float t13 = si.sigma * si.sigma;
  float t14 = t13 * t13;
  f = length * F * t14;
  return f;
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (d/sigma)^(-4), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^4 |AB| int_0^1 tau^3 (|P - Gamma|^2)^(-4/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 63 +, 149 *, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float scalis_segment_inverse_i4_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float ab0 = end_b[0] - end_a[0];
  float ap0 = si.p[0] - end_a[0];
  float bp0 = si.p[0] - end_b[0];
  float ab1 = end_b[1] - end_a[1];
  float ap1 = si.p[1] - end_a[1];
  float bp1 = si.p[1] - end_b[1];
  float ab2 = end_b[2] - end_a[2];
  float ap2 = si.p[2] - end_a[2];
  float bp2 = si.p[2] - end_b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
  float ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  float plain_cross0 = ab1 * ap2 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
  float plain_cross2 = ap1 * ab0 - ap0 * ab1;
  float plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  float cross_cross;
  float foot0;
  float foot1;
  float foot2;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
    float t0 = float(1) / ab_ab;
    foot0 = ap0 - ab_ap * t0 * ab0;
    foot1 = ap1 - ab_ap * t0 * ab1;
    foot2 = ap2 - ab_ap * ab2 * t0;
  }
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float ap_bp = ap0 * bp0 + bp2 * ap2 + ap1 * bp1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float t1 = float(1) / ap_ap;
  float log_ratio = log(bp_bp * t1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t2 = sqrt(cross_cross);
    float t3 = float(1) / t2;
    float J2 = atan(t2, ap_bp) * t3;
    float t4 = delta_tau * delta_tau;
    float t5 = t4 * delta_tau;
    float t6 = float(1) / ab_ab;
    float t7 = float(1) / bp_bp;
    float t8 = t7 * a_minus_b + ab_ap * t1 + J2 * ab_ab;
    float t9 = float(1) / cross_cross;
    float t10 = ab_ap * t8 * t9 + t1 - t7;
    float t11 = float(2) * J2 + float(2) * ab_ap * t10 * t6 - ap_ap * t8 * t9;
    float t12 = tau_lo * tau_lo;
    float t13 = t12 * tau_lo;
    F = (float(1) / float(2)) * t5 * t6 * (float(2) * ab_ap * t11 * t6 + t6 * (float(2) * ab_ap * J2 + log_ratio) - t10 * ap_ap * t6) + (float(3) / float(2)) * t10 * delta_tau * t12 * t6 + (float(1) / float(2)) * t8 * t13 * t9 + (float(3) / float(2)) * t4 * tau_lo * t11 * t6;
    float t14 = t7 * t7;
    float t15 = t1 * t1;
    float t16 = float(2) * t14 * a_minus_b + float(2) * ab_ap * t15 + float(3) * t8 * ab_ab * t9;
    float t17 = float(2) * t14 - ab_ap * t16 * t9 - float(2) * t15;
    float t18 = float(4) * t8 * t9 - ap_ap * t16 * t9 - float(2) * ab_ap * t17 * t6;
    G_ap = (float(3) / float(8)) * t4 * t18 * tau_lo * t6 + (float(1) / float(8)) * (ap_ap * t17 * t6 + float(4) * t10 * t6 + float(2) * ab_ap * t18 * t6) * t5 * t6 + (float(1) / float(8)) * t13 * t16 * t9 - (float(3) / float(8)) * t17 * delta_tau * t12 * t6;
    G_E = (float(1) / float(8)) * (float(3) * t5 * t11 * t6 + float(3) * t8 * delta_tau * t12 * t9 + float(6) * t10 * t4 * tau_lo * t6 + float(2) * t15 * t13 - float(2) * t14 * (t13 + t5 + float(3) * delta_tau * t12 + float(3) * t4 * tau_lo)) * t6;
  }
  float t19 = si.sigma * si.sigma;
  float t20 = t19 * t19;
  float g_factor = -float(4) * length * t20;
  f = length * t20 * F;
  grad[0] = (foot0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = g_factor * (foot1 * G_ap - ab1 * G_E);
  grad[2] = -(ab2 * G_E - G_ap * foot2) * g_factor;
  return f;
}

// the field, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (d/sigma)^(-5), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^5 |AB| int_0^1 tau^4 (|P - Gamma|^2)^(-5/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 45 +, 101 *, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
float scalis_segment_inverse_i5_f(ScalisSegmentInput si) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float ab0 = end_b[0] - end_a[0];
  float ap0 = si.p[0] - end_a[0];
  float bp0 = si.p[0] - end_b[0];
  float ab1 = end_b[1] - end_a[1];
  float ap1 = si.p[1] - end_a[1];
  float bp1 = si.p[1] - end_b[1];
  float ab2 = end_b[2] - end_a[2];
  float ap2 = si.p[2] - end_a[2];
  float bp2 = si.p[2] - end_b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  float ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ab2 * ap0 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ab_bp = ab1 * bp1 + bp2 * ab2 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t0 = float(1) / cross_cross;
    X = (r1 * ab_ap + a_minus_b * r0) * length * t0;
  }
  float t1 = float(1) / length;
  float J1 = t1 * skelconv_asinh(X);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t2 = tau_lo * tau_lo;
    float t3 = t2 * tau_lo;
    float t4 = float(1) / r0;
    float t5 = t4 * t4;
    float t6 = float(1) / cross_cross;
    float t7 = float(1) / r1;
    float t8 = t4 * ab_ap + t7 * a_minus_b;
    float t9 = t7 * t7;
    float t10 = float(2) * ab_ab * t8 * t6 + t5 * t4 * ab_ap + t7 * a_minus_b * t9;
    float t11 = t5 * t4 + t6 * ab_ap * t10 - t7 * t9;
    float t12 = float(1) / ab_ab;
    float t13 = delta_tau * delta_tau;
    float t14 = t13 * t13;
    float t15 = ap_ap * t6 * t10 - float(3) * t8 * t6 - float(2) * t11 * t12 * ab_ap;
    float t16 = t8 * t6 * ab_ap + t4 - t7;
    float t17 = ap_ap * t11 * t12 + float(2) * t15 * t12 * ab_ap - float(3) * t16 * t12;
    float t18 = t2 * t2;
    float t19 = t13 * delta_tau;
    F = (float(4) / float(3)) * delta_tau * t3 * t11 * t12 + (float(1) / float(3)) * t14 * t12 * (ap_ap * t15 * t12 - float(2) * t17 * t12 * ab_ap - float(3) * (ap_ap * t8 * t6 - J1 - float(2) * t16 * t12 * ab_ap) * t12) + (float(1) / float(3)) * t18 * t6 * t10 - (float(4) / float(3)) * t19 * t17 * tau_lo * t12 - float(2) * t13 * t2 * t15 * t12;
  }
  float t20 = si.sigma * si.sigma;
  float t21 = t20 * t20;
  float t22 = t21 * si.sigma;
  f = F * length * t22;
  return f;
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (d/sigma)^(-5), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^5 |AB| int_0^1 tau^4 (|P - Gamma|^2)^(-5/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 74 +, 207 *, 7 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
float scalis_segment_inverse_i5_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float ab0 = end_b[0] - end_a[0];
  float ap0 = si.p[0] - end_a[0];
  float bp0 = si.p[0] - end_b[0];
  float ab1 = end_b[1] - end_a[1];
  float ap1 = si.p[1] - end_a[1];
  float bp1 = si.p[1] - end_b[1];
  float ab2 = end_b[2] - end_a[2];
  float ap2 = si.p[2] - end_a[2];
  float bp2 = si.p[2] - end_b[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ab2 * ap2 + ab0 * ap0 + ap1 * ab1;
  float ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  float plain_cross0 = ap2 * ab1 - ab2 * ap1;
  float plain_cross1 = ab2 * ap0 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ap0 * ab1;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  float foot0;
  float foot1;
  float foot2;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
    float t0 = float(1) / ab_ab;
    foot0 = ap0 - ab0 * ab_ap * t0;
    foot1 = ap1 - ab_ap * t0 * ab1;
    foot2 = ap2 - ab2 * ab_ap * t0;
  }
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = ab0 * bp0 + ab2 * bp2 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t1 = float(1) / cross_cross;
    X = t1 * (a_minus_b * r0 + r1 * ab_ap) * length;
  }
  float t2 = float(1) / length;
  float J1 = skelconv_asinh(X) * t2;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t3 = float(1) / cross_cross;
    float t4 = tau_lo * tau_lo;
    float t5 = t4 * t4;
    float t6 = float(1) / r1;
    float t7 = t6 * t6;
    float t8 = float(1) / r0;
    float t9 = t6 * a_minus_b + ab_ap * t8;
    float t10 = t8 * t8;
    float t11 = t6 * t7 * a_minus_b + float(2) * t3 * t9 * ab_ab + ab_ap * t10 * t8;
    float t12 = t4 * tau_lo;
    float t13 = t3 * ab_ap * t11 + t10 * t8 - t6 * t7;
    float t14 = float(1) / ab_ab;
    float t15 = t3 * ap_ap * t11 - float(3) * t3 * t9 - float(2) * ab_ap * t13 * t14;
    float t16 = t8 + t3 * ab_ap * t9 - t6;
    float t17 = ap_ap * t13 * t14 + float(2) * ab_ap * t15 * t14 - float(3) * t16 * t14;
    float t18 = delta_tau * delta_tau;
    float t19 = t18 * t18;
    float t20 = t18 * delta_tau;
    F = (float(1) / float(3)) * t3 * t5 * t11 + (float(4) / float(3)) * delta_tau * t12 * t13 * t14 - (float(1) / float(3)) * (float(2) * ab_ap * t17 * t14 - ap_ap * t15 * t14 - float(3) * (float(2) * ab_ap * t16 * t14 + J1 - t3 * ap_ap * t9) * t14) * t19 * t14 - (float(4) / float(3)) * t17 * t20 * tau_lo * t14 - float(2) * t18 * t4 * t15 * t14;
    float t21 = t10 * t10;
    float t22 = t7 * t7;
    float t23 = float(4) * t3 * t11 * ab_ab + float(3) * ab_ap * t21 * t8 + float(3) * t6 * t22 * a_minus_b;
    float t24 = float(3) * t21 * t8 + t3 * ab_ap * t23 - float(3) * t6 * t22;
    float t25 = float(5) * t3 * t11 + float(2) * ab_ap * t24 * t14 - t3 * t23 * ap_ap;
    float t26 = ap_ap * t24 * t14 - float(2) * ab_ap * t25 * t14 - float(5) * t13 * t14;
    G_ap = (float(4) / float(15)) * delta_tau * t12 * t24 * t14 + (float(2) / float(5)) * t25 * t18 * t4 * t14 + (float(1) / float(15)) * t3 * t23 * t5 - (float(4) / float(15)) * t26 * t20 * tau_lo * t14 - (float(1) / float(15)) * (ap_ap * t25 * t14 + float(5) * t15 * t14 + float(2) * ab_ap * t26 * t14) * t19 * t14;
    float t27 = t8 * t8;
    float t28 = t27 * t27;
    float t29 = t28 * t8;
    float t30 = t6 * t6;
    float t31 = t30 * t30;
    float t32 = t31 * t6;
    G_E = (float(1) / float(15)) * (float(12) * t18 * t4 * t13 * t14 + float(4) * t3 * delta_tau * t12 * t11 + float(3) * t29 * t5 - float(4) * t17 * t19 * t14 - float(12) * t20 * tau_lo * t15 * t14 - float(3) * t32 * (float(4) * delta_tau * t12 + t5 + t19 + float(4) * t20 * tau_lo + float(6) * t18 * t4)) * t14;
  }
  float t33 = si.sigma * si.sigma;
  float t34 = t33 * t33;
  float t35 = t34 * si.sigma;
  float g_factor = -float(5) * length * t35;
  f = length * t35 * F;
  grad[0] = -(ab0 * G_E - foot0 * G_ap) * g_factor;
  grad[1] = (foot1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = -(ab2 * G_E - foot2 * G_ap) * g_factor;
  return f;
}

// the field, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (d/sigma)^(-6), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^6 |AB| int_0^1 tau^5 (|P - Gamma|^2)^(-6/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 53 +, 125 *, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float scalis_segment_inverse_i6_f(ScalisSegmentInput si) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float ab0 = end_b[0] - end_a[0];
  float ap0 = si.p[0] - end_a[0];
  float bp0 = si.p[0] - end_b[0];
  float ab1 = end_b[1] - end_a[1];
  float ap1 = si.p[1] - end_a[1];
  float bp1 = si.p[1] - end_b[1];
  float ab2 = end_b[2] - end_a[2];
  float ap2 = si.p[2] - end_a[2];
  float bp2 = si.p[2] - end_b[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  float ab_ap = ap0 * ab0 + ab1 * ap1 + ap2 * ab2;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ab1 * ap2 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ap2 * ab0;
  float plain_cross2 = ap1 * ab0 - ab1 * ap0;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + ab1 * bp1 + bp2 * ab2;
  float ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float t0 = float(1) / ap_ap;
  float log_ratio = log(bp_bp * t0);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, ap_bp);
    float t3 = tau_lo * tau_lo;
    float t4 = t3 * t3;
    float t5 = float(1) / ab_ab;
    float t6 = t0 * t0;
    float t7 = float(1) / cross_cross;
    float t8 = float(1) / bp_bp;
    float t9 = ab_ap * t0 + t8 * a_minus_b + J2 * ab_ab;
    float t10 = t8 * t8;
    float t11 = float(3) * t7 * ab_ab * t9 + float(2) * t10 * a_minus_b + float(2) * ab_ap * t6;
    float t12 = float(2) * t6 + t7 * ab_ap * t11 - float(2) * t10;
    float t13 = float(2) * ab_ap * t5 * t12 + float(4) * t7 * t9 - t7 * ap_ap * t11;
    float t14 = t3 * tau_lo;
    float t15 = t4 * tau_lo;
    float t16 = delta_tau * delta_tau;
    float t17 = t16 * t16;
    float t18 = t17 * delta_tau;
    float t19 = t8 - t7 * ab_ap * t9 - t0;
    float t20 = float(2) * J2 - float(2) * ab_ap * t19 * t5 - t7 * ap_ap * t9;
    float t21 = float(4) * t19 * t5 + ap_ap * t5 * t12 - float(2) * t13 * ab_ap * t5;
    float t22 = t13 * ap_ap * t5 + float(2) * ab_ap * t21 * t5 - float(4) * t20 * t5;
    float t23 = t16 * delta_tau;
    F = (float(5) / float(8)) * delta_tau * t4 * t5 * t12 + (float(5) / float(4)) * t13 * delta_tau * delta_tau * t14 * t5 + (float(1) / float(8)) * t7 * t11 * t15 + (float(1) / float(8)) * t18 * (float(4) * ((log_ratio + float(2) * ab_ap * J2) * t5 + float(2) * ab_ap * t20 * t5 + ap_ap * t19 * t5) * t5 + t21 * ap_ap * t5 - float(2) * ab_ap * t22 * t5) * t5 - (float(5) / float(8)) * t17 * tau_lo * t22 * t5 - (float(5) / float(4)) * t21 * t23 * t3 * t5;
  }
  float t24 = si.sigma * si.sigma;
  float t25 = t24 * si.sigma;
  float t26 = t25 * t25;
  f = length * t26 * F;
  return f;
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (d/sigma)^(-6), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^6 |AB| int_0^1 tau^5 (|P - Gamma|^2)^(-6/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 87 +, 237 *, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float scalis_segment_inverse_i6_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float ab0 = end_b[0] - end_a[0];
  float ap0 = si.p[0] - end_a[0];
  float bp0 = si.p[0] - end_b[0];
  float ab1 = end_b[1] - end_a[1];
  float ap1 = si.p[1] - end_a[1];
  float bp1 = si.p[1] - end_b[1];
  float ab2 = end_b[2] - end_a[2];
  float ap2 = si.p[2] - end_a[2];
  float bp2 = si.p[2] - end_b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  float ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ab2 * ap0 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  float cross_cross;
  float foot0;
  float foot1;
  float foot2;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
    float t0 = float(1) / ab_ab;
    foot0 = ap0 - t0 * ab0 * ab_ap;
    foot1 = ap1 - t0 * ab1 * ab_ap;
    foot2 = ap2 - t0 * ab2 * ab_ap;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  float ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float t1 = float(1) / ap_ap;
  float log_ratio = log(bp_bp * t1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t2 = sqrt(cross_cross);
    float t3 = float(1) / t2;
    float J2 = atan(t2, ap_bp) * t3;
    float t4 = float(1) / cross_cross;
    float t5 = t1 * t1;
    float t6 = float(1) / bp_bp;
    float t7 = ab_ab * J2 + t6 * a_minus_b + ab_ap * t1;
    float t8 = t6 * t6;
    float t9 = float(2) * ab_ap * t5 + float(3) * ab_ab * t4 * t7 + float(2) * t8 * a_minus_b;
    float t10 = tau_lo * tau_lo;
    float t11 = t10 * t10;
    float t12 = t11 * tau_lo;
    float t13 = float(1) / ab_ab;
    float t14 = delta_tau * delta_tau;
    float t15 = t14 * delta_tau;
    float t16 = float(2) * t5 + t4 * ab_ap * t9 - float(2) * t8;
    float t17 = float(4) * t4 * t7 + float(2) * t13 * ab_ap * t16 - t4 * ap_ap * t9;
    float t18 = t6 - t4 * ab_ap * t7 - t1;
    float t19 = float(2) * t13 * t17 * ab_ap - t13 * ap_ap * t16 - float(4) * t13 * t18;
    float t20 = t10 * tau_lo;
    float t21 = t4 * ap_ap * t7 + float(2) * t13 * t18 * ab_ap - float(2) * J2;
    float t22 = float(4) * t13 * t21 + t13 * t17 * ap_ap - float(2) * t13 * ab_ap * t19;
    float t23 = t14 * t14;
    float t24 = t23 * delta_tau;
    F = (float(1) / float(8)) * t4 * t9 * t12 + (float(5) / float(4)) * t13 * t10 * t15 * t19 + (float(5) / float(4)) * t13 * t17 * t20 * t14 + (float(5) / float(8)) * t13 * t16 * t11 * delta_tau - (float(5) / float(8)) * t13 * t22 * tau_lo * t23 - (float(1) / float(8)) * t13 * (t13 * ap_ap * t19 + float(2) * t13 * ab_ap * t22 + float(4) * t13 * (float(2) * t13 * ab_ap * t21 - t13 * t18 * ap_ap - t13 * (float(2) * ab_ap * J2 + log_ratio))) * t24;
    float t25 = t5 * t1;
    float t26 = t8 * t6;
    float t27 = float(5) * ab_ab * t4 * t9 + float(8) * ab_ap * t25 + float(8) * t26 * a_minus_b;
    float t28 = float(8) * t25 + t4 * t27 * ab_ap - float(8) * t26;
    float t29 = float(6) * t4 * t9 + float(2) * t13 * ab_ap * t28 - t4 * t27 * ap_ap;
    float t30 = float(6) * t13 * t16 + float(2) * t13 * ab_ap * t29 - t13 * t28 * ap_ap;
    float t31 = float(2) * t13 * ab_ap * t30 + float(6) * t13 * t17 - t13 * ap_ap * t29;
    G_ap = (float(1) / float(48)) * t4 * t27 * t12 + (float(1) / float(48)) * t13 * t24 * (float(6) * t13 * t19 + float(2) * t13 * t31 * ab_ap - t13 * t30 * ap_ap) + (float(5) / float(24)) * t13 * t29 * t20 * t14 + (float(5) / float(48)) * t13 * t28 * t11 * delta_tau + (float(5) / float(48)) * t13 * t31 * tau_lo * t23 + (float(5) / float(24)) * t13 * t30 * t10 * t15;
    G_E = -(float(1) / float(48)) * t13 * (float(5) * t13 * t22 * t24 + float(8) * t26 * (float(5) * t11 * delta_tau + t12 + t24 + float(10) * t20 * t14 + float(5) * tau_lo * t23 + float(10) * t10 * t15) - float(20) * t13 * t16 * t20 * t14 - float(20) * t13 * tau_lo * t23 * t19 - float(5) * t4 * t9 * t11 * delta_tau - float(8) * t25 * t12 - float(30) * t13 * t17 * t10 * t15);
  }
  float t32 = si.sigma * si.sigma;
  float t33 = t32 * si.sigma;
  float t34 = t33 * t33;
  float g_factor = -float(6) * length * t34;
  f = length * t34 * F;
  grad[0] = g_factor * (G_ap * foot0 - ab0 * G_E);
  grad[1] = -g_factor * (ab1 * G_E - G_ap * foot1);
  grad[2] = g_factor * (G_ap * foot2 - ab2 * G_E);
  return f;
}

// the field, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (d/sigma)^(-7), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^7 |AB| int_0^1 tau^6 (|P - Gamma|^2)^(-7/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 61 +, 164 *, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
float scalis_segment_inverse_i7_f(ScalisSegmentInput si) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float ab0 = end_b[0] - end_a[0];
  float ap0 = si.p[0] - end_a[0];
  float bp0 = si.p[0] - end_b[0];
  float ab1 = end_b[1] - end_a[1];
  float ap1 = si.p[1] - end_a[1];
  float bp1 = si.p[1] - end_b[1];
  float ab2 = end_b[2] - end_a[2];
  float ap2 = si.p[2] - end_a[2];
  float bp2 = si.p[2] - end_b[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  float ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  float ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ab2 * ap0 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t0 = float(1) / cross_cross;
    X = length * t0 * (a_minus_b * r0 + ab_ap * r1);
  }
  float t1 = float(1) / length;
  float J1 = t1 * skelconv_asinh(X);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t2 = float(1) / r0;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = float(1) / r1;
    float t6 = t5 * t5;
    float t7 = a_minus_b * t5 + t2 * ab_ap;
    float t8 = float(1) / cross_cross;
    float t9 = a_minus_b * t6 * t5 + float(2) * t7 * ab_ab * t8 + t2 * ab_ap * t3;
    float t10 = t6 * t6;
    float t11 = float(3) * t2 * ab_ap * t4 + float(4) * t9 * ab_ab * t8 + float(3) * a_minus_b * t10 * t5;
    float t12 = float(3) * t2 * t4 + t11 * t8 * ab_ap - float(3) * t10 * t5;
    float t13 = tau_lo * tau_lo;
    float t14 = t13 * t13;
    float t15 = t14 * tau_lo;
    float t16 = float(1) / ab_ab;
    float t17 = t13 * tau_lo;
    float t18 = t17 * t17;
    float t19 = t11 * t8 * ap_ap - float(2) * t12 * t16 * ab_ap - float(5) * t9 * t8;
    float t20 = t9 * t8 * ab_ap + t2 * t3 - t6 * t5;
    float t21 = float(2) * t16 * t20 * ab_ap + float(3) * t7 * t8 - t9 * t8 * ap_ap;
    float t22 = float(5) * t16 * t20 - t12 * t16 * ap_ap - float(2) * t16 * t19 * ab_ap;
    float t23 = t16 * t19 * ap_ap + float(5) * t16 * t21 + float(2) * t16 * t22 * ab_ap;
    float t24 = delta_tau * delta_tau;
    float t25 = t24 * t24;
    float t26 = t24 * delta_tau;
    float t27 = t25 * delta_tau;
    float t28 = t5 - t2 - t7 * t8 * ab_ap;
    float t29 = t16 * t20 * ap_ap + float(3) * t28 * t16 - float(2) * t16 * t21 * ab_ap;
    float t30 = t16 * t22 * ap_ap + float(5) * t29 * t16 - float(2) * t23 * t16 * ab_ap;
    float t31 = t26 * t26;
    F = (float(2) / float(5)) * delta_tau * t12 * t15 * t16 + (float(1) / float(15)) * t11 * t18 * t8 + t23 * t25 * t13 * t16 + (float(4) / float(3)) * t26 * t17 * t16 * t22 - t24 * t14 * t16 * t19 - (float(2) / float(5)) * t27 * tau_lo * t16 * t30 - (float(1) / float(15)) * t31 * t16 * (float(5) * t16 * (t16 * t21 * ap_ap + float(3) * t16 * (t7 * t8 * ap_ap + float(2) * t28 * t16 * ab_ap - J1) + float(2) * t29 * t16 * ab_ap) + t23 * t16 * ap_ap + float(2) * t16 * ab_ap * t30);
  }
  float t32 = si.sigma * si.sigma;
  float t33 = t32 * si.sigma;
  float t34 = t33 * t33;
  float t35 = t34 * si.sigma;
  f = length * t35 * F;
  return f;
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (d/sigma)^(-7), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^7 |AB| int_0^1 tau^6 (|P - Gamma|^2)^(-7/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 100 +, 308 *, 7 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
float scalis_segment_inverse_i7_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float ab0 = end_b[0] - end_a[0];
  float ap0 = si.p[0] - end_a[0];
  float bp0 = si.p[0] - end_b[0];
  float ab1 = end_b[1] - end_a[1];
  float ap1 = si.p[1] - end_a[1];
  float bp1 = si.p[1] - end_b[1];
  float ab2 = end_b[2] - end_a[2];
  float ap2 = si.p[2] - end_a[2];
  float bp2 = si.p[2] - end_b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  float ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ab2 * ap0 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  float cross_cross;
  float foot0;
  float foot1;
  float foot2;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
    float t0 = float(1) / ab_ab;
    foot0 = ap0 - t0 * ab0 * ab_ap;
    foot1 = ap1 - t0 * ab1 * ab_ap;
    foot2 = ap2 - t0 * ab2 * ab_ap;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t1 = float(1) / cross_cross;
    X = length * (a_minus_b * r0 + ab_ap * r1) * t1;
  }
  float t2 = float(1) / length;
  float J1 = t2 * skelconv_asinh(X);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t3 = float(1) / ab_ab;
    float t4 = float(1) / r1;
    float t5 = float(1) / r0;
    float t6 = a_minus_b * t4 + ab_ap * t5;
    float t7 = float(1) / cross_cross;
    float t8 = t5 * t5;
    float t9 = t4 * t4;
    float t10 = float(2) * ab_ab * t6 * t7 + ab_ap * t5 * t8 + a_minus_b * t4 * t9;
    float t11 = t9 * t9;
    float t12 = t8 * t8;
    float t13 = float(4) * ab_ab * t10 * t7 + float(3) * a_minus_b * t4 * t11 + float(3) * ab_ap * t5 * t12;
    float t14 = ab_ap * t13 * t7 + float(3) * t5 * t12 - float(3) * t4 * t11;
    float t15 = tau_lo * tau_lo;
    float t16 = t15 * t15;
    float t17 = t16 * tau_lo;
    float t18 = t15 * tau_lo;
    float t19 = t18 * t18;
    float t20 = t4 * t9 - t5 * t8 - ab_ap * t10 * t7;
    float t21 = float(2) * t3 * t20 * ab_ap + t10 * ap_ap * t7 - float(3) * t6 * t7;
    float t22 = t13 * ap_ap * t7 - float(5) * t10 * t7 - float(2) * t3 * ab_ap * t14;
    float t23 = float(5) * t3 * t20 + float(2) * t3 * ab_ap * t22 + t3 * ap_ap * t14;
    float t24 = float(5) * t3 * t21 + float(2) * t3 * ab_ap * t23 - t3 * ap_ap * t22;
    float t25 = delta_tau * delta_tau;
    float t26 = t25 * t25;
    float t27 = t4 - t5 - ab_ap * t6 * t7;
    float t28 = float(2) * t3 * ab_ap * t21 + float(3) * t3 * t27 - t3 * t20 * ap_ap;
    float t29 = float(2) * t3 * ab_ap * t24 + float(5) * t3 * t28 - t3 * ap_ap * t23;
    float t30 = t26 * delta_tau;
    float t31 = t25 * delta_tau;
    float t32 = t31 * t31;
    F = (float(2) / float(5)) * t3 * delta_tau * t14 * t17 + (float(1) / float(15)) * t13 * t7 * t19 - t3 * t24 * t26 * t15 - t3 * t25 * t16 * t22 - (float(2) / float(5)) * t3 * t29 * t30 * tau_lo - (float(4) / float(3)) * t3 * t31 * t23 * t18 - (float(1) / float(15)) * t3 * (float(2) * t3 * ab_ap * t29 + float(5) * t3 * (float(3) * t3 * (ap_ap * t6 * t7 + float(2) * t3 * t27 * ab_ap - J1) + float(2) * t3 * t28 * ab_ap - t3 * t21 * ap_ap) - t3 * t24 * ap_ap) * t32;
    float t33 = t11 * t9;
    float t34 = t12 * t8;
    float t35 = float(2) * ab_ab * t13 * t7 + float(5) * a_minus_b * t4 * t33 + float(5) * ab_ap * t5 * t34;
    float t36 = ab_ap * t35 * t7 + float(5) * t5 * t34 - float(5) * t4 * t33;
    float t37 = float(6) * t3 * ab_ap * t36 + float(7) * t13 * t7 - float(3) * t35 * ap_ap * t7;
    float t38 = float(2) * t3 * t37 * ab_ap + float(7) * t3 * t14 - float(3) * t3 * ap_ap * t36;
    float t39 = float(7) * t3 * t22 + t3 * t37 * ap_ap - float(2) * t3 * ab_ap * t38;
    float t40 = float(7) * t3 * t23 + float(2) * t3 * ab_ap * t39 + t3 * t38 * ap_ap;
    G_ap = (float(1) / float(35)) * t35 * t7 * t19 + (float(4) / float(21)) * t3 * t38 * t31 * t18 + (float(6) / float(35)) * t3 * delta_tau * t17 * t36 + (float(1) / float(7)) * t3 * t37 * t25 * t16 - (float(2) / float(35)) * t3 * t40 * t30 * tau_lo - (float(1) / float(7)) * t3 * t26 * t15 * t39 - (float(1) / float(105)) * t3 * (float(7) * t3 * t24 + float(2) * t3 * t40 * ab_ap - t3 * ap_ap * t39) * t32;
    float t41 = t4 * t4;
    float t42 = t41 * t4;
    float t43 = t42 * t42;
    float t44 = t43 * t4;
    float t45 = t5 * t5;
    float t46 = t45 * t5;
    float t47 = t46 * t46;
    float t48 = t47 * t5;
    G_E = -(float(1) / float(35)) * t3 * (float(2) * t3 * t29 * t32 + float(5) * (t19 + float(15) * t25 * t16 + t32 + float(6) * t30 * tau_lo + float(15) * t26 * t15 + float(20) * t31 * t18 + float(6) * delta_tau * t17) * t44 + float(20) * t3 * t31 * t18 * t22 + float(20) * t3 * t26 * t23 * t15 + float(10) * t3 * t24 * t30 * tau_lo - float(2) * t13 * delta_tau * t7 * t17 - float(5) * t48 * t19 - float(10) * t3 * t25 * t14 * t16);
  }
  float t49 = si.sigma * si.sigma;
  float t50 = t49 * si.sigma;
  float t51 = t50 * t50;
  float t52 = t51 * si.sigma;
  float g_factor = -float(7) * t52 * length;
  f = F * t52 * length;
  grad[0] = (foot0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = -(ab1 * G_E - foot1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_E - G_ap * foot2) * g_factor;
  return f;
}

// the field, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (d/sigma)^(-8), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^8 |AB| int_0^1 tau^7 (|P - Gamma|^2)^(-8/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 71 +, 191 *, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float scalis_segment_inverse_i8_f(ScalisSegmentInput si) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float ab0 = end_b[0] - end_a[0];
  float ap0 = si.p[0] - end_a[0];
  float bp0 = si.p[0] - end_b[0];
  float ab1 = end_b[1] - end_a[1];
  float ap1 = si.p[1] - end_a[1];
  float bp1 = si.p[1] - end_b[1];
  float ab2 = end_b[2] - end_a[2];
  float ap2 = si.p[2] - end_a[2];
  float bp2 = si.p[2] - end_b[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  float ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ab2 * ap0 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  float ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float t0 = float(1) / ap_ap;
  float log_ratio = log(bp_bp * t0);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, ap_bp);
    float t3 = float(1) / ab_ab;
    float t4 = t0 * t0;
    float t5 = t4 * t0;
    float t6 = float(1) / cross_cross;
    float t7 = float(1) / bp_bp;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = a_minus_b * t7 + ab_ab * J2 + ab_ap * t0;
    float t11 = float(2) * ab_ap * t4 + float(3) * ab_ab * t6 * t10 + float(2) * a_minus_b * t8;
    float t12 = float(8) * ab_ap * t5 + float(8) * a_minus_b * t9 + float(5) * ab_ab * t6 * t11;
    float t13 = float(8) * t5 + t6 * t12 * ab_ap - float(8) * t9;
    float t14 = t6 * t12 * ap_ap - float(6) * t6 * t11 - float(2) * t3 * t13 * ab_ap;
    float t15 = float(2) * t4 + t6 * ab_ap * t11 - float(2) * t8;
    float t16 = t3 * t13 * ap_ap + float(2) * t3 * ab_ap * t14 - float(6) * t3 * t15;
    float t17 = float(4) * t6 * t10 + float(2) * t3 * t15 * ab_ap - t6 * ap_ap * t11;
    float t18 = float(2) * t3 * ab_ap * t16 - float(6) * t3 * t17 - t3 * t14 * ap_ap;
    float t19 = t7 - t0 - t6 * ab_ap * t10;
    float t20 = t6 * ap_ap * t10 + float(2) * t3 * t19 * ab_ap - float(2) * J2;
    float t21 = float(4) * t3 * t19 + t3 * t15 * ap_ap - float(2) * t3 * ab_ap * t17;
    float t22 = float(4) * t3 * t20 + t3 * t17 * ap_ap + float(2) * t3 * ab_ap * t21;
    float t23 = float(6) * t3 * t21 + float(2) * t3 * ab_ap * t18 - t3 * ap_ap * t16;
    float t24 = t3 * ap_ap * t18 - float(6) * t22 * t3 - float(2) * t3 * t23 * ab_ap;
    float t25 = delta_tau * delta_tau;
    float t26 = t25 * delta_tau;
    float t27 = t26 * t26;
    float t28 = tau_lo * tau_lo;
    float t29 = t28 * tau_lo;
    float t30 = t29 * t29;
    float t31 = t30 * tau_lo;
    float t32 = t27 * delta_tau;
    float t33 = t25 * t25;
    float t34 = t33 * delta_tau;
    float t35 = t28 * t28;
    float t36 = t35 * tau_lo;
    F = (float(7) / float(48)) * t3 * t24 * t27 * tau_lo + (float(1) / float(48)) * t6 * t12 * t31 + (float(7) / float(48)) * t3 * t13 * delta_tau * t30 + (float(1) / float(48)) * t3 * t32 * (t3 * t23 * ap_ap + float(2) * t3 * t24 * ab_ap - float(6) * t3 * (float(2) * t22 * t3 * ab_ap - t3 * ap_ap * t21 - float(4) * t3 * (t3 * (log_ratio + float(2) * ab_ap * J2) + t3 * t19 * ap_ap - float(2) * t3 * ab_ap * t20))) - (float(7) / float(16)) * t3 * t23 * t34 * t28 - (float(35) / float(48)) * t3 * t18 * t33 * t29 - (float(7) / float(16)) * t3 * t14 * t25 * t36 - (float(35) / float(48)) * t3 * t16 * t26 * t35;
  }
  float t37 = si.sigma * si.sigma;
  float t38 = t37 * t37;
  float t39 = t38 * t38;
  f = length * t39 * F;
  return f;
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (d/sigma)^(-8), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^8 |AB| int_0^1 tau^7 (|P - Gamma|^2)^(-8/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 115 +, 338 *, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float scalis_segment_inverse_i8_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float ab0 = end_b[0] - end_a[0];
  float ap0 = si.p[0] - end_a[0];
  float bp0 = si.p[0] - end_b[0];
  float ab1 = end_b[1] - end_a[1];
  float ap1 = si.p[1] - end_a[1];
  float bp1 = si.p[1] - end_b[1];
  float ab2 = end_b[2] - end_a[2];
  float ap2 = si.p[2] - end_a[2];
  float bp2 = si.p[2] - end_b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab1 * ap1 + ap0 * ab0 + ab2 * ap2;
  float ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ap0 * ab1;
  float plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  float cross_cross;
  float foot0;
  float foot1;
  float foot2;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
    float t0 = float(1) / ab_ab;
    foot0 = ap0 - t0 * ab0 * ab_ap;
    foot1 = ap1 - t0 * ab1 * ab_ap;
    foot2 = ap2 - t0 * ab2 * ab_ap;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float t1 = float(1) / ap_ap;
  float log_ratio = log(t1 * bp_bp);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t2 = sqrt(cross_cross);
    float t3 = float(1) / t2;
    float J2 = atan(t2, ap_bp) * t3;
    float t4 = t1 * t1;
    float t5 = t4 * t1;
    float t6 = float(1) / bp_bp;
    float t7 = t6 * t6;
    float t8 = t7 * t6;
    float t9 = float(1) / cross_cross;
    float t10 = J2 * ab_ab + t1 * ab_ap + a_minus_b * t6;
    float t11 = float(2) * t4 * ab_ap + float(3) * ab_ab * t9 * t10 + float(2) * a_minus_b * t7;
    float t12 = float(8) * t5 * ab_ap + float(8) * a_minus_b * t8 + float(5) * ab_ab * t9 * t11;
    float t13 = tau_lo * tau_lo;
    float t14 = t13 * tau_lo;
    float t15 = t14 * t14;
    float t16 = t15 * tau_lo;
    float t17 = float(1) / ab_ab;
    float t18 = float(8) * t5 + t12 * t9 * ab_ap - float(8) * t8;
    float t19 = delta_tau * delta_tau;
    float t20 = t19 * delta_tau;
    float t21 = t20 * t20;
    float t22 = float(6) * t9 * t11 + float(2) * t17 * ab_ap * t18 - ap_ap * t12 * t9;
    float t23 = float(2) * t4 + t9 * t11 * ab_ap - float(2) * t7;
    float t24 = ap_ap * t17 * t18 - float(6) * t23 * t17 - float(2) * t17 * ab_ap * t22;
    float t25 = float(4) * t9 * t10 + float(2) * t23 * t17 * ab_ap - ap_ap * t9 * t11;
    float t26 = ap_ap * t17 * t22 + float(2) * t24 * t17 * ab_ap - float(6) * t25 * t17;
    float t27 = t6 - t9 * ab_ap * t10 - t1;
    float t28 = t23 * ap_ap * t17 + float(4) * t17 * t27 - float(2) * t25 * t17 * ab_ap;
    float t29 = float(2) * t26 * t17 * ab_ap + float(6) * t28 * t17 - t24 * ap_ap * t17;
    float t30 = float(2) * t17 * t27 * ab_ap + ap_ap * t9 * t10 - float(2) * J2;
    float t31 = float(2) * t28 * t17 * ab_ap + ap_ap * t25 * t17 + float(4) * t30 * t17;
    float t32 = ap_ap * t26 * t17 - float(2) * t17 * t29 * ab_ap - float(6) * t17 * t31;
    float t33 = t13 * t13;
    float t34 = t33 * tau_lo;
    float t35 = t21 * delta_tau;
    float t36 = t19 * t19;
    float t37 = t36 * delta_tau;
    F = (float(1) / float(48)) * t12 * t16 * t9 + (float(7) / float(48)) * delta_tau * t15 * t17 * t18 + (float(7) / float(48)) * t21 * tau_lo * t17 * t32 + (float(7) / float(16)) * t19 * t34 * t17 * t22 + (float(1) / float(48)) * (float(6) * (t28 * ap_ap * t17 - float(4) * t17 * (float(2) * t30 * t17 * ab_ap - ap_ap * t17 * t27 - t17 * (log_ratio + float(2) * J2 * ab_ap)) - float(2) * t17 * t31 * ab_ap) * t17 + ap_ap * t17 * t29 + float(2) * t17 * ab_ap * t32) * t35 * t17 - (float(35) / float(48)) * t24 * t20 * t33 * t17 - (float(7) / float(16)) * t37 * t13 * t17 * t29 - (float(35) / float(48)) * t26 * t36 * t14 * t17;
    float t38 = t7 * t7;
    float t39 = t4 * t4;
    float t40 = float(7) * t12 * ab_ab * t9 + float(48) * a_minus_b * t38 + float(48) * t39 * ab_ap;
    float t41 = t40 * t9 * ab_ap + float(48) * t39 - float(48) * t38;
    float t42 = float(2) * t41 * t17 * ab_ap + float(8) * t12 * t9 - ap_ap * t40 * t9;
    float t43 = float(8) * t17 * t18 + float(2) * t17 * t42 * ab_ap - ap_ap * t41 * t17;
    float t44 = float(2) * t43 * t17 * ab_ap + float(8) * t17 * t22 - ap_ap * t17 * t42;
    float t45 = float(2) * t44 * t17 * ab_ap - ap_ap * t43 * t17 - float(8) * t24 * t17;
    float t46 = ap_ap * t44 * t17 + float(8) * t26 * t17 - float(2) * t17 * t45 * ab_ap;
    G_ap = (float(7) / float(128)) * t37 * t13 * t17 * t45 + (float(35) / float(384)) * t43 * t20 * t33 * t17 + (float(7) / float(128)) * t19 * t34 * t17 * t42 + (float(7) / float(384)) * delta_tau * t15 * t41 * t17 + (float(1) / float(384)) * t16 * t40 * t9 + (float(35) / float(384)) * t44 * t36 * t14 * t17 - (float(1) / float(384)) * (float(2) * t46 * t17 * ab_ap + ap_ap * t17 * t45 + float(8) * t17 * t29) * t35 * t17 - (float(7) / float(384)) * t46 * t21 * tau_lo * t17;
    G_E = (float(1) / float(384)) * t17 * (float(7) * t35 * t17 * t32 + float(42) * t19 * t34 * t17 * t18 + float(105) * t20 * t33 * t17 * t22 + float(48) * t39 * t16 + float(7) * t12 * delta_tau * t15 * t9 - float(48) * (float(7) * delta_tau * t15 + t35 + float(7) * t21 * tau_lo + float(21) * t37 * t13 + float(35) * t20 * t33 + float(35) * t36 * t14 + float(21) * t19 * t34 + t16) * t38 - float(140) * t24 * t36 * t14 * t17 - float(42) * t21 * tau_lo * t17 * t29 - float(105) * t26 * t37 * t13 * t17);
  }
  float t47 = si.sigma * si.sigma;
  float t48 = t47 * t47;
  float t49 = t48 * t48;
  float g_factor = -float(8) * t49 * length;
  f = t49 * F * length;
  grad[0] = g_factor * (foot0 * G_ap - ab0 * G_E);
  grad[1] = -g_factor * (ab1 * G_E - foot1 * G_ap);
  grad[2] = g_factor * (G_ap * foot2 - ab2 * G_E);
  return f;
}

// the field, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (d/sigma)^(-9), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^9 |AB| int_0^1 tau^8 (|P - Gamma|^2)^(-9/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 81 +, 247 *, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
float scalis_segment_inverse_i9_f(ScalisSegmentInput si) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float ab0 = end_b[0] - end_a[0];
  float ap0 = si.p[0] - end_a[0];
  float bp0 = si.p[0] - end_b[0];
  float ab1 = end_b[1] - end_a[1];
  float ap1 = si.p[1] - end_a[1];
  float bp1 = si.p[1] - end_b[1];
  float ab2 = end_b[2] - end_a[2];
  float ap2 = si.p[2] - end_a[2];
  float bp2 = si.p[2] - end_b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ab2 * ap0 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ab_bp = ab2 * bp2 + ab1 * bp1 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t0 = float(1) / cross_cross;
    X = length * t0 * (a_minus_b * r0 + ab_ap * r1);
  }
  float t1 = float(1) / length;
  float J1 = t1 * skelconv_asinh(X);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t2 = tau_lo * tau_lo;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = float(1) / r0;
    float t6 = t5 * t5;
    float t7 = t6 * t6;
    float t8 = t7 * t6;
    float t9 = float(1) / r1;
    float t10 = t9 * t9;
    float t11 = t10 * t10;
    float t12 = t11 * t10;
    float t13 = ab_ap * t5 + a_minus_b * t9;
    float t14 = float(1) / cross_cross;
    float t15 = t6 * ab_ap * t5 + float(2) * ab_ab * t13 * t14 + a_minus_b * t10 * t9;
    float t16 = float(3) * a_minus_b * t11 * t9 + float(4) * ab_ab * t15 * t14 + float(3) * t7 * ab_ap * t5;
    float t17 = float(5) * t8 * ab_ap * t5 + float(5) * a_minus_b * t12 * t9 + float(2) * ab_ab * t16 * t14;
    float t18 = t2 * tau_lo;
    float t19 = t18 * t18;
    float t20 = t19 * tau_lo;
    float t21 = float(1) / ab_ab;
    float t22 = float(5) * t8 * t5 + t17 * ab_ap * t14 - float(5) * t12 * t9;
    float t23 = float(6) * t21 * t22 * ab_ap + float(7) * t16 * t14 - float(3) * ap_ap * t17 * t14;
    float t24 = delta_tau * delta_tau;
    float t25 = t24 * t24;
    float t26 = t25 * delta_tau;
    float t27 = t16 * ab_ap * t14 + float(3) * t7 * t5 - float(3) * t11 * t9;
    float t28 = float(3) * ap_ap * t21 * t22 - float(7) * t21 * t27 - float(2) * t21 * ab_ap * t23;
    float t29 = float(5) * t15 * t14 + float(2) * t21 * ab_ap * t27 - ap_ap * t16 * t14;
    float t30 = ap_ap * t21 * t23 + float(2) * t21 * ab_ap * t28 - float(7) * t21 * t29;
    float t31 = t6 * t5 + t15 * ab_ap * t14 - t10 * t9;
    float t32 = ap_ap * t21 * t27 - float(5) * t21 * t31 - float(2) * t21 * ab_ap * t29;
    float t33 = float(2) * t21 * ab_ap * t30 + float(7) * t21 * t32 - ap_ap * t21 * t28;
    float t34 = t24 * delta_tau;
    float t35 = t3 * tau_lo;
    float t36 = t34 * t34;
    float t37 = ap_ap * t15 * t14 - float(3) * t13 * t14 - float(2) * t21 * ab_ap * t31;
    float t38 = float(2) * t21 * ab_ap * t32 + float(5) * t21 * t37 + ap_ap * t21 * t29;
    float t39 = float(7) * t38 * t21 + float(2) * t21 * ab_ap * t33 - ap_ap * t21 * t30;
    float t40 = t36 * delta_tau;
    float t41 = t9 - t13 * ab_ap * t14 - t5;
    float t42 = ap_ap * t21 * t31 + float(2) * t21 * ab_ap * t37 + float(3) * t21 * t41;
    float t43 = float(2) * t38 * t21 * ab_ap + float(5) * t21 * t42 - ap_ap * t21 * t32;
    float t44 = float(7) * t21 * t43 + float(2) * t21 * ab_ap * t39 - ap_ap * t21 * t33;
    float t45 = t25 * t25;
    F = (float(1) / float(35)) * t4 * t17 * t14 + (float(8) / float(35)) * delta_tau * t20 * t21 * t22 + (float(4) / float(15)) * delta_tau * delta_tau * t19 * t21 * t23 - (float(8) / float(15)) * t26 * t18 * t21 * t33 - (float(2) / float(3)) * t25 * t3 * t21 * t30 - (float(8) / float(15)) * t34 * t35 * t21 * t28 - (float(4) / float(15)) * t36 * t2 * t21 * t39 - (float(8) / float(105)) * t40 * tau_lo * t21 * t44 - (float(1) / float(105)) * t45 * t21 * (float(2) * t21 * ab_ap * t44 - float(7) * t21 * (ap_ap * t38 * t21 + float(5) * t21 * (ap_ap * t21 * t37 - float(2) * t21 * t42 * ab_ap - float(3) * t21 * (ap_ap * t13 * t14 + float(2) * t21 * t41 * ab_ap - J1)) - float(2) * t21 * ab_ap * t43) - ap_ap * t21 * t39);
  }
  float t46 = si.sigma * si.sigma;
  float t47 = t46 * t46;
  float t48 = t47 * t47;
  float t49 = t48 * si.sigma;
  f = F * length * t49;
  return f;
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (d/sigma)^(-9), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^9 |AB| int_0^1 tau^8 (|P - Gamma|^2)^(-9/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 130 +, 422 *, 7 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
float scalis_segment_inverse_i9_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float ab0 = end_b[0] - end_a[0];
  float ap0 = si.p[0] - end_a[0];
  float bp0 = si.p[0] - end_b[0];
  float ab1 = end_b[1] - end_a[1];
  float ap1 = si.p[1] - end_a[1];
  float bp1 = si.p[1] - end_b[1];
  float ab2 = end_b[2] - end_a[2];
  float ap2 = si.p[2] - end_a[2];
  float bp2 = si.p[2] - end_b[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  float ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  float ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ab2 * ap0 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  float foot0;
  float foot1;
  float foot2;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
    float t0 = float(1) / ab_ab;
    foot0 = ap0 - t0 * ab0 * ab_ap;
    foot1 = ap1 - t0 * ab1 * ab_ap;
    foot2 = ap2 - t0 * ab2 * ab_ap;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t1 = float(1) / cross_cross;
    X = length * t1 * (r0 * a_minus_b + r1 * ab_ap);
  }
  float t2 = float(1) / length;
  float J1 = skelconv_asinh(X) * t2;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t3 = delta_tau * delta_tau;
    float t4 = t3 * t3;
    float t5 = t4 * t4;
    float t6 = float(1) / ab_ab;
    float t7 = float(1) / r0;
    float t8 = t7 * t7;
    float t9 = t8 * t8;
    float t10 = float(1) / cross_cross;
    float t11 = float(1) / r1;
    float t12 = t11 * t11;
    float t13 = t12 * t12;
    float t14 = t7 * ab_ap + t11 * a_minus_b;
    float t15 = t11 * t12 * a_minus_b + t8 * t7 * ab_ap + float(2) * t14 * ab_ab * t10;
    float t16 = float(3) * t9 * t7 * ab_ap + float(3) * t11 * t13 * a_minus_b + float(4) * ab_ab * t10 * t15;
    float t17 = float(3) * t9 * t7 + t10 * ab_ap * t16 - float(3) * t11 * t13;
    float t18 = float(2) * t17 * t6 * ab_ap + float(5) * t10 * t15 - ap_ap * t10 * t16;
    float t19 = t10 * t15 * ab_ap + t8 * t7 - t11 * t12;
    float t20 = float(2) * t6 * ab_ap * t18 + float(5) * t19 * t6 - ap_ap * t17 * t6;
    float t21 = float(3) * t14 * t10 + float(2) * t19 * t6 * ab_ap - ap_ap * t10 * t15;
    float t22 = float(2) * t6 * ab_ap * t20 + float(5) * t21 * t6 - ap_ap * t6 * t18;
    float t23 = t7 + t14 * t10 * ab_ap - t11;
    float t24 = float(3) * t6 * t23 + float(2) * t21 * t6 * ab_ap - ap_ap * t19 * t6;
    float t25 = float(2) * t6 * ab_ap * t22 + float(5) * t6 * t24 - ap_ap * t6 * t20;
    float t26 = t9 * t8;
    float t27 = t13 * t12;
    float t28 = float(5) * t26 * t7 * ab_ap + float(5) * t11 * t27 * a_minus_b + float(2) * ab_ab * t10 * t16;
    float t29 = float(5) * t26 * t7 + t28 * t10 * ab_ap - float(5) * t11 * t27;
    float t30 = float(3) * ap_ap * t28 * t10 - float(6) * t6 * t29 * ab_ap - float(7) * t10 * t16;
    float t31 = float(2) * t6 * ab_ap * t30 + float(3) * ap_ap * t6 * t29 - float(7) * t17 * t6;
    float t32 = float(2) * t31 * t6 * ab_ap - ap_ap * t6 * t30 - float(7) * t6 * t18;
    float t33 = ap_ap * t31 * t6 + float(7) * t6 * t20 - float(2) * t6 * t32 * ab_ap;
    float t34 = float(2) * t33 * t6 * ab_ap + ap_ap * t6 * t32 + float(7) * t6 * t22;
    float t35 = float(2) * t6 * ab_ap * t34 + float(7) * t6 * t25 - ap_ap * t33 * t6;
    float t36 = t3 * delta_tau;
    float t37 = t36 * t36;
    float t38 = t37 * delta_tau;
    float t39 = tau_lo * tau_lo;
    float t40 = t39 * t39;
    float t41 = t40 * t40;
    float t42 = t39 * tau_lo;
    float t43 = t42 * t42;
    float t44 = t43 * tau_lo;
    float t45 = t4 * delta_tau;
    float t46 = t40 * tau_lo;
    F = (float(1) / float(105)) * t5 * t6 * (float(7) * (float(2) * t6 * ab_ap * t25 - float(5) * (ap_ap * t21 * t6 - float(3) * t6 * (float(2) * t6 * ab_ap * t23 + J1 - ap_ap * t14 * t10) - float(2) * t6 * t24 * ab_ap) * t6 - ap_ap * t6 * t22) * t6 + float(2) * t35 * t6 * ab_ap - ap_ap * t6 * t34) + (float(8) / float(105)) * t38 * tau_lo * t35 * t6 + (float(1) / float(35)) * t41 * t28 * t10 + (float(4) / float(15)) * t37 * t39 * t6 * t34 + (float(8) / float(35)) * delta_tau * t44 * t6 * t29 + (float(8) / float(15)) * t33 * t45 * t42 * t6 - (float(4) / float(15)) * t3 * t43 * t6 * t30 - (float(2) / float(3)) * t4 * t40 * t6 * t32 - (float(8) / float(15)) * t31 * t36 * t46 * t6;
    float t47 = t13 * t13;
    float t48 = t9 * t9;
    float t49 = float(8) * ab_ab * t28 * t10 + float(35) * t11 * t47 * a_minus_b + float(35) * t48 * t7 * ab_ap;
    float t50 = t10 * ab_ap * t49 + float(35) * t48 * t7 - float(35) * t11 * t47;
    float t51 = float(9) * t28 * t10 + float(2) * t50 * t6 * ab_ap - ap_ap * t10 * t49;
    float t52 = float(9) * t6 * t29 + float(2) * t6 * t51 * ab_ap - ap_ap * t50 * t6;
    float t53 = ap_ap * t6 * t51 + float(3) * t6 * t30 - float(2) * t6 * t52 * ab_ap;
    float t54 = float(3) * t31 * t6 + float(2) * t53 * t6 * ab_ap + ap_ap * t6 * t52;
    float t55 = float(3) * t6 * t32 + float(2) * t54 * t6 * ab_ap - ap_ap * t53 * t6;
    float t56 = float(2) * t55 * t6 * ab_ap - float(3) * t33 * t6 - ap_ap * t54 * t6;
    G_ap = (float(1) / float(315)) * t41 * t10 * t49 + (float(4) / float(45)) * t3 * t43 * t6 * t51 + (float(8) / float(45)) * t36 * t46 * t6 * t52 + (float(8) / float(315)) * t50 * delta_tau * t44 * t6 - (float(8) / float(315)) * t56 * t38 * tau_lo * t6 - (float(2) / float(9)) * t53 * t4 * t40 * t6 - (float(4) / float(45)) * t55 * t37 * t39 * t6 - (float(1) / float(315)) * t5 * t6 * (float(2) * t56 * t6 * ab_ap - float(3) * t6 * t34 - ap_ap * t55 * t6) - (float(8) / float(45)) * t45 * t54 * t42 * t6;
    float t57 = t11 * t11;
    float t58 = t57 * t57;
    float t59 = t58 * t58;
    float t60 = t59 * t11;
    float t61 = t7 * t7;
    float t62 = t61 * t61;
    float t63 = t62 * t62;
    float t64 = t63 * t7;
    G_E = -(float(1) / float(945)) * (float(168) * t36 * t46 * t6 * t30 + float(280) * t31 * t4 * t40 * t6 + float(105) * (t5 + float(28) * t37 * t39 + float(28) * t3 * t43 + float(56) * t45 * t42 + float(8) * t38 * tau_lo + float(56) * t36 * t46 + float(70) * t4 * t40 + t41 + float(8) * delta_tau * t44) * t60 + float(280) * t45 * t42 * t6 * t32 - float(168) * t3 * t43 * t6 * t29 - float(168) * t33 * t37 * t39 * t6 - float(24) * delta_tau * t44 * t28 * t10 - float(56) * t38 * tau_lo * t6 * t34 - float(105) * t41 * t64 - float(8) * t5 * t35 * t6) * t6;
  }
  float t65 = si.sigma * si.sigma;
  float t66 = t65 * t65;
  float t67 = t66 * t66;
  float t68 = t67 * si.sigma;
  float g_factor = -float(9) * length * t68;
  f = length * t68 * F;
  grad[0] = g_factor * (G_ap * foot0 - ab0 * G_E);
  grad[1] = -g_factor * (ab1 * G_E - foot1 * G_ap);
  grad[2] = g_factor * (G_ap * foot2 - ab2 * G_E);
  return f;
}

// the field, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (d/sigma)^(-10), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^10 |AB| int_0^1 tau^9 (|P - Gamma|^2)^(-10/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 93 +, 273 *, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float scalis_segment_inverse_i10_f(ScalisSegmentInput si) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float ab0 = end_b[0] - end_a[0];
  float ap0 = si.p[0] - end_a[0];
  float bp0 = si.p[0] - end_b[0];
  float ab1 = end_b[1] - end_a[1];
  float ap1 = si.p[1] - end_a[1];
  float bp1 = si.p[1] - end_b[1];
  float ab2 = end_b[2] - end_a[2];
  float ap2 = si.p[2] - end_a[2];
  float bp2 = si.p[2] - end_b[2];
  float ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  float ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ab2 * ap0 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float t0 = float(1) / ap_ap;
  float log_ratio = log(bp_bp * t0);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, ap_bp);
    float t3 = t0 * t0;
    float t4 = t3 * t0;
    float t5 = float(1) / cross_cross;
    float t6 = float(1) / bp_bp;
    float t7 = a_minus_b * t6 + ab_ab * J2 + ab_ap * t0;
    float t8 = t6 * t6;
    float t9 = float(3) * ab_ab * t5 * t7 + float(2) * ab_ap * t3 + float(2) * a_minus_b * t8;
    float t10 = t8 * t6;
    float t11 = float(8) * ab_ap * t4 + float(5) * ab_ab * t9 * t5 + float(8) * a_minus_b * t10;
    float t12 = t3 * t3;
    float t13 = t8 * t8;
    float t14 = float(7) * ab_ab * t11 * t5 + float(48) * ab_ap * t12 + float(48) * a_minus_b * t13;
    float t15 = t14 * t5 * ab_ap + float(48) * t12 - float(48) * t13;
    float t16 = tau_lo * tau_lo;
    float t17 = t16 * t16;
    float t18 = t17 * t17;
    float t19 = float(1) / ab_ab;
    float t20 = delta_tau * delta_tau;
    float t21 = t20 * t20;
    float t22 = t21 * delta_tau;
    float t23 = float(8) * t11 * t5 + float(2) * t15 * t19 * ab_ap - t14 * t5 * ap_ap;
    float t24 = t11 * t5 * ab_ap + float(8) * t4 - float(8) * t10;
    float t25 = t15 * t19 * ap_ap - float(2) * t19 * ab_ap * t23 - float(8) * t19 * t24;
    float t26 = t11 * t5 * ap_ap - float(2) * t19 * ab_ap * t24 - float(6) * t9 * t5;
    float t27 = t19 * t23 * ap_ap + float(8) * t26 * t19 + float(2) * t19 * t25 * ab_ap;
    float t28 = float(2) * t3 + t9 * t5 * ab_ap - float(2) * t8;
    float t29 = float(2) * t26 * t19 * ab_ap + t19 * t24 * ap_ap - float(6) * t19 * t28;
    float t30 = t19 * t25 * ap_ap - float(2) * t19 * t27 * ab_ap - float(8) * t19 * t29;
    float t31 = float(4) * t5 * t7 + float(2) * t19 * t28 * ab_ap - t9 * t5 * ap_ap;
    float t32 = float(2) * t19 * ab_ap * t29 - float(6) * t19 * t31 - t26 * t19 * ap_ap;
    float t33 = t19 * t27 * ap_ap + float(2) * t19 * t30 * ab_ap - float(8) * t19 * t32;
    float t34 = t16 * tau_lo;
    float t35 = t20 * delta_tau;
    float t36 = t35 * t35;
    float t37 = t18 * tau_lo;
    float t38 = t34 * t34;
    float t39 = t38 * tau_lo;
    float t40 = t21 * t21;
    float t41 = t40 * delta_tau;
    float t42 = t6 - t0 - t5 * ab_ap * t7;
    float t43 = float(2) * t19 * ab_ap * t42 + t5 * t7 * ap_ap - float(2) * J2;
    float t44 = t19 * t28 * ap_ap + float(4) * t19 * t42 - float(2) * t19 * ab_ap * t31;
    float t45 = float(4) * t19 * t43 + t19 * t31 * ap_ap + float(2) * t19 * t44 * ab_ap;
    float t46 = float(2) * t19 * t32 * ab_ap + float(6) * t19 * t44 - t19 * t29 * ap_ap;
    float t47 = float(6) * t45 * t19 + float(2) * t46 * t19 * ab_ap - t19 * t32 * ap_ap;
    float t48 = float(8) * t46 * t19 + t19 * t30 * ap_ap - float(2) * t33 * t19 * ab_ap;
    float t49 = float(8) * t47 * t19 + t33 * t19 * ap_ap + float(2) * t19 * ab_ap * t48;
    float t50 = t17 * tau_lo;
    float t51 = t36 * delta_tau;
    F = (float(3) / float(128)) * t15 * t18 * delta_tau * t19 + (float(21) / float(64)) * t17 * t22 * t19 * t30 + (float(7) / float(32)) * t33 * t34 * t36 * t19 + (float(1) / float(384)) * t37 * t14 * t5 + (float(3) / float(32)) * t39 * t20 * t19 * t23 - (float(1) / float(384)) * t41 * t19 * (float(2) * t19 * ab_ap * t49 - float(8) * t19 * (float(6) * (t19 * t44 * ap_ap + float(4) * t19 * (t19 * t42 * ap_ap + t19 * (log_ratio + float(2) * J2 * ab_ap) - float(2) * t19 * ab_ap * t43) - float(2) * t45 * t19 * ab_ap) * t19 + t46 * t19 * ap_ap - float(2) * t47 * t19 * ab_ap) - t19 * t48 * ap_ap) - (float(21) / float(64)) * t50 * t21 * t19 * t27 - (float(7) / float(32)) * t38 * t35 * t19 * t25 - (float(3) / float(128)) * tau_lo * t40 * t19 * t49 - (float(3) / float(32)) * t16 * t51 * t19 * t48;
  }
  float t52 = si.sigma * si.sigma;
  float t53 = t52 * t52;
  float t54 = t53 * si.sigma;
  float t55 = t54 * t54;
  f = F * length * t55;
  return f;
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (d/sigma)^(-10), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^10 |AB| int_0^1 tau^9 (|P - Gamma|^2)^(-10/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 147 +, 456 *, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float scalis_segment_inverse_i10_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float ab0 = end_b[0] - end_a[0];
  float ap0 = si.p[0] - end_a[0];
  float bp0 = si.p[0] - end_b[0];
  float ab1 = end_b[1] - end_a[1];
  float ap1 = si.p[1] - end_a[1];
  float bp1 = si.p[1] - end_b[1];
  float ab2 = end_b[2] - end_a[2];
  float ap2 = si.p[2] - end_a[2];
  float bp2 = si.p[2] - end_b[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  float ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ab2 * ap0 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  float cross_cross;
  float foot0;
  float foot1;
  float foot2;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
    float t0 = float(1) / ab_ab;
    foot0 = ap0 - t0 * ab0 * ab_ap;
    foot1 = ap1 - t0 * ab1 * ab_ap;
    foot2 = ap2 - t0 * ab2 * ab_ap;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  float ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float t1 = float(1) / ap_ap;
  float log_ratio = log(bp_bp * t1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t2 = sqrt(cross_cross);
    float t3 = float(1) / t2;
    float J2 = t3 * atan(t2, ap_bp);
    float t4 = float(1) / ab_ab;
    float t5 = float(1) / cross_cross;
    float t6 = t1 * t1;
    float t7 = t6 * t6;
    float t8 = float(1) / bp_bp;
    float t9 = t8 * t8;
    float t10 = t9 * t8;
    float t11 = ab_ap * t1 + t8 * a_minus_b + ab_ab * J2;
    float t12 = float(2) * t9 * a_minus_b + float(3) * ab_ab * t5 * t11 + float(2) * ab_ap * t6;
    float t13 = t6 * t1;
    float t14 = float(8) * t10 * a_minus_b + float(5) * ab_ab * t5 * t12 + float(8) * ab_ap * t13;
    float t15 = t9 * t9;
    float t16 = float(48) * ab_ap * t7 + float(7) * ab_ab * t5 * t14 + float(48) * t15 * a_minus_b;
    float t17 = t5 * ab_ap * t16 + float(48) * t7 - float(48) * t15;
    float t18 = tau_lo * tau_lo;
    float t19 = t18 * t18;
    float t20 = t19 * t19;
    float t21 = t20 * tau_lo;
    float t22 = float(8) * t5 * t14 + float(2) * t4 * ab_ap * t17 - t5 * t16 * ap_ap;
    float t23 = delta_tau * delta_tau;
    float t24 = t18 * tau_lo;
    float t25 = t24 * t24;
    float t26 = t25 * tau_lo;
    float t27 = float(8) * t13 + t5 * ab_ap * t14 - float(8) * t10;
    float t28 = t5 * ap_ap * t14 - float(2) * t4 * ab_ap * t27 - float(6) * t5 * t12;
    float t29 = float(2) * t9 - t5 * ab_ap * t12 - float(2) * t6;
    float t30 = float(2) * t4 * t28 * ab_ap + t4 * t27 * ap_ap + float(6) * t4 * t29;
    float t31 = t4 * ap_ap * t17 - float(8) * t4 * t27 - float(2) * t4 * t22 * ab_ap;
    float t32 = float(2) * t31 * t4 * ab_ap + t4 * t22 * ap_ap + float(8) * t4 * t28;
    float t33 = float(8) * t4 * t30 + float(2) * t4 * ab_ap * t32 - t31 * t4 * ap_ap;
    float t34 = t5 * t11 * ab_ap + t1 - t8;
    float t35 = float(4) * t5 * t11 - t5 * ap_ap * t12 - float(2) * t4 * t29 * ab_ap;
    float t36 = float(4) * t4 * t34 + t4 * t29 * ap_ap + float(2) * t4 * t35 * ab_ap;
    float t37 = float(2) * t4 * ab_ap * t30 - t4 * t28 * ap_ap - float(6) * t4 * t35;
    float t38 = float(6) * t4 * t36 + t4 * ap_ap * t30 - float(2) * t4 * ab_ap * t37;
    float t39 = float(2) * t4 * t33 * ab_ap + float(8) * t4 * t37 - t4 * ap_ap * t32;
    float t40 = t4 * t33 * ap_ap + float(8) * t4 * t38 - float(2) * t4 * ab_ap * t39;
    float t41 = t23 * delta_tau;
    float t42 = t41 * t41;
    float t43 = t42 * delta_tau;
    float t44 = t5 * t11 * ap_ap - float(2) * J2 - float(2) * t4 * ab_ap * t34;
    float t45 = float(2) * t4 * ab_ap * t36 - t4 * t35 * ap_ap - float(4) * t4 * t44;
    float t46 = float(2) * t4 * ab_ap * t38 + float(6) * t4 * t45 + t4 * ap_ap * t37;
    float t47 = t4 * t39 * ap_ap + float(2) * t4 * ab_ap * t40 + float(8) * t4 * t46;
    float t48 = t23 * t23;
    float t49 = t48 * t48;
    float t50 = t49 * delta_tau;
    float t51 = t19 * tau_lo;
    float t52 = t48 * delta_tau;
    F = (float(3) / float(128)) * t4 * t17 * delta_tau * t20 + (float(1) / float(384)) * t5 * t16 * t21 + (float(3) / float(32)) * t4 * t22 * t23 * t26 + (float(3) / float(32)) * t4 * t40 * t43 * t18 + (float(1) / float(384)) * t4 * (float(2) * t47 * t4 * ab_ap + float(8) * t4 * (float(6) * t4 * (float(2) * t4 * ab_ap * t45 + float(4) * t4 * (t4 * (float(2) * J2 * ab_ap + log_ratio) - t4 * ap_ap * t34 - float(2) * t4 * t44 * ab_ap) - t4 * t36 * ap_ap) + float(2) * t4 * t46 * ab_ap - t4 * t38 * ap_ap) - t4 * ap_ap * t40) * t50 + (float(3) / float(128)) * t47 * t4 * t49 * tau_lo - (float(21) / float(64)) * t4 * t48 * t32 * t51 - (float(7) / float(32)) * t31 * t4 * t41 * t25 - (float(21) / float(64)) * t4 * t33 * t52 * t19 - (float(7) / float(32)) * t4 * t39 * t42 * t24;
    float t53 = t15 * t8;
    float t54 = t7 * t1;
    float t55 = float(128) * ab_ap * t54 + float(3) * ab_ab * t5 * t16 + float(128) * t53 * a_minus_b;
    float t56 = float(128) * t53 - float(128) * t54 - t5 * ab_ap * t55;
    float t57 = float(10) * t5 * t16 - float(6) * t4 * ab_ap * t56 - float(3) * t5 * t55 * ap_ap;
    float t58 = float(10) * t4 * t17 + float(2) * t4 * ab_ap * t57 + float(3) * t4 * ap_ap * t56;
    float t59 = float(10) * t4 * t22 + float(2) * t4 * ab_ap * t58 - t4 * ap_ap * t57;
    float t60 = float(2) * t4 * t59 * ab_ap - float(10) * t31 * t4 - t4 * ap_ap * t58;
    float t61 = float(10) * t4 * t32 + t4 * t59 * ap_ap - float(2) * t4 * t60 * ab_ap;
    float t62 = float(2) * t4 * ab_ap * t61 + float(10) * t4 * t33 + t4 * t60 * ap_ap;
    float t63 = float(10) * t4 * t39 + float(2) * t4 * t62 * ab_ap - t4 * t61 * ap_ap;
    G_ap = (float(1) / float(3840)) * t4 * t50 * (float(10) * t4 * t40 + t4 * t62 * ap_ap - float(2) * t4 * ab_ap * t63) + (float(7) / float(320)) * t4 * t58 * t41 * t25 + (float(1) / float(1280)) * t5 * t55 * t21 + (float(21) / float(640)) * t4 * t60 * t52 * t19 + (float(3) / float(320)) * t4 * t57 * t23 * t26 + (float(21) / float(640)) * t4 * t59 * t48 * t51 - (float(9) / float(1280)) * t4 * t56 * delta_tau * t20 - (float(3) / float(320)) * t4 * t62 * t43 * t18 - (float(3) / float(1280)) * t4 * t63 * t49 * tau_lo - (float(7) / float(320)) * t4 * t61 * t42 * t24;
    G_E = (float(1) / float(1280)) * t4 * (float(3) * t47 * t4 * t50 + float(24) * t4 * t40 * t49 * tau_lo + float(24) * t4 * t17 * t23 * t26 + float(3) * t5 * t16 * delta_tau * t20 + float(84) * t4 * t22 * t41 * t25 + float(128) * t54 * t21 - float(210) * t4 * t52 * t32 * t19 - float(168) * t4 * t33 * t42 * t24 - float(128) * t53 * (float(36) * t23 * t26 + float(36) * t43 * t18 + float(84) * t42 * t24 + float(9) * t49 * tau_lo + float(84) * t41 * t25 + float(9) * delta_tau * t20 + float(126) * t48 * t51 + float(126) * t52 * t19 + t50 + t21) - float(168) * t31 * t4 * t48 * t51 - float(84) * t4 * t39 * t43 * t18);
  }
  float t64 = si.sigma * si.sigma;
  float t65 = t64 * t64;
  float t66 = t65 * si.sigma;
  float t67 = t66 * t66;
  float g_factor = -float(10) * length * t67;
  f = length * F * t67;
  grad[0] = -g_factor * (G_E * ab0 - foot0 * G_ap);
  grad[1] = (foot1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = (G_ap * foot2 - G_E * ab2) * g_factor;
  return f;
}

