// generated/glsl/scalis_segment_cauchy.glsl - SCALIS segment kernels of the cauchy family in GLSL (float; ES 3.00 and 4.50), generic forms only.
//
// GENERATED FILE: DO NOT EDIT. Regenerate with
//     skelconv-codegen --inverse 1:16 --cauchy 1:16 --compact 2:16 --weights 0:3 --polygon-inverse 3:12 --polygon-cauchy 3:12 --polygon-compact 4:12 --scalis-inverse 2:10 --scalis-cauchy 2:10 --out generated
// Generator: skelconv-codegen 0.1.0 (GiNaC 1.8.6)
// From: codegen/segment_families.cpp (the families) and codegen/segment_moments.cpp
// (recurrence (1) of Hubert & Cani unrolled; SPEC sec. 2, Hubert 2012 sec. 3).
// Unnormalised, as generated/scalis_segment_cauchy.hpp: f = c F / h is the caller's
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
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-2/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^2 |AB| int_0^1 tau^1 (|P - Gamma|^2 + sigma^2tau^2)^(-2/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 38 +, 52 *, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float scalis_segment_cauchy_i2_f(ScalisSegmentInput si) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float sigma2 = si.sigma * si.sigma;
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
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ap_bp = bp2 * ap2 + ap1 * bp1 + bp0 * ap0;
  float length = sqrt(ab_ab);
  float a = ab_ab + sigma2 * delta_tau * delta_tau;
  float b = ab_ap - sigma2 * delta_tau * tau_lo;
  float c = ap_ap + sigma2 * tau_lo * tau_lo;
  float radial0 = ab0 * tau_lo + ap0 * delta_tau;
  float radial1 = ap1 * delta_tau + ab1 * tau_lo;
  float radial2 = ab2 * tau_lo + ap2 * delta_tau;
  float D = cross_cross + sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0);
  float q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  float c_minus_b = ap_bp + sigma2 * tau_hi * tau_lo;
  float log_ratio = log(q1 / c);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float J2 = atan(t0, c_minus_b) / t0;
    F = (float(1) / float(2)) * (float(2) * J2 * b + log_ratio) * delta_tau / a + J2 * tau_lo;
  }
  f = sigma2 * F * length;
  return f;
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-2/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^2 |AB| int_0^1 tau^1 (|P - Gamma|^2 + sigma^2tau^2)^(-2/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 59 +, 102 *, 8 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float scalis_segment_cauchy_i2_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float sigma2 = si.sigma * si.sigma;
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
  float ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  float ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  float ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a = ab_ab + delta_tau * delta_tau * sigma2;
  float b = ab_ap - delta_tau * tau_lo * sigma2;
  float c = tau_lo * tau_lo * sigma2 + ap_ap;
  float radial0 = ap0 * delta_tau + ab0 * tau_lo;
  float radial1 = ap1 * delta_tau + ab1 * tau_lo;
  float radial2 = ap2 * delta_tau + ab2 * tau_lo;
  float D = cross_cross + (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2;
  float a_minus_b = tau_hi * delta_tau * sigma2 - ab_bp;
  float q1 = tau_hi * tau_hi * sigma2 + bp_bp;
  float c_minus_b = ap_bp + tau_hi * tau_lo * sigma2;
  float t1 = float(1) / c;
  float log_ratio = log(q1 * t1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t2 = sqrt(D);
    float t3 = float(1) / t2;
    float J2 = atan(t2, c_minus_b) * t3;
    float t4 = float(1) / a;
    F = J2 * tau_lo + (float(1) / float(2)) * (float(2) * b * J2 + log_ratio) * delta_tau * t4;
    float t5 = float(1) / q1;
    float t6 = b * t1 + a_minus_b * t5 + J2 * a;
    float t7 = float(1) / D;
    G_ap = (float(1) / float(2)) * t6 * tau_lo * t7 - (float(1) / float(2)) * (t5 - b * t6 * t7 - t1) * delta_tau * t4;
    G_E = (float(1) / float(2)) * t4 * (J2 * delta_tau + t1 * tau_lo - t5 * (delta_tau + tau_lo));
  }
  float t8 = float(1) / ab_ab;
  float t9 = float(1) / a;
  float foot_offset = t8 * (ab_ap * delta_tau + ab_ab * tau_lo) * delta_tau * t9 * sigma2;
  float foot_h0 = foot0 + ab0 * foot_offset;
  float foot_h1 = foot1 + ab1 * foot_offset;
  float foot_h2 = foot2 + ab2 * foot_offset;
  float g_factor = -float(2) * length * sigma2;
  f = F * length * sigma2;
  grad[0] = -(ab0 * G_E - foot_h0 * G_ap) * g_factor;
  grad[1] = -g_factor * (ab1 * G_E - G_ap * foot_h1);
  grad[2] = -g_factor * (ab2 * G_E - G_ap * foot_h2);
  return f;
}

// the field, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-3/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^3 |AB| int_0^1 tau^2 (|P - Gamma|^2 + sigma^2tau^2)^(-3/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 44 +, 70 *, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
float scalis_segment_cauchy_i3_f(ScalisSegmentInput si) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float sigma2 = si.sigma * si.sigma;
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
  float ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ap2 * ab1 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ap2 * ab0;
  float plain_cross2 = ap1 * ab0 - ap0 * ab1;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float t0 = delta_tau * delta_tau;
  float a = t0 * sigma2 + ab_ab;
  float b = ab_ap - tau_lo * delta_tau * sigma2;
  float t1 = tau_lo * tau_lo;
  float c = t1 * sigma2 + ap_ap;
  float radial0 = tau_lo * ab0 + ap0 * delta_tau;
  float radial1 = ap1 * delta_tau + tau_lo * ab1;
  float radial2 = ap2 * delta_tau + tau_lo * ab2;
  float D = cross_cross + (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2;
  float a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  float q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t2 = float(1) / D;
    float t3 = sqrt(a);
    X = t2 * t3 * (a_minus_b * r0 + b * r1);
  }
  float t4 = sqrt(a);
  float t5 = float(1) / t4;
  float J1 = t5 * skelconv_asinh(X);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t6 = float(1) / D;
    float t7 = float(1) / r1;
    float t8 = float(1) / r0;
    float t9 = a_minus_b * t7 + t8 * b;
    float t10 = t7 - t8 - t6 * t9 * b;
    float t11 = float(1) / a;
    F = t1 * t6 * t9 - float(2) * t10 * tau_lo * delta_tau * t11 - t0 * t11 * (float(2) * t10 * t11 * b + c * t6 * t9 - J1);
  }
  f = length * sigma2 * F * si.sigma;
  return f;
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-3/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^3 |AB| int_0^1 tau^2 (|P - Gamma|^2 + sigma^2tau^2)^(-3/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 67 +, 144 *, 9 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
float scalis_segment_cauchy_i3_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float sigma2 = si.sigma * si.sigma;
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
  float t1 = delta_tau * delta_tau;
  float a = t1 * sigma2 + ab_ab;
  float b = ab_ap - delta_tau * tau_lo * sigma2;
  float t2 = tau_lo * tau_lo;
  float c = ap_ap + t2 * sigma2;
  float radial0 = ab0 * tau_lo + ap0 * delta_tau;
  float radial1 = ap1 * delta_tau + tau_lo * ab1;
  float radial2 = ab2 * tau_lo + ap2 * delta_tau;
  float D = cross_cross + (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2;
  float a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  float q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t3 = float(1) / D;
    float t4 = sqrt(a);
    X = (r1 * b + r0 * a_minus_b) * t3 * t4;
  }
  float t5 = sqrt(a);
  float t6 = float(1) / t5;
  float J1 = skelconv_asinh(X) * t6;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t7 = float(1) / r0;
    float t8 = float(1) / D;
    float t9 = float(1) / r1;
    float t10 = t7 * b + t9 * a_minus_b;
    float t11 = t7 + t8 * t10 * b - t9;
    float t12 = float(1) / a;
    F = float(2) * t11 * delta_tau * tau_lo * t12 + t8 * t2 * t10 - t1 * (c * t8 * t10 - J1 - float(2) * t11 * t12 * b) * t12;
    float t13 = t7 * t7;
    float t14 = t9 * t9;
    float t15 = t13 * t7 * b + float(2) * t8 * a * t10 + t14 * t9 * a_minus_b;
    float t16 = t14 * t9 - t13 * t7 - t15 * t8 * b;
    G_ap = (float(1) / float(3)) * t15 * t8 * t2 + (float(1) / float(3)) * (float(3) * t8 * t10 - c * t15 * t8 - float(2) * t12 * b * t16) * t1 * t12 - (float(2) / float(3)) * delta_tau * tau_lo * t12 * t16;
    float t17 = t7 * t7;
    float t18 = t17 * t7;
    float t19 = t9 * t9;
    float t20 = t19 * t9;
    G_E = (float(1) / float(3)) * (t18 * t2 + float(2) * t11 * t1 * t12 + float(2) * t8 * delta_tau * tau_lo * t10 - t20 * (t2 + float(2) * delta_tau * tau_lo + t1)) * t12;
  }
  float t21 = float(1) / a;
  float t22 = float(1) / ab_ab;
  float foot_offset = (ab_ap * delta_tau + tau_lo * ab_ab) * delta_tau * t21 * sigma2 * t22;
  float foot_h0 = foot0 + ab0 * foot_offset;
  float foot_h1 = foot_offset * ab1 + foot1;
  float foot_h2 = foot2 + ab2 * foot_offset;
  float g_factor = -float(3) * si.sigma * length * sigma2;
  f = si.sigma * length * F * sigma2;
  grad[0] = (G_ap * foot_h0 - ab0 * G_E) * g_factor;
  grad[1] = -(G_E * ab1 - G_ap * foot_h1) * g_factor;
  grad[2] = (G_ap * foot_h2 - ab2 * G_E) * g_factor;
  return f;
}

// the field, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-4/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^4 |AB| int_0^1 tau^3 (|P - Gamma|^2 + sigma^2tau^2)^(-4/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 51 +, 90 *, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float scalis_segment_cauchy_i4_f(ScalisSegmentInput si) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float sigma2 = si.sigma * si.sigma;
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
  float ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
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
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  float length = sqrt(ab_ab);
  float t0 = delta_tau * delta_tau;
  float a = ab_ab + t0 * sigma2;
  float b = ab_ap - delta_tau * sigma2 * tau_lo;
  float t1 = tau_lo * tau_lo;
  float c = ap_ap + sigma2 * t1;
  float radial0 = ab0 * tau_lo + delta_tau * ap0;
  float radial1 = delta_tau * ap1 + ab1 * tau_lo;
  float radial2 = ab2 * tau_lo + delta_tau * ap2;
  float D = cross_cross + sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1);
  float a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  float q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  float c_minus_b = ap_bp + sigma2 * tau_hi * tau_lo;
  float t2 = float(1) / c;
  float log_ratio = log(t2 * q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t3 = sqrt(D);
    float t4 = float(1) / t3;
    float J2 = t4 * atan(t3, c_minus_b);
    float t5 = float(1) / a;
    float t6 = float(1) / D;
    float t7 = float(1) / q1;
    float t8 = a * J2 + b * t2 + a_minus_b * t7;
    float t9 = t2 + t6 * b * t8 - t7;
    float t10 = t0 * delta_tau;
    float t11 = float(2) * t5 * t9 * b + float(2) * J2 - t6 * c * t8;
    float t12 = t1 * tau_lo;
    F = (float(3) / float(2)) * delta_tau * t5 * t9 * t1 + (float(1) / float(2)) * t10 * t5 * (float(2) * t5 * b * t11 + t5 * (log_ratio + float(2) * J2 * b) - t5 * t9 * c) + (float(1) / float(2)) * t6 * t8 * t12 + (float(3) / float(2)) * t0 * t5 * t11 * tau_lo;
  }
  f = sigma2 * sigma2 * F * length;
  return f;
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-4/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^4 |AB| int_0^1 tau^3 (|P - Gamma|^2 + sigma^2tau^2)^(-4/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 79 +, 178 *, 8 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float scalis_segment_cauchy_i4_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float sigma2 = si.sigma * si.sigma;
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
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  float ap_bp = bp2 * ap2 + bp0 * ap0 + bp1 * ap1;
  float length = sqrt(ab_ab);
  float t1 = delta_tau * delta_tau;
  float a = t1 * sigma2 + ab_ab;
  float b = ab_ap - delta_tau * tau_lo * sigma2;
  float t2 = tau_lo * tau_lo;
  float c = ap_ap + t2 * sigma2;
  float radial0 = tau_lo * ab0 + delta_tau * ap0;
  float radial1 = tau_lo * ab1 + delta_tau * ap1;
  float radial2 = tau_lo * ab2 + delta_tau * ap2;
  float D = sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) + cross_cross;
  float a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  float q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  float c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  float t3 = float(1) / c;
  float log_ratio = log(q1 * t3);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t4 = sqrt(D);
    float t5 = float(1) / t4;
    float J2 = t5 * atan(t4, c_minus_b);
    float t6 = t2 * tau_lo;
    float t7 = float(1) / D;
    float t8 = float(1) / q1;
    float t9 = b * t3 + a * J2 + a_minus_b * t8;
    float t10 = float(1) / a;
    float t11 = t7 * b * t9 + t3 - t8;
    float t12 = t7 * t9 * c - float(2) * t10 * b * t11 - float(2) * J2;
    float t13 = t1 * delta_tau;
    F = (float(1) / float(2)) * t6 * t7 * t9 + (float(3) / float(2)) * delta_tau * t2 * t10 * t11 - (float(3) / float(2)) * t1 * tau_lo * t10 * t12 - (float(1) / float(2)) * t13 * t10 * (float(2) * t10 * b * t12 + t10 * c * t11 - (log_ratio + float(2) * b * J2) * t10);
    float t14 = t8 * t8;
    float t15 = t3 * t3;
    float t16 = float(2) * a_minus_b * t14 + float(3) * t7 * a * t9 + float(2) * b * t15;
    float t17 = float(2) * t14 - t7 * b * t16 - float(2) * t15;
    float t18 = t7 * t16 * c + float(2) * t10 * t17 * b - float(4) * t7 * t9;
    G_ap = (float(1) / float(8)) * t6 * t7 * t16 - (float(3) / float(8)) * t1 * tau_lo * t10 * t18 - (float(1) / float(8)) * t13 * t10 * (float(2) * t10 * b * t18 - t10 * t17 * c - float(4) * t10 * t11) - (float(3) / float(8)) * delta_tau * t2 * t10 * t17;
    G_E = (float(1) / float(8)) * t10 * (float(6) * t1 * tau_lo * t10 * t11 + float(3) * delta_tau * t2 * t7 * t9 + float(2) * t6 * t15 - float(2) * t14 * (t6 + t13 + float(3) * delta_tau * t2 + float(3) * t1 * tau_lo) - float(3) * t13 * t10 * t12);
  }
  float t19 = float(1) / a;
  float t20 = float(1) / ab_ab;
  float foot_offset = delta_tau * t19 * sigma2 * (tau_lo * ab_ab + delta_tau * ab_ap) * t20;
  float foot_h0 = foot0 + ab0 * foot_offset;
  float foot_h1 = foot1 + ab1 * foot_offset;
  float foot_h2 = ab2 * foot_offset + foot2;
  float t21 = sigma2 * sigma2;
  float g_factor = -float(4) * t21 * length;
  f = t21 * F * length;
  grad[0] = -g_factor * (G_E * ab0 - foot_h0 * G_ap);
  grad[1] = -g_factor * (G_E * ab1 - foot_h1 * G_ap);
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot_h2);
  return f;
}

// the field, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-5/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^5 |AB| int_0^1 tau^4 (|P - Gamma|^2 + sigma^2tau^2)^(-5/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 56 +, 119 *, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
float scalis_segment_cauchy_i5_f(ScalisSegmentInput si) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float sigma2 = si.sigma * si.sigma;
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
  float ab_ap = ap1 * ab1 + ab2 * ap2 + ab0 * ap0;
  float ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  float plain_cross0 = ab1 * ap2 - ap1 * ab2;
  float plain_cross1 = ab2 * ap0 - ab0 * ap2;
  float plain_cross2 = ap1 * ab0 - ab1 * ap0;
  float plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float length = sqrt(ab_ab);
  float t0 = delta_tau * delta_tau;
  float a = t0 * sigma2 + ab_ab;
  float b = ab_ap - delta_tau * tau_lo * sigma2;
  float t1 = tau_lo * tau_lo;
  float c = ap_ap + t1 * sigma2;
  float radial0 = tau_lo * ab0 + delta_tau * ap0;
  float radial1 = ap1 * delta_tau + tau_lo * ab1;
  float radial2 = delta_tau * ap2 + tau_lo * ab2;
  float D = sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) + cross_cross;
  float a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  float q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t2 = float(1) / D;
    float t3 = sqrt(a);
    X = t2 * (b * r1 + r0 * a_minus_b) * t3;
  }
  float t4 = sqrt(a);
  float t5 = float(1) / t4;
  float J1 = t5 * skelconv_asinh(X);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t6 = float(1) / r0;
    float t7 = t6 * t6;
    float t8 = float(1) / D;
    float t9 = float(1) / r1;
    float t10 = t9 * t9;
    float t11 = a_minus_b * t9 + t6 * b;
    float t12 = t10 * a_minus_b * t9 + t6 * b * t7 + float(2) * t8 * a * t11;
    float t13 = t6 * t7 + t8 * t12 * b - t10 * t9;
    float t14 = t1 * tau_lo;
    float t15 = float(1) / a;
    float t16 = t1 * t1;
    float t17 = float(2) * t13 * t15 * b + float(3) * t8 * t11 - t8 * t12 * c;
    float t18 = t0 * delta_tau;
    float t19 = t6 + t8 * t11 * b - t9;
    float t20 = float(3) * t15 * t19 + float(2) * t15 * t17 * b - t13 * t15 * c;
    float t21 = t0 * t0;
    F = (float(4) / float(3)) * t13 * delta_tau * t14 * t15 + (float(1) / float(3)) * t8 * t16 * t12 + float(2) * t0 * t1 * t15 * t17 + (float(4) / float(3)) * t18 * tau_lo * t15 * t20 - (float(1) / float(3)) * t21 * t15 * (t15 * t17 * c - float(2) * t15 * t20 * b - float(3) * t15 * (float(2) * t15 * t19 * b + J1 - t8 * t11 * c));
  }
  f = sigma2 * sigma2 * F * si.sigma * length;
  return f;
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-5/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^5 |AB| int_0^1 tau^4 (|P - Gamma|^2 + sigma^2tau^2)^(-5/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 89 +, 235 *, 9 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
float scalis_segment_cauchy_i5_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float sigma2 = si.sigma * si.sigma;
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
  float ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
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
    foot0 = ap0 - ab0 * ab_ap * t0;
    foot1 = ap1 - ab1 * ab_ap * t0;
    foot2 = ap2 - ab2 * ab_ap * t0;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  float length = sqrt(ab_ab);
  float t1 = delta_tau * delta_tau;
  float a = t1 * sigma2 + ab_ab;
  float b = ab_ap - delta_tau * tau_lo * sigma2;
  float t2 = tau_lo * tau_lo;
  float c = t2 * sigma2 + ap_ap;
  float radial0 = ap0 * delta_tau + ab0 * tau_lo;
  float radial1 = ap1 * delta_tau + ab1 * tau_lo;
  float radial2 = ab2 * tau_lo + ap2 * delta_tau;
  float D = cross_cross + (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2;
  float a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  float q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t3 = float(1) / D;
    float t4 = sqrt(a);
    X = t3 * t4 * (b * r1 + r0 * a_minus_b);
  }
  float t5 = sqrt(a);
  float t6 = float(1) / t5;
  float J1 = skelconv_asinh(X) * t6;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t7 = float(1) / a;
    float t8 = float(1) / D;
    float t9 = float(1) / r1;
    float t10 = float(1) / r0;
    float t11 = a_minus_b * t9 + b * t10;
    float t12 = t10 * t10;
    float t13 = t9 * t9;
    float t14 = b * t12 * t10 + float(2) * t8 * a * t11 + t13 * a_minus_b * t9;
    float t15 = t12 * t10 + b * t14 * t8 - t13 * t9;
    float t16 = float(3) * t8 * t11 + float(2) * b * t15 * t7 - t14 * c * t8;
    float t17 = t2 * tau_lo;
    float t18 = t2 * t2;
    float t19 = t9 - b * t8 * t11 - t10;
    float t20 = float(3) * t19 * t7 + c * t15 * t7 - float(2) * b * t7 * t16;
    float t21 = t1 * delta_tau;
    float t22 = t1 * t1;
    F = float(2) * t1 * t2 * t7 * t16 + (float(4) / float(3)) * delta_tau * t15 * t17 * t7 + (float(1) / float(3)) * t14 * t8 * t18 - (float(4) / float(3)) * t20 * t21 * tau_lo * t7 - (float(1) / float(3)) * t22 * t7 * (float(2) * b * t20 * t7 + c * t7 * t16 - float(3) * (J1 - c * t8 * t11 - float(2) * b * t19 * t7) * t7);
    float t23 = t13 * t13;
    float t24 = t12 * t12;
    float t25 = float(4) * t14 * t8 * a + float(3) * t23 * a_minus_b * t9 + float(3) * b * t24 * t10;
    float t26 = float(3) * t23 * t9 - b * t8 * t25 - float(3) * t24 * t10;
    float t27 = float(5) * t14 * t8 - c * t8 * t25 - float(2) * b * t26 * t7;
    float t28 = c * t26 * t7 + float(5) * t15 * t7 + float(2) * b * t27 * t7;
    G_ap = (float(1) / float(15)) * t8 * t25 * t18 + (float(4) / float(15)) * t21 * tau_lo * t7 * t28 + (float(2) / float(5)) * t27 * t1 * t2 * t7 + (float(1) / float(15)) * (float(2) * b * t7 * t28 + float(5) * t7 * t16 - c * t27 * t7) * t22 * t7 - (float(4) / float(15)) * delta_tau * t26 * t17 * t7;
    float t29 = t9 * t9;
    float t30 = t29 * t29;
    float t31 = t30 * t9;
    float t32 = t10 * t10;
    float t33 = t32 * t32;
    float t34 = t33 * t10;
    G_E = -(float(1) / float(15)) * (float(4) * t20 * t22 * t7 + float(3) * (float(4) * delta_tau * t17 + t18 + float(4) * t21 * tau_lo + float(6) * t1 * t2 + t22) * t31 - float(3) * t34 * t18 - float(12) * t1 * t15 * t2 * t7 - float(4) * t14 * t8 * delta_tau * t17 - float(12) * t21 * tau_lo * t7 * t16) * t7;
  }
  float t35 = float(1) / a;
  float t36 = float(1) / ab_ab;
  float foot_offset = (tau_lo * ab_ab + ab_ap * delta_tau) * delta_tau * t35 * sigma2 * t36;
  float foot_h0 = ab0 * foot_offset + foot0;
  float foot_h1 = ab1 * foot_offset + foot1;
  float foot_h2 = foot2 + ab2 * foot_offset;
  float t37 = sigma2 * sigma2;
  float g_factor = -float(5) * si.sigma * length * t37;
  f = si.sigma * length * F * t37;
  grad[0] = -(ab0 * G_E - G_ap * foot_h0) * g_factor;
  grad[1] = -(ab1 * G_E - G_ap * foot_h1) * g_factor;
  grad[2] = -(ab2 * G_E - G_ap * foot_h2) * g_factor;
  return f;
}

// the field, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-6/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^6 |AB| int_0^1 tau^5 (|P - Gamma|^2 + sigma^2tau^2)^(-6/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 65 +, 144 *, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float scalis_segment_cauchy_i6_f(ScalisSegmentInput si) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float sigma2 = si.sigma * si.sigma;
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  float ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  float length = sqrt(ab_ab);
  float t0 = delta_tau * delta_tau;
  float a = ab_ab + t0 * sigma2;
  float b = ab_ap - delta_tau * tau_lo * sigma2;
  float t1 = tau_lo * tau_lo;
  float c = t1 * sigma2 + ap_ap;
  float radial0 = ab0 * tau_lo + ap0 * delta_tau;
  float radial1 = ab1 * tau_lo + ap1 * delta_tau;
  float radial2 = ab2 * tau_lo + ap2 * delta_tau;
  float D = cross_cross + (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2;
  float a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  float q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  float c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  float t2 = float(1) / c;
  float log_ratio = log(t2 * q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t3 = sqrt(D);
    float t4 = float(1) / t3;
    float J2 = atan(t3, c_minus_b) * t4;
    float t5 = float(1) / a;
    float t6 = float(1) / q1;
    float t7 = a * J2 + b * t2 + a_minus_b * t6;
    float t8 = float(1) / D;
    float t9 = b * t7 * t8 + t2 - t6;
    float t10 = float(2) * b * t5 * t9 + float(2) * J2 - c * t7 * t8;
    float t11 = t6 * t6;
    float t12 = t2 * t2;
    float t13 = float(2) * a_minus_b * t11 + float(3) * t7 * t8 * a + float(2) * b * t12;
    float t14 = float(2) * t11 - b * t8 * t13 - float(2) * t12;
    float t15 = c * t8 * t13 + float(2) * b * t14 * t5 - float(4) * t7 * t8;
    float t16 = float(4) * t5 * t9 + t14 * c * t5 - float(2) * b * t15 * t5;
    float t17 = float(4) * t10 * t5 + t15 * c * t5 + float(2) * b * t16 * t5;
    float t18 = t0 * t0;
    float t19 = t18 * delta_tau;
    float t20 = t1 * t1;
    float t21 = t20 * tau_lo;
    float t22 = t0 * delta_tau;
    float t23 = t1 * tau_lo;
    F = (float(1) / float(8)) * (float(4) * (float(2) * t10 * b * t5 + (float(2) * b * J2 + log_ratio) * t5 - c * t5 * t9) * t5 + float(2) * t17 * b * t5 - t16 * c * t5) * t19 * t5 + (float(1) / float(8)) * t21 * t8 * t13 + (float(5) / float(4)) * t16 * t22 * t1 * t5 + (float(5) / float(8)) * t17 * t18 * tau_lo * t5 - (float(5) / float(8)) * t14 * delta_tau * t20 * t5 - (float(5) / float(4)) * t15 * t0 * t23 * t5;
  }
  float t24 = sigma2 * sigma2;
  float t25 = t24 * sigma2;
  f = length * t25 * F;
  return f;
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-6/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^6 |AB| int_0^1 tau^5 (|P - Gamma|^2 + sigma^2tau^2)^(-6/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 103 +, 266 *, 8 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float scalis_segment_cauchy_i6_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float sigma2 = si.sigma * si.sigma;
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
  float ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
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
  float ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  float ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  float length = sqrt(ab_ab);
  float t1 = delta_tau * delta_tau;
  float a = ab_ab + sigma2 * t1;
  float b = ab_ap - tau_lo * sigma2 * delta_tau;
  float t2 = tau_lo * tau_lo;
  float c = t2 * sigma2 + ap_ap;
  float radial0 = tau_lo * ab0 + ap0 * delta_tau;
  float radial1 = tau_lo * ab1 + ap1 * delta_tau;
  float radial2 = tau_lo * ab2 + ap2 * delta_tau;
  float D = cross_cross + (radial0 * radial0 + radial2 * radial2 + radial1 * radial1) * sigma2;
  float a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  float q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  float c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  float t3 = float(1) / c;
  float log_ratio = log(q1 * t3);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t4 = sqrt(D);
    float t5 = float(1) / t4;
    float J2 = atan(t4, c_minus_b) * t5;
    float t6 = t2 * t2;
    float t7 = float(1) / a;
    float t8 = t3 * t3;
    float t9 = float(1) / q1;
    float t10 = b * t3 + a_minus_b * t9 + a * J2;
    float t11 = float(1) / D;
    float t12 = t9 * t9;
    float t13 = float(3) * a * t10 * t11 + float(2) * a_minus_b * t12 + float(2) * b * t8;
    float t14 = float(2) * t8 + t13 * b * t11 - float(2) * t12;
    float t15 = b * t10 * t11 + t3 - t9;
    float t16 = float(2) * t7 * t15 * b + float(2) * J2 - t10 * c * t11;
    float t17 = float(4) * t10 * t11 + float(2) * t7 * t14 * b - t13 * c * t11;
    float t18 = float(2) * t7 * b * t17 + float(4) * t7 * t15 - t7 * t14 * c;
    float t19 = float(2) * t7 * b * t18 + float(4) * t7 * t16 - t7 * t17 * c;
    float t20 = t1 * t1;
    float t21 = t20 * delta_tau;
    float t22 = t2 * tau_lo;
    float t23 = t1 * delta_tau;
    float t24 = t6 * tau_lo;
    F = (float(5) / float(8)) * t6 * t7 * t14 * delta_tau + (float(1) / float(8)) * t7 * (float(4) * t7 * (t7 * (float(2) * b * J2 + log_ratio) + float(2) * t7 * b * t16 - t7 * t15 * c) + float(2) * t7 * t19 * b - t7 * t18 * c) * t21 + (float(5) / float(4)) * t22 * t7 * t17 * t1 + (float(5) / float(4)) * t2 * t7 * t18 * t23 + (float(5) / float(8)) * tau_lo * t7 * t19 * t20 + (float(1) / float(8)) * t24 * t13 * t11;
    float t25 = t12 * t9;
    float t26 = t8 * t3;
    float t27 = float(5) * a * t13 * t11 + float(8) * a_minus_b * t25 + float(8) * b * t26;
    float t28 = float(8) * t26 + b * t27 * t11 - float(8) * t25;
    float t29 = c * t27 * t11 - float(2) * t28 * t7 * b - float(6) * t13 * t11;
    float t30 = float(6) * t7 * t14 - float(2) * t7 * b * t29 - t28 * t7 * c;
    float t31 = float(2) * t7 * t30 * b + float(6) * t7 * t17 + t7 * c * t29;
    G_ap = (float(5) / float(24)) * t2 * t7 * t30 * t23 + (float(1) / float(48)) * t24 * t27 * t11 + (float(5) / float(48)) * t28 * t6 * t7 * delta_tau + (float(5) / float(48)) * tau_lo * t7 * t31 * t20 - (float(1) / float(48)) * t7 * (t7 * t30 * c - float(6) * t7 * t18 - float(2) * t7 * b * t31) * t21 - (float(5) / float(24)) * t22 * t7 * t29 * t1;
    G_E = (float(1) / float(48)) * t7 * (float(30) * t2 * t7 * t17 * t23 + float(20) * tau_lo * t7 * t18 * t20 + float(5) * t6 * t13 * t11 * delta_tau + float(5) * t7 * t19 * t21 + float(8) * t24 * t26 + float(20) * t22 * t7 * t14 * t1 - float(8) * t25 * (float(5) * tau_lo * t20 + float(10) * t2 * t23 + t21 + float(10) * t22 * t1 + float(5) * t6 * delta_tau + t24));
  }
  float t32 = float(1) / a;
  float t33 = float(1) / ab_ab;
  float foot_offset = t32 * sigma2 * t33 * (ab_ap * delta_tau + tau_lo * ab_ab) * delta_tau;
  float foot_h0 = foot_offset * ab0 + foot0;
  float foot_h1 = foot1 + foot_offset * ab1;
  float foot_h2 = foot_offset * ab2 + foot2;
  float t34 = sigma2 * sigma2;
  float t35 = t34 * sigma2;
  float g_factor = -float(6) * t35 * length;
  f = F * t35 * length;
  grad[0] = -g_factor * (ab0 * G_E - G_ap * foot_h0);
  grad[1] = g_factor * (foot_h1 * G_ap - ab1 * G_E);
  grad[2] = -(ab2 * G_E - foot_h2 * G_ap) * g_factor;
  return f;
}

// the field, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-7/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^7 |AB| int_0^1 tau^6 (|P - Gamma|^2 + sigma^2tau^2)^(-7/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 72 +, 182 *, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
float scalis_segment_cauchy_i7_f(ScalisSegmentInput si) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float sigma2 = si.sigma * si.sigma;
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
  float ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
  float ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ab2 * ap0 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  float length = sqrt(ab_ab);
  float t0 = delta_tau * delta_tau;
  float a = ab_ab + t0 * sigma2;
  float b = ab_ap - delta_tau * tau_lo * sigma2;
  float t1 = tau_lo * tau_lo;
  float c = t1 * sigma2 + ap_ap;
  float radial0 = ap0 * delta_tau + ab0 * tau_lo;
  float radial1 = ap1 * delta_tau + ab1 * tau_lo;
  float radial2 = ab2 * tau_lo + ap2 * delta_tau;
  float D = cross_cross + (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2;
  float a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  float q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t2 = float(1) / D;
    float t3 = sqrt(a);
    X = (b * r1 + a_minus_b * r0) * t2 * t3;
  }
  float t4 = sqrt(a);
  float t5 = float(1) / t4;
  float J1 = skelconv_asinh(X) * t5;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t6 = float(1) / D;
    float t7 = float(1) / r0;
    float t8 = t7 * t7;
    float t9 = t8 * t8;
    float t10 = float(1) / r1;
    float t11 = t10 * t10;
    float t12 = t11 * t11;
    float t13 = b * t7 + a_minus_b * t10;
    float t14 = float(2) * t13 * t6 * a + a_minus_b * t10 * t11 + b * t8 * t7;
    float t15 = float(3) * b * t9 * t7 + float(3) * a_minus_b * t10 * t12 + float(4) * t6 * a * t14;
    float t16 = b * t6 * t15 + float(3) * t9 * t7 - float(3) * t10 * t12;
    float t17 = t1 * t1;
    float t18 = t17 * tau_lo;
    float t19 = float(1) / a;
    float t20 = t1 * tau_lo;
    float t21 = t20 * t20;
    float t22 = float(2) * b * t16 * t19 + float(5) * t6 * t14 - c * t6 * t15;
    float t23 = t10 * t11 - t8 * t7 - b * t6 * t14;
    float t24 = t10 - t7 - b * t13 * t6;
    float t25 = float(2) * b * t23 * t19 + c * t6 * t14 - float(3) * t13 * t6;
    float t26 = t23 * c * t19 - float(3) * t24 * t19 - float(2) * b * t25 * t19;
    float t27 = float(5) * t23 * t19 + t16 * c * t19 - float(2) * b * t22 * t19;
    float t28 = float(5) * t25 * t19 + c * t22 * t19 + float(2) * b * t27 * t19;
    float t29 = float(5) * t26 * t19 + c * t27 * t19 - float(2) * b * t28 * t19;
    float t30 = t0 * t0;
    float t31 = t30 * delta_tau;
    float t32 = t0 * delta_tau;
    float t33 = t32 * t32;
    F = (float(2) / float(5)) * t16 * delta_tau * t18 * t19 + (float(1) / float(15)) * t6 * t21 * t15 + t0 * t17 * t22 * t19 + (float(2) / float(5)) * t29 * t31 * tau_lo * t19 - (float(1) / float(15)) * (float(5) * (float(3) * (float(2) * b * t24 * t19 + c * t13 * t6 - J1) * t19 - c * t25 * t19 - float(2) * b * t26 * t19) * t19 - float(2) * b * t29 * t19 - t28 * c * t19) * t33 * t19 - t28 * t30 * t1 * t19 - (float(4) / float(3)) * t27 * t32 * t20 * t19;
  }
  float t34 = sigma2 * sigma2;
  float t35 = t34 * sigma2;
  f = si.sigma * length * t35 * F;
  return f;
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-7/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^7 |AB| int_0^1 tau^6 (|P - Gamma|^2 + sigma^2tau^2)^(-7/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 115 +, 336 *, 9 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
float scalis_segment_cauchy_i7_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float sigma2 = si.sigma * si.sigma;
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
  float ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
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
  float ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float t1 = delta_tau * delta_tau;
  float a = ab_ab + t1 * sigma2;
  float b = ab_ap - delta_tau * tau_lo * sigma2;
  float t2 = tau_lo * tau_lo;
  float c = ap_ap + t2 * sigma2;
  float radial0 = ap0 * delta_tau + tau_lo * ab0;
  float radial1 = ap1 * delta_tau + tau_lo * ab1;
  float radial2 = ap2 * delta_tau + tau_lo * ab2;
  float D = sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) + cross_cross;
  float a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  float q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t3 = sqrt(a);
    float t4 = float(1) / D;
    X = t3 * (r1 * b + a_minus_b * r0) * t4;
  }
  float t5 = sqrt(a);
  float t6 = float(1) / t5;
  float J1 = t6 * skelconv_asinh(X);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t7 = float(1) / a;
    float t8 = t1 * t1;
    float t9 = float(1) / r0;
    float t10 = float(1) / r1;
    float t11 = b * t9 + t10 * a_minus_b;
    float t12 = float(1) / D;
    float t13 = t10 * t10;
    float t14 = t9 * t9;
    float t15 = float(2) * t11 * a * t12 + t10 * a_minus_b * t13 + b * t14 * t9;
    float t16 = t15 * b * t12 + t14 * t9 - t10 * t13;
    float t17 = float(3) * t11 * t12 + float(2) * t7 * t16 * b - t15 * c * t12;
    float t18 = t14 * t14;
    float t19 = t13 * t13;
    float t20 = float(3) * b * t18 * t9 + float(3) * t10 * a_minus_b * t19 + float(4) * a * t15 * t12;
    float t21 = t20 * b * t12 + float(3) * t18 * t9 - float(3) * t10 * t19;
    float t22 = float(2) * t7 * b * t21 + float(5) * t15 * t12 - t20 * c * t12;
    float t23 = float(2) * t7 * b * t22 + float(5) * t7 * t16 - t7 * c * t21;
    float t24 = float(5) * t7 * t17 + float(2) * t7 * b * t23 - t7 * t22 * c;
    float t25 = t2 * tau_lo;
    float t26 = t25 * t25;
    float t27 = t2 * t2;
    float t28 = t27 * tau_lo;
    float t29 = t1 * delta_tau;
    float t30 = t9 + t11 * b * t12 - t10;
    float t31 = t7 * t16 * c - float(3) * t7 * t30 - float(2) * t7 * b * t17;
    float t32 = t7 * t23 * c + float(5) * t7 * t31 - float(2) * t7 * t24 * b;
    float t33 = t8 * delta_tau;
    float t34 = t29 * t29;
    F = t7 * t8 * t24 * t2 + (float(1) / float(15)) * t20 * t26 * t12 + (float(2) / float(5)) * t7 * delta_tau * t28 * t21 + t7 * t1 * t27 * t22 + (float(4) / float(3)) * t7 * t29 * t25 * t23 - (float(2) / float(5)) * t32 * t7 * t33 * tau_lo - (float(1) / float(15)) * t7 * (float(5) * t7 * (t7 * c * t17 + float(2) * t7 * b * t31 - float(3) * t7 * (float(2) * t7 * b * t30 + J1 - t11 * c * t12)) + t7 * t24 * c + float(2) * t32 * t7 * b) * t34;
    float t35 = t19 * t13;
    float t36 = t18 * t14;
    float t37 = float(5) * t10 * a_minus_b * t35 + float(5) * b * t36 * t9 + float(2) * a * t20 * t12;
    float t38 = float(5) * t10 * t35 - float(5) * t36 * t9 - b * t37 * t12;
    float t39 = float(3) * t37 * c * t12 + float(6) * t7 * b * t38 - float(7) * t20 * t12;
    float t40 = float(3) * t7 * t38 * c + float(7) * t7 * t21 - float(2) * t7 * t39 * b;
    float t41 = float(7) * t7 * t22 + float(2) * t7 * b * t40 + t7 * t39 * c;
    float t42 = float(2) * t7 * b * t41 + float(7) * t7 * t23 - t7 * t40 * c;
    G_ap = (float(4) / float(21)) * t7 * t29 * t25 * t40 + (float(1) / float(7)) * t7 * t8 * t2 * t41 + (float(1) / float(105)) * t7 * t34 * (float(7) * t7 * t24 + float(2) * t7 * b * t42 - t7 * t41 * c) + (float(1) / float(35)) * t26 * t37 * t12 + (float(2) / float(35)) * t7 * t33 * tau_lo * t42 - (float(1) / float(7)) * t7 * t39 * t1 * t27 - (float(6) / float(35)) * t7 * delta_tau * t28 * t38;
    float t43 = t9 * t9;
    float t44 = t43 * t9;
    float t45 = t44 * t44;
    float t46 = t45 * t9;
    float t47 = t10 * t10;
    float t48 = t47 * t10;
    float t49 = t48 * t48;
    float t50 = t49 * t10;
    G_E = (float(1) / float(35)) * t7 * (float(10) * t7 * t33 * t24 * tau_lo + float(20) * t7 * t8 * t2 * t23 + float(5) * t26 * t46 + float(10) * t7 * t1 * t27 * t21 + float(2) * t20 * delta_tau * t28 * t12 + float(20) * t7 * t29 * t25 * t22 - float(5) * t50 * (float(6) * delta_tau * t28 + t26 + float(20) * t29 * t25 + t34 + float(15) * t8 * t2 + float(15) * t1 * t27 + float(6) * t33 * tau_lo) - float(2) * t32 * t7 * t34);
  }
  float t51 = float(1) / a;
  float t52 = float(1) / ab_ab;
  float foot_offset = t51 * delta_tau * sigma2 * (ab_ap * delta_tau + tau_lo * ab_ab) * t52;
  float foot_h0 = foot_offset * ab0 + foot0;
  float foot_h1 = foot_offset * ab1 + foot1;
  float foot_h2 = foot_offset * ab2 + foot2;
  float t53 = sigma2 * sigma2;
  float t54 = t53 * sigma2;
  float g_factor = -float(7) * t54 * length * si.sigma;
  f = F * t54 * length * si.sigma;
  grad[0] = -g_factor * (ab0 * G_E - foot_h0 * G_ap);
  grad[1] = g_factor * (G_ap * foot_h1 - ab1 * G_E);
  grad[2] = -(ab2 * G_E - foot_h2 * G_ap) * g_factor;
  return f;
}

// the field, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-8/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^8 |AB| int_0^1 tau^7 (|P - Gamma|^2 + sigma^2tau^2)^(-8/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 83 +, 211 *, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float scalis_segment_cauchy_i8_f(ScalisSegmentInput si) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float sigma2 = si.sigma * si.sigma;
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
  float ab_ap = ab1 * ap1 + ab0 * ap0 + ap2 * ab2;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ab1 * ap2 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  float ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float t0 = delta_tau * delta_tau;
  float a = t0 * sigma2 + ab_ab;
  float b = ab_ap - tau_lo * delta_tau * sigma2;
  float t1 = tau_lo * tau_lo;
  float c = ap_ap + t1 * sigma2;
  float radial0 = ap0 * delta_tau + ab0 * tau_lo;
  float radial1 = ap1 * delta_tau + ab1 * tau_lo;
  float radial2 = tau_lo * ab2 + ap2 * delta_tau;
  float D = cross_cross + sigma2 * (radial0 * radial0 + radial2 * radial2 + radial1 * radial1);
  float a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  float q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  float c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  float t2 = float(1) / c;
  float log_ratio = log(t2 * q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t3 = sqrt(D);
    float t4 = float(1) / t3;
    float J2 = atan(t3, c_minus_b) * t4;
    float t5 = float(1) / a;
    float t6 = float(1) / q1;
    float t7 = t2 * b + a * J2 + a_minus_b * t6;
    float t8 = float(1) / D;
    float t9 = t6 * t6;
    float t10 = t2 * t2;
    float t11 = float(3) * t7 * t8 * a + float(2) * a_minus_b * t9 + float(2) * t10 * b;
    float t12 = float(2) * t9 - float(2) * t10 - t11 * t8 * b;
    float t13 = float(4) * t7 * t8 - t11 * c * t8 - float(2) * t12 * t5 * b;
    float t14 = t9 * t6;
    float t15 = t10 * t2;
    float t16 = float(5) * t11 * t8 * a + float(8) * a_minus_b * t14 + float(8) * t15 * b;
    float t17 = t16 * t8 * b + float(8) * t15 - float(8) * t14;
    float t18 = t16 * c * t8 - float(6) * t11 * t8 - float(2) * t5 * t17 * b;
    float t19 = float(6) * t12 * t5 + float(2) * t5 * t18 * b + c * t5 * t17;
    float t20 = float(6) * t5 * t13 + c * t5 * t18 - float(2) * t19 * t5 * b;
    float t21 = t1 * tau_lo;
    float t22 = t0 * t0;
    float t23 = t2 + t7 * t8 * b - t6;
    float t24 = float(2) * t5 * b * t13 + c * t12 * t5 + float(4) * t23 * t5;
    float t25 = float(2) * t20 * t5 * b + c * t19 * t5 + float(6) * t5 * t24;
    float t26 = t22 * delta_tau;
    float t27 = t21 * t21;
    float t28 = t27 * tau_lo;
    float t29 = t1 * t1;
    float t30 = t0 * delta_tau;
    float t31 = c * t7 * t8 - float(2) * t23 * t5 * b - float(2) * J2;
    float t32 = float(4) * t31 * t5 + c * t5 * t13 - float(2) * t5 * t24 * b;
    float t33 = c * t20 * t5 + float(6) * t5 * t32 - float(2) * t25 * t5 * b;
    float t34 = t30 * t30;
    float t35 = t34 * delta_tau;
    float t36 = t29 * tau_lo;
    F = (float(35) / float(48)) * t20 * t21 * t22 * t5 + (float(7) / float(16)) * t25 * t1 * t26 * t5 + (float(1) / float(48)) * t16 * t28 * t8 + (float(7) / float(48)) * t27 * delta_tau * t5 * t17 - (float(35) / float(48)) * t29 * t19 * t30 * t5 - (float(7) / float(48)) * t33 * tau_lo * t34 * t5 - (float(1) / float(48)) * t35 * t5 * (float(6) * t5 * (float(2) * t5 * t32 * b + float(4) * (t23 * c * t5 + float(2) * t31 * t5 * b - (float(2) * J2 * b + log_ratio) * t5) * t5 + c * t5 * t24) + float(2) * t33 * t5 * b + c * t25 * t5) - (float(7) / float(16)) * t36 * t0 * t5 * t18;
  }
  float t37 = sigma2 * sigma2;
  float t38 = t37 * t37;
  f = length * t38 * F;
  return f;
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-8/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^8 |AB| int_0^1 tau^7 (|P - Gamma|^2 + sigma^2tau^2)^(-8/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 131 +, 367 *, 8 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float scalis_segment_cauchy_i8_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float sigma2 = si.sigma * si.sigma;
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
  float ab_ap = ab2 * ap2 + ap1 * ab1 + ap0 * ab0;
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
    foot0 = ap0 - t0 * ab0 * ab_ap;
    foot1 = ap1 - t0 * ab1 * ab_ap;
    foot2 = ap2 - t0 * ab2 * ab_ap;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float ap_bp = ap1 * bp1 + ap0 * bp0 + bp2 * ap2;
  float length = sqrt(ab_ab);
  float t1 = delta_tau * delta_tau;
  float a = ab_ab + t1 * sigma2;
  float b = ab_ap - delta_tau * tau_lo * sigma2;
  float t2 = tau_lo * tau_lo;
  float c = ap_ap + t2 * sigma2;
  float radial0 = ap0 * delta_tau + tau_lo * ab0;
  float radial1 = ap1 * delta_tau + tau_lo * ab1;
  float radial2 = delta_tau * ap2 + tau_lo * ab2;
  float D = (radial1 * radial1 + radial0 * radial0 + radial2 * radial2) * sigma2 + cross_cross;
  float a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  float q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  float c_minus_b = tau_lo * sigma2 * tau_hi + ap_bp;
  float t3 = float(1) / c;
  float log_ratio = log(q1 * t3);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t4 = sqrt(D);
    float t5 = float(1) / t4;
    float J2 = atan(t4, c_minus_b) * t5;
    float t6 = float(1) / D;
    float t7 = t2 * tau_lo;
    float t8 = t7 * t7;
    float t9 = t8 * tau_lo;
    float t10 = float(1) / q1;
    float t11 = t10 * t10;
    float t12 = t11 * t10;
    float t13 = t3 * t3;
    float t14 = t13 * t3;
    float t15 = b * t3 + J2 * a + a_minus_b * t10;
    float t16 = float(2) * a_minus_b * t11 + float(3) * t6 * a * t15 + float(2) * b * t13;
    float t17 = float(8) * a_minus_b * t12 + float(8) * b * t14 + float(5) * t16 * t6 * a;
    float t18 = t1 * t1;
    float t19 = t18 * delta_tau;
    float t20 = float(1) / a;
    float t21 = float(8) * t12 - float(8) * t14 - t6 * b * t17;
    float t22 = t6 * c * t17 + float(2) * t20 * t21 * b - float(6) * t16 * t6;
    float t23 = t16 * t6 * b + float(2) * t13 - float(2) * t11;
    float t24 = float(2) * t20 * t22 * b - t20 * t21 * c - float(6) * t20 * t23;
    float t25 = float(4) * t6 * t15 + float(2) * t20 * b * t23 - t16 * t6 * c;
    float t26 = float(6) * t20 * t25 + t20 * t22 * c - float(2) * t24 * t20 * b;
    float t27 = t6 * t15 * b + t3 - t10;
    float t28 = float(4) * t20 * t27 + float(2) * t20 * t25 * b - t20 * t23 * c;
    float t29 = t24 * t20 * c + float(2) * t26 * t20 * b + float(6) * t28 * t20;
    float t30 = t1 * delta_tau;
    float t31 = t30 * t30;
    float t32 = float(2) * J2 + float(2) * t20 * b * t27 - t6 * t15 * c;
    float t33 = float(4) * t20 * t32 + float(2) * t28 * t20 * b - t20 * t25 * c;
    float t34 = float(6) * t33 * t20 + float(2) * t20 * b * t29 - t26 * t20 * c;
    float t35 = t2 * t2;
    float t36 = t35 * tau_lo;
    float t37 = t31 * delta_tau;
    F = (float(1) / float(48)) * t6 * t9 * t17 + (float(7) / float(16)) * t19 * t2 * t20 * t29 + (float(7) / float(48)) * t31 * tau_lo * t20 * t34 + (float(35) / float(48)) * t18 * t26 * t7 * t20 - (float(7) / float(16)) * t1 * t36 * t20 * t22 - (float(35) / float(48)) * t24 * t30 * t35 * t20 - (float(7) / float(48)) * delta_tau * t8 * t20 * t21 - (float(1) / float(48)) * t37 * t20 * (float(6) * t20 * (t28 * t20 * c - float(4) * t20 * (float(2) * t20 * b * t32 + t20 * (float(2) * J2 * b + log_ratio) - t20 * t27 * c) - float(2) * t33 * t20 * b) + t20 * t29 * c - float(2) * t20 * b * t34);
    float t38 = t11 * t11;
    float t39 = t13 * t13;
    float t40 = float(48) * a_minus_b * t38 + float(7) * t6 * a * t17 + float(48) * b * t39;
    float t41 = float(48) * t38 - float(48) * t39 - t6 * t40 * b;
    float t42 = t6 * t40 * c + float(2) * t20 * t41 * b - float(8) * t6 * t17;
    float t43 = float(8) * t20 * t21 + float(2) * t20 * b * t42 - t20 * t41 * c;
    float t44 = float(8) * t20 * t22 + float(2) * t43 * t20 * b - t20 * t42 * c;
    float t45 = t43 * t20 * c - float(2) * t20 * b * t44 - float(8) * t24 * t20;
    float t46 = float(2) * t20 * t45 * b + float(8) * t26 * t20 + t20 * t44 * c;
    G_ap = (float(1) / float(384)) * t6 * t40 * t9 + (float(1) / float(384)) * t37 * t20 * (float(2) * t20 * t46 * b + float(8) * t20 * t29 - t20 * t45 * c) + (float(7) / float(384)) * t31 * tau_lo * t20 * t46 + (float(7) / float(128)) * t19 * t2 * t20 * t45 - (float(35) / float(384)) * t18 * t7 * t20 * t44 - (float(35) / float(384)) * t43 * t30 * t35 * t20 - (float(7) / float(384)) * delta_tau * t8 * t20 * t41 - (float(7) / float(128)) * t1 * t36 * t20 * t42;
    G_E = -(float(1) / float(384)) * t20 * (float(48) * (float(7) * delta_tau * t8 + t9 + float(21) * t1 * t36 + t37 + float(21) * t19 * t2 + float(35) * t18 * t7 + float(35) * t30 * t35 + float(7) * t31 * tau_lo) * t38 + float(140) * t24 * t18 * t7 * t20 + float(105) * t30 * t35 * t20 * t22 + float(42) * t1 * t36 * t20 * t21 - float(42) * t31 * tau_lo * t20 * t29 - float(48) * t9 * t39 - float(105) * t19 * t26 * t2 * t20 - float(7) * t37 * t20 * t34 - float(7) * t6 * delta_tau * t8 * t17);
  }
  float t47 = float(1) / a;
  float t48 = float(1) / ab_ab;
  float foot_offset = delta_tau * (delta_tau * ab_ap + tau_lo * ab_ab) * t47 * sigma2 * t48;
  float foot_h0 = foot0 + ab0 * foot_offset;
  float foot_h1 = ab1 * foot_offset + foot1;
  float foot_h2 = ab2 * foot_offset + foot2;
  float t49 = sigma2 * sigma2;
  float t50 = t49 * t49;
  float g_factor = -float(8) * t50 * length;
  f = F * t50 * length;
  grad[0] = g_factor * (foot_h0 * G_ap - G_E * ab0);
  grad[1] = -g_factor * (G_E * ab1 - foot_h1 * G_ap);
  grad[2] = -(G_E * ab2 - G_ap * foot_h2) * g_factor;
  return f;
}

// the field, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-9/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^9 |AB| int_0^1 tau^8 (|P - Gamma|^2 + sigma^2tau^2)^(-9/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 92 +, 264 *, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
float scalis_segment_cauchy_i9_f(ScalisSegmentInput si) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float sigma2 = si.sigma * si.sigma;
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
  float ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ap2 * ab1 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ap2 * ab0;
  float plain_cross2 = ap1 * ab0 - ap0 * ab1;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float t0 = delta_tau * delta_tau;
  float a = ab_ab + t0 * sigma2;
  float b = ab_ap - tau_lo * delta_tau * sigma2;
  float t1 = tau_lo * tau_lo;
  float c = ap_ap + t1 * sigma2;
  float radial0 = tau_lo * ab0 + ap0 * delta_tau;
  float radial1 = ap1 * delta_tau + tau_lo * ab1;
  float radial2 = ap2 * delta_tau + tau_lo * ab2;
  float D = (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2 + cross_cross;
  float a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  float q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t2 = float(1) / D;
    float t3 = sqrt(a);
    X = (a_minus_b * r0 + b * r1) * t2 * t3;
  }
  float t4 = sqrt(a);
  float t5 = float(1) / t4;
  float J1 = t5 * skelconv_asinh(X);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t6 = t1 * tau_lo;
    float t7 = t6 * t6;
    float t8 = float(1) / a;
    float t9 = float(1) / D;
    float t10 = float(1) / r0;
    float t11 = t10 * t10;
    float t12 = t11 * t11;
    float t13 = float(1) / r1;
    float t14 = t13 * t13;
    float t15 = t14 * t14;
    float t16 = a_minus_b * t13 + t10 * b;
    float t17 = float(2) * t9 * a * t16 + a_minus_b * t14 * t13 + t11 * t10 * b;
    float t18 = float(3) * t12 * t10 * b + float(3) * a_minus_b * t15 * t13 + float(4) * t9 * a * t17;
    float t19 = t12 * t11;
    float t20 = t15 * t14;
    float t21 = float(5) * a_minus_b * t20 * t13 + float(2) * t9 * a * t18 + float(5) * t19 * t10 * b;
    float t22 = float(5) * t19 * t10 + t21 * t9 * b - float(5) * t20 * t13;
    float t23 = float(7) * t9 * t18 + float(6) * t22 * t8 * b - float(3) * t21 * c * t9;
    float t24 = t0 * delta_tau;
    float t25 = t24 * t24;
    float t26 = float(3) * t15 * t13 - float(3) * t12 * t10 - t9 * t18 * b;
    float t27 = float(2) * t26 * t8 * b + c * t9 * t18 - float(5) * t9 * t17;
    float t28 = t9 * t17 * b + t11 * t10 - t14 * t13;
    float t29 = c * t9 * t17 - float(2) * t8 * b * t28 - float(3) * t9 * t16;
    float t30 = float(2) * t8 * t27 * b - c * t26 * t8 - float(5) * t8 * t28;
    float t31 = c * t8 * t27 - float(5) * t29 * t8 - float(2) * t8 * b * t30;
    float t32 = float(3) * t22 * c * t8 + float(7) * t26 * t8 - float(2) * t8 * t23 * b;
    float t33 = float(7) * t8 * t27 + float(2) * t8 * t32 * b + c * t8 * t23;
    float t34 = c * t8 * t32 - float(2) * t8 * t33 * b - float(7) * t8 * t30;
    float t35 = float(7) * t31 * t8 + float(2) * t34 * t8 * b + c * t8 * t33;
    float t36 = t1 * t1;
    float t37 = t36 * t36;
    float t38 = t13 - t9 * b * t16 - t10;
    float t39 = float(3) * t8 * t38 + float(2) * t29 * t8 * b + c * t8 * t28;
    float t40 = float(2) * t31 * t8 * b + c * t8 * t30 - float(5) * t8 * t39;
    float t41 = float(2) * t8 * t35 * b + float(7) * t8 * t40 - c * t34 * t8;
    float t42 = t25 * delta_tau;
    float t43 = t0 * t0;
    float t44 = t43 * delta_tau;
    float t45 = t7 * tau_lo;
    float t46 = t43 * t43;
    float t47 = t36 * tau_lo;
    F = (float(4) / float(15)) * t7 * t0 * t8 * t23 + (float(4) / float(15)) * t1 * t25 * t8 * t35 + (float(1) / float(35)) * t21 * t37 * t9 + (float(8) / float(105)) * t41 * tau_lo * t42 * t8 + (float(8) / float(15)) * t6 * t44 * t34 * t8 + (float(8) / float(35)) * t22 * t45 * delta_tau * t8 - (float(1) / float(105)) * t46 * t8 * (float(7) * t8 * (c * t31 * t8 + float(5) * (float(3) * (float(2) * t8 * t38 * b + c * t9 * t16 - J1) * t8 + float(2) * t8 * b * t39 - c * t29 * t8) * t8 - float(2) * t8 * t40 * b) + c * t8 * t35 - float(2) * t41 * t8 * b) - (float(2) / float(3)) * t36 * t43 * t8 * t33 - (float(8) / float(15)) * t47 * t24 * t8 * t32;
  }
  float t48 = sigma2 * sigma2;
  float t49 = t48 * t48;
  f = si.sigma * length * t49 * F;
  return f;
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-9/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^9 |AB| int_0^1 tau^8 (|P - Gamma|^2 + sigma^2tau^2)^(-9/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 145 +, 450 *, 9 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
float scalis_segment_cauchy_i9_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float sigma2 = si.sigma * si.sigma;
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
  float ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float length = sqrt(ab_ab);
  float t1 = delta_tau * delta_tau;
  float a = ab_ab + t1 * sigma2;
  float b = ab_ap - delta_tau * tau_lo * sigma2;
  float t2 = tau_lo * tau_lo;
  float c = ap_ap + t2 * sigma2;
  float radial0 = ap0 * delta_tau + tau_lo * ab0;
  float radial1 = ap1 * delta_tau + tau_lo * ab1;
  float radial2 = tau_lo * ab2 + ap2 * delta_tau;
  float D = cross_cross + sigma2 * (radial2 * radial2 + radial1 * radial1 + radial0 * radial0);
  float a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  float q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t3 = float(1) / D;
    float t4 = sqrt(a);
    X = t3 * t4 * (r0 * a_minus_b + r1 * b);
  }
  float t5 = sqrt(a);
  float t6 = float(1) / t5;
  float J1 = skelconv_asinh(X) * t6;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t7 = float(1) / a;
    float t8 = float(1) / D;
    float t9 = float(1) / r1;
    float t10 = t9 * t9;
    float t11 = float(1) / r0;
    float t12 = t11 * b + a_minus_b * t9;
    float t13 = t11 * t11;
    float t14 = a_minus_b * t9 * t10 + float(2) * t8 * a * t12 + t13 * t11 * b;
    float t15 = t8 * b * t14 + t13 * t11 - t9 * t10;
    float t16 = t10 * t10;
    float t17 = t13 * t13;
    float t18 = float(3) * t17 * t11 * b + float(4) * t8 * a * t14 + float(3) * a_minus_b * t9 * t16;
    float t19 = float(3) * t9 * t16 - t8 * t18 * b - float(3) * t17 * t11;
    float t20 = float(2) * t19 * t7 * b + c * t8 * t18 - float(5) * t8 * t14;
    float t21 = float(5) * t7 * t15 + c * t19 * t7 - float(2) * t20 * t7 * b;
    float t22 = t17 * t13;
    float t23 = t16 * t10;
    float t24 = float(2) * t8 * a * t18 + float(5) * t22 * t11 * b + float(5) * a_minus_b * t9 * t23;
    float t25 = float(5) * t9 * t23 - float(5) * t22 * t11 - t8 * t24 * b;
    float t26 = float(3) * c * t8 * t24 + float(6) * t25 * t7 * b - float(7) * t8 * t18;
    float t27 = float(2) * t26 * t7 * b + float(7) * t19 * t7 - float(3) * c * t25 * t7;
    float t28 = float(2) * t7 * t27 * b + float(7) * t20 * t7 - c * t26 * t7;
    float t29 = float(7) * t21 * t7 + c * t7 * t27 - float(2) * t7 * b * t28;
    float t30 = t1 * t1;
    float t31 = t30 * delta_tau;
    float t32 = t2 * tau_lo;
    float t33 = t2 * t2;
    float t34 = t33 * t33;
    float t35 = t1 * delta_tau;
    float t36 = t35 * t35;
    float t37 = float(2) * t7 * b * t15 + float(3) * t8 * t12 - c * t8 * t14;
    float t38 = c * t20 * t7 + float(2) * t21 * t7 * b + float(5) * t37 * t7;
    float t39 = c * t7 * t28 + float(7) * t7 * t38 + float(2) * t29 * t7 * b;
    float t40 = t33 * tau_lo;
    float t41 = t32 * t32;
    float t42 = t41 * tau_lo;
    float t43 = t30 * t30;
    float t44 = t11 + t8 * t12 * b - t9;
    float t45 = c * t7 * t15 - float(3) * t7 * t44 - float(2) * t37 * t7 * b;
    float t46 = float(2) * t7 * t38 * b - float(5) * t7 * t45 - c * t21 * t7;
    float t47 = c * t29 * t7 - float(2) * t7 * t39 * b - float(7) * t46 * t7;
    float t48 = t36 * delta_tau;
    F = (float(8) / float(15)) * t29 * t31 * t32 * t7 + (float(1) / float(35)) * t34 * t8 * t24 + (float(4) / float(15)) * t36 * t2 * t7 * t39 - (float(8) / float(15)) * t35 * t40 * t7 * t27 - (float(8) / float(35)) * t25 * delta_tau * t42 * t7 - (float(2) / float(3)) * t30 * t33 * t7 * t28 - (float(1) / float(105)) * t43 * t7 * (float(7) * (float(5) * (c * t37 * t7 + float(2) * t7 * t45 * b + float(3) * (c * t8 * t12 - float(2) * t7 * t44 * b - J1) * t7) * t7 + c * t7 * t38 - float(2) * t46 * t7 * b) * t7 + c * t7 * t39 + float(2) * t7 * t47 * b) - (float(8) / float(105)) * t48 * tau_lo * t7 * t47 - (float(4) / float(15)) * t1 * t41 * t26 * t7;
    float t49 = t17 * t17;
    float t50 = t16 * t16;
    float t51 = float(35) * t49 * t11 * b + float(8) * t8 * a * t24 + float(35) * a_minus_b * t9 * t50;
    float t52 = t8 * b * t51 + float(35) * t49 * t11 - float(35) * t9 * t50;
    float t53 = float(2) * t7 * b * t52 + float(9) * t8 * t24 - c * t8 * t51;
    float t54 = c * t7 * t52 + float(9) * t25 * t7 - float(2) * t7 * t53 * b;
    float t55 = float(2) * t7 * b * t54 + float(3) * t26 * t7 + c * t7 * t53;
    float t56 = float(3) * t7 * t27 + float(2) * t7 * t55 * b - c * t7 * t54;
    float t57 = float(2) * t56 * t7 * b + float(3) * t7 * t28 - c * t7 * t55;
    float t58 = float(2) * t57 * t7 * b - float(3) * t29 * t7 - c * t56 * t7;
    G_ap = (float(4) / float(45)) * t1 * t41 * t7 * t53 + (float(1) / float(315)) * t34 * t8 * t51 + (float(8) / float(315)) * delta_tau * t42 * t7 * t52 - (float(8) / float(315)) * t48 * tau_lo * t7 * t58 - (float(4) / float(45)) * t36 * t2 * t57 * t7 - (float(1) / float(315)) * t43 * t7 * (float(2) * t7 * b * t58 - c * t57 * t7 - float(3) * t7 * t39) - (float(8) / float(45)) * t31 * t32 * t56 * t7 - (float(8) / float(45)) * t35 * t40 * t7 * t54 - (float(2) / float(9)) * t30 * t33 * t7 * t55;
    float t59 = t9 * t9;
    float t60 = t59 * t59;
    float t61 = t60 * t60;
    float t62 = t61 * t9;
    float t63 = t11 * t11;
    float t64 = t63 * t63;
    float t65 = t64 * t64;
    float t66 = t65 * t11;
    G_E = -(float(1) / float(945)) * t7 * (float(105) * (float(8) * delta_tau * t42 + float(70) * t30 * t33 + float(56) * t35 * t40 + float(8) * t48 * tau_lo + float(56) * t31 * t32 + t34 + t43 + float(28) * t36 * t2 + float(28) * t1 * t41) * t62 + float(168) * t35 * t40 * t26 * t7 + float(280) * t31 * t32 * t7 * t28 + float(8) * t43 * t7 * t47 + float(280) * t30 * t33 * t7 * t27 + float(168) * t25 * t1 * t41 * t7 - float(56) * t48 * tau_lo * t7 * t39 - float(168) * t29 * t36 * t2 * t7 - float(24) * delta_tau * t42 * t8 * t24 - float(105) * t66 * t34);
  }
  float t67 = float(1) / a;
  float t68 = float(1) / ab_ab;
  float foot_offset = delta_tau * t67 * sigma2 * t68 * (tau_lo * ab_ab + ab_ap * delta_tau);
  float foot_h0 = foot0 + foot_offset * ab0;
  float foot_h1 = foot1 + foot_offset * ab1;
  float foot_h2 = foot_offset * ab2 + foot2;
  float t69 = sigma2 * sigma2;
  float t70 = t69 * t69;
  float g_factor = -float(9) * length * t70 * si.sigma;
  f = length * t70 * F * si.sigma;
  grad[0] = (foot_h0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = g_factor * (foot_h1 * G_ap - G_E * ab1);
  grad[2] = -g_factor * (G_E * ab2 - foot_h2 * G_ap);
  return f;
}

// the field, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-10/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^10 |AB| int_0^1 tau^9 (|P - Gamma|^2 + sigma^2tau^2)^(-10/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 105 +, 293 *, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float scalis_segment_cauchy_i10_f(ScalisSegmentInput si) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float sigma2 = si.sigma * si.sigma;
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
  float ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ap2 * ab1 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ap2 * ab0;
  float plain_cross2 = ap1 * ab0 - ap0 * ab1;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  float ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  float length = sqrt(ab_ab);
  float t0 = delta_tau * delta_tau;
  float a = t0 * sigma2 + ab_ab;
  float b = ab_ap - delta_tau * tau_lo * sigma2;
  float t1 = tau_lo * tau_lo;
  float c = t1 * sigma2 + ap_ap;
  float radial0 = tau_lo * ab0 + ap0 * delta_tau;
  float radial1 = ap1 * delta_tau + tau_lo * ab1;
  float radial2 = tau_lo * ab2 + ap2 * delta_tau;
  float D = cross_cross + (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2;
  float a_minus_b = delta_tau * sigma2 * tau_hi - ab_bp;
  float q1 = bp_bp + sigma2 * tau_hi * tau_hi;
  float c_minus_b = ap_bp + tau_lo * sigma2 * tau_hi;
  float t2 = float(1) / c;
  float log_ratio = log(t2 * q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t3 = sqrt(D);
    float t4 = float(1) / t3;
    float J2 = t4 * atan(t3, c_minus_b);
    float t5 = t0 * t0;
    float t6 = t5 * delta_tau;
    float t7 = t1 * t1;
    float t8 = float(1) / a;
    float t9 = t2 * t2;
    float t10 = t9 * t9;
    float t11 = float(1) / D;
    float t12 = t9 * t2;
    float t13 = float(1) / q1;
    float t14 = t13 * t13;
    float t15 = t14 * t13;
    float t16 = a_minus_b * t13 + t2 * b + J2 * a;
    float t17 = float(3) * t16 * t11 * a + float(2) * t9 * b + float(2) * a_minus_b * t14;
    float t18 = float(8) * t12 * b + float(8) * a_minus_b * t15 + float(5) * t11 * a * t17;
    float t19 = t14 * t14;
    float t20 = float(7) * t18 * t11 * a + float(48) * a_minus_b * t19 + float(48) * t10 * b;
    float t21 = float(48) * t10 + t11 * t20 * b - float(48) * t19;
    float t22 = float(2) * t21 * t8 * b + float(8) * t18 * t11 - c * t11 * t20;
    float t23 = float(8) * t12 + t18 * t11 * b - float(8) * t15;
    float t24 = t21 * c * t8 - float(2) * t8 * t22 * b - float(8) * t23 * t8;
    float t25 = c * t18 * t11 - float(2) * t23 * t8 * b - float(6) * t11 * t17;
    float t26 = float(8) * t25 * t8 + float(2) * t24 * t8 * b + c * t8 * t22;
    float t27 = float(2) * t9 + t11 * b * t17 - float(2) * t14;
    float t28 = float(2) * t25 * t8 * b + c * t23 * t8 - float(6) * t8 * t27;
    float t29 = t24 * c * t8 - float(2) * t26 * t8 * b - float(8) * t8 * t28;
    float t30 = t7 * t7;
    float t31 = t30 * tau_lo;
    float t32 = t1 * tau_lo;
    float t33 = t32 * t32;
    float t34 = t33 * tau_lo;
    float t35 = t0 * delta_tau;
    float t36 = t35 * t35;
    float t37 = t36 * delta_tau;
    float t38 = float(4) * t16 * t11 + float(2) * t8 * t27 * b - c * t11 * t17;
    float t39 = float(2) * t8 * t28 * b - c * t25 * t8 - float(6) * t8 * t38;
    float t40 = float(8) * t39 * t8 - c * t26 * t8 - float(2) * t8 * t29 * b;
    float t41 = t13 - t16 * t11 * b - t2;
    float t42 = c * t8 * t27 + float(4) * t41 * t8 - float(2) * t8 * b * t38;
    float t43 = float(6) * t8 * t42 + float(2) * t39 * t8 * b - c * t8 * t28;
    float t44 = float(2) * t8 * t40 * b + c * t8 * t29 + float(8) * t8 * t43;
    float t45 = t5 * t5;
    float t46 = c * t16 * t11 + float(2) * t41 * t8 * b - float(2) * J2;
    float t47 = c * t8 * t38 + float(2) * t8 * b * t42 + float(4) * t46 * t8;
    float t48 = c * t39 * t8 - float(2) * t8 * t43 * b - float(6) * t8 * t47;
    float t49 = float(2) * t8 * b * t44 - float(8) * t48 * t8 - c * t8 * t40;
    float t50 = t45 * delta_tau;
    float t51 = t7 * tau_lo;
    F = (float(21) / float(64)) * t6 * t7 * t8 * t29 + (float(3) / float(128)) * t21 * delta_tau * t30 * t8 + (float(1) / float(384)) * t11 * t31 * t20 + (float(3) / float(32)) * t0 * t34 * t8 * t22 - (float(3) / float(32)) * t37 * t1 * t8 * t44 - (float(3) / float(128)) * t45 * tau_lo * t8 * t49 - (float(7) / float(32)) * t36 * t32 * t8 * t40 - (float(1) / float(384)) * t50 * t8 * (float(2) * t8 * t49 * b - c * t8 * t44 - float(8) * t8 * (float(2) * t48 * t8 * b + float(6) * (c * t8 * t42 + float(4) * (t41 * c * t8 + t8 * (float(2) * J2 * b + log_ratio) - float(2) * t46 * t8 * b) * t8 - float(2) * t8 * t47 * b) * t8 + c * t8 * t43)) - (float(21) / float(64)) * t5 * t51 * t26 * t8 - (float(7) / float(32)) * t24 * t35 * t33 * t8;
  }
  float t52 = sigma2 * sigma2;
  float t53 = t52 * t52;
  float t54 = t53 * sigma2;
  f = length * t54 * F;
  return f;
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-10/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^10 |AB| int_0^1 tau^9 (|P - Gamma|^2 + sigma^2tau^2)^(-10/2) dt; SPEC sec. 4, Zanni 2013 eq. 13, Table 3]
// Operations: 163 +, 485 *, 8 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float scalis_segment_cauchy_i10_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  float f;
  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).
  bool swap_ends = si.tau1 < si.tau0;
  vec3 end_a = swap_ends ? si.b : si.a;
  vec3 end_b = swap_ends ? si.a : si.b;
  float tau_lo = swap_ends ? si.tau1 : si.tau0;
  float tau_hi = swap_ends ? si.tau0 : si.tau1;
  float delta_tau = tau_hi - tau_lo;
  float sigma2 = si.sigma * si.sigma;
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
  float ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  float ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = ab2 * bp2 + ab0 * bp0 + bp1 * ab1;
  float ap_bp = ap2 * bp2 + bp1 * ap1 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float t1 = delta_tau * delta_tau;
  float a = sigma2 * t1 + ab_ab;
  float b = ab_ap - sigma2 * delta_tau * tau_lo;
  float t2 = tau_lo * tau_lo;
  float c = sigma2 * t2 + ap_ap;
  float radial0 = ap0 * delta_tau + ab0 * tau_lo;
  float radial1 = ab1 * tau_lo + ap1 * delta_tau;
  float radial2 = ap2 * delta_tau + ab2 * tau_lo;
  float D = (radial2 * radial2 + radial1 * radial1 + radial0 * radial0) * sigma2 + cross_cross;
  float a_minus_b = sigma2 * tau_hi * delta_tau - ab_bp;
  float q1 = sigma2 * tau_hi * tau_hi + bp_bp;
  float c_minus_b = ap_bp + sigma2 * tau_hi * tau_lo;
  float t3 = float(1) / c;
  float log_ratio = log(q1 * t3);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t4 = sqrt(D);
    float t5 = float(1) / t4;
    float J2 = atan(t4, c_minus_b) * t5;
    float t6 = t3 * t3;
    float t7 = float(1) / q1;
    float t8 = t7 * t7;
    float t9 = a_minus_b * t7 + b * t3 + J2 * a;
    float t10 = float(1) / D;
    float t11 = float(2) * b * t6 + float(2) * a_minus_b * t8 + float(3) * t9 * t10 * a;
    float t12 = t6 * t3;
    float t13 = t8 * t7;
    float t14 = float(5) * t11 * t10 * a + float(8) * b * t12 + float(8) * a_minus_b * t13;
    float t15 = t6 * t6;
    float t16 = t8 * t8;
    float t17 = float(48) * b * t15 + float(7) * t14 * t10 * a + float(48) * a_minus_b * t16;
    float t18 = float(48) * t16 - b * t17 * t10 - float(48) * t15;
    float t19 = float(1) / a;
    float t20 = float(8) * t14 * t10 - t17 * c * t10 - float(2) * b * t18 * t19;
    float t21 = float(8) * t12 + t14 * b * t10 - float(8) * t13;
    float t22 = float(2) * b * t20 * t19 + t18 * c * t19 + float(8) * t21 * t19;
    float t23 = t1 * delta_tau;
    float t24 = t2 * tau_lo;
    float t25 = t24 * t24;
    float t26 = t2 * t2;
    float t27 = t26 * t26;
    float t28 = t27 * tau_lo;
    float t29 = t14 * c * t10 - float(6) * t11 * t10 - float(2) * b * t21 * t19;
    float t30 = float(2) * t6 + b * t11 * t10 - float(2) * t8;
    float t31 = float(2) * b * t19 * t29 + t21 * c * t19 - float(6) * t30 * t19;
    float t32 = float(2) * b * t30 * t19 + float(4) * t9 * t10 - c * t11 * t10;
    float t33 = float(2) * b * t31 * t19 - float(6) * t32 * t19 - c * t19 * t29;
    float t34 = t7 - t3 - b * t9 * t10;
    float t35 = float(2) * b * t32 * t19 - float(4) * t34 * t19 - c * t30 * t19;
    float t36 = float(6) * t35 * t19 + c * t31 * t19 - float(2) * b * t33 * t19;
    float t37 = c * t9 * t10 + float(2) * b * t34 * t19 - float(2) * J2;
    float t38 = float(2) * t35 * b * t19 - c * t32 * t19 - float(4) * t37 * t19;
    float t39 = c * t33 * t19 + float(2) * b * t36 * t19 + float(6) * t38 * t19;
    float t40 = float(8) * t19 * t29 + c * t20 * t19 - float(2) * t22 * b * t19;
    float t41 = float(8) * t31 * t19 + float(2) * b * t40 * t19 + t22 * c * t19;
    float t42 = float(8) * t33 * t19 + float(2) * t41 * b * t19 - c * t40 * t19;
    float t43 = float(2) * t42 * b * t19 - t41 * c * t19 - float(8) * t36 * t19;
    float t44 = float(8) * t39 * t19 + t42 * c * t19 - float(2) * b * t43 * t19;
    float t45 = t1 * t1;
    float t46 = t45 * t45;
    float t47 = t25 * tau_lo;
    float t48 = t46 * delta_tau;
    float t49 = t45 * delta_tau;
    float t50 = t26 * tau_lo;
    float t51 = t23 * t23;
    float t52 = t51 * delta_tau;
    F = (float(7) / float(32)) * t22 * t23 * t25 * t19 + (float(1) / float(384)) * t17 * t28 * t10 + (float(3) / float(128)) * t44 * t46 * tau_lo * t19 + (float(3) / float(32)) * t20 * t1 * t47 * t19 - (float(1) / float(384)) * (float(8) * (c * t36 * t19 - float(6) * t19 * (float(4) * ((float(2) * b * J2 + log_ratio) * t19 + c * t34 * t19 - float(2) * b * t37 * t19) * t19 + float(2) * b * t38 * t19 - t35 * c * t19) - float(2) * t39 * b * t19) * t19 - float(2) * b * t44 * t19 - t43 * c * t19) * t48 * t19 - (float(21) / float(64)) * t41 * t49 * t26 * t19 - (float(21) / float(64)) * t40 * t45 * t50 * t19 - (float(3) / float(32)) * t43 * t52 * t2 * t19 - (float(3) / float(128)) * t18 * delta_tau * t27 * t19 - (float(7) / float(32)) * t42 * t51 * t24 * t19;
    float t53 = t15 * t3;
    float t54 = t16 * t7;
    float t55 = float(128) * b * t53 + float(3) * t17 * t10 * a + float(128) * a_minus_b * t54;
    float t56 = b * t55 * t10 + float(128) * t53 - float(128) * t54;
    float t57 = float(10) * t17 * t10 + float(6) * b * t56 * t19 - float(3) * c * t55 * t10;
    float t58 = float(3) * c * t56 * t19 + float(10) * t18 * t19 - float(2) * b * t57 * t19;
    float t59 = float(10) * t20 * t19 - c * t57 * t19 - float(2) * b * t58 * t19;
    float t60 = float(10) * t22 * t19 + t58 * c * t19 + float(2) * b * t59 * t19;
    float t61 = float(10) * t40 * t19 + c * t59 * t19 - float(2) * b * t60 * t19;
    float t62 = c * t60 * t19 + float(2) * b * t61 * t19 + float(10) * t41 * t19;
    float t63 = float(10) * t42 * t19 + float(2) * t62 * b * t19 - c * t61 * t19;
    G_ap = (float(1) / float(1280)) * t55 * t28 * t10 + (float(21) / float(640)) * t60 * t49 * t26 * t19 + (float(9) / float(1280)) * t56 * delta_tau * t27 * t19 + (float(3) / float(320)) * t57 * t1 * t47 * t19 + (float(21) / float(640)) * t59 * t45 * t50 * t19 - (float(1) / float(3840)) * (float(2) * b * t63 * t19 + float(10) * t43 * t19 - t62 * c * t19) * t48 * t19 - (float(7) / float(320)) * t58 * t23 * t25 * t19 - (float(3) / float(1280)) * t46 * tau_lo * t63 * t19 - (float(7) / float(320)) * t51 * t61 * t24 * t19 - (float(3) / float(320)) * t62 * t52 * t2 * t19;
    G_E = -(float(1) / float(1280)) * t19 * (float(24) * t18 * t1 * t47 * t19 + float(24) * t43 * t46 * tau_lo * t19 + float(168) * t41 * t51 * t24 * t19 + float(84) * t42 * t52 * t2 * t19 + float(128) * (float(36) * t1 * t47 + float(36) * t52 * t2 + float(84) * t51 * t24 + float(9) * t46 * tau_lo + float(84) * t23 * t25 + t48 + float(9) * delta_tau * t27 + float(126) * t45 * t50 + float(126) * t49 * t26 + t28) * t54 + float(210) * t40 * t49 * t26 * t19 - float(3) * t17 * delta_tau * t27 * t10 - float(3) * t44 * t48 * t19 - float(84) * t20 * t23 * t25 * t19 - float(168) * t22 * t45 * t50 * t19 - float(128) * t53 * t28);
  }
  float t64 = float(1) / ab_ab;
  float t65 = float(1) / a;
  float foot_offset = sigma2 * (ab_ap * delta_tau + ab_ab * tau_lo) * t64 * delta_tau * t65;
  float foot_h0 = foot_offset * ab0 + foot0;
  float foot_h1 = foot1 + foot_offset * ab1;
  float foot_h2 = foot2 + foot_offset * ab2;
  float t66 = sigma2 * sigma2;
  float t67 = t66 * t66;
  float t68 = t67 * sigma2;
  float g_factor = -float(10) * t68 * length;
  f = t68 * F * length;
  grad[0] = -g_factor * (ab0 * G_E - G_ap * foot_h0);
  grad[1] = (G_ap * foot_h1 - ab1 * G_E) * g_factor;
  grad[2] = -g_factor * (ab2 * G_E - foot_h2 * G_ap);
  return f;
}

