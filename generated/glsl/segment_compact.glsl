// generated/glsl/segment_compact.glsl - segment kernels of the compact family in GLSL (float; ES 3.00 and 4.50), generic forms only.
//
// GENERATED FILE: DO NOT EDIT. Regenerate with
//     skelconv-codegen --inverse 1:16 --cauchy 1:16 --compact 2:16 --weights 0:3 --polygon-inverse 3:12 --polygon-cauchy 3:12 --polygon-compact 4:12 --scalis-inverse 2:10 --scalis-cauchy 2:10 --out generated
// Generator: skelconv-codegen 0.1.0 (GiNaC 1.8.6)
// From: codegen/segment_families.cpp (the families) and codegen/segment_moments.cpp
// (recurrence (1) of Hubert & Cani unrolled; SPEC sec. 2, Hubert 2012 sec. 3).
// Left out (their generic path calls a Gauss rule or a loop):
// segment_compact_i2_w0 segment_compact_i2_w1 segment_compact_i2_w2
// segment_compact_i2_w3 segment_compact_i4_w0 segment_compact_i4_w1
// segment_compact_i4_w2 segment_compact_i4_w3 segment_compact_i6_w0
// segment_compact_i6_w1 segment_compact_i6_w2 segment_compact_i6_w3
// segment_compact_i8_w0 segment_compact_i8_w1 segment_compact_i8_w2
// segment_compact_i8_w3 segment_compact_i10_w0 segment_compact_i10_w1
// segment_compact_i10_w2 segment_compact_i10_w3 segment_compact_i12_w0
// segment_compact_i12_w1 segment_compact_i12_w2 segment_compact_i12_w3
// segment_compact_i14_w0 segment_compact_i14_w1 segment_compact_i14_w2
// segment_compact_i14_w3 segment_compact_i16_w0 segment_compact_i16_w1
// segment_compact_i16_w2 segment_compact_i16_w3

#ifndef SKELCONV_SEGMENT_INPUT
#define SKELCONV_SEGMENT_INPUT
// The segment AB, the query point p, the weight w(t) = sum_k w[k] t^k,
// the Cauchy sharpness s, the compact support radius R and the part
// [t0, t1] of AB inside the ball of radius R around p (compact only; the
// caller clips, as skelconv/detail/clip.hpp does).
struct SegmentInput {
  vec3 a;
  vec3 b;
  vec3 p;
  vec4 w;
  float s;
  float R;
  float t0;
  float t1;
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
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(3/2) dt
// Operations: 30 +, 47 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i3_w0_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
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
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -inv_R2 * ab_ab;
  float b = -ab_ap * inv_R2;
  float c = float(1) - inv_R2 * ap_ap;
  float D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  float slope0 = si.t0 * a - b;
  float q0 = max(float(0), float(c + si.t0 * (slope0 - b)));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c + si.t1 * (slope1 - b)));
  float r1 = sqrt(q1);
  float root_minus_a = length * inv_R;
  float J1 = (atan(-slope1, r1 * root_minus_a) - atan(-slope0, root_minus_a * r0)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t0 = float(1) / a;
    F = (float(1) / float(8)) * (float(3) * (D * J1 + r1 * slope1 - slope0 * r0) * D * t0 + float(2) * r1 * slope1 * q1 - float(2) * slope0 * q0 * r0) * t0 * si.w[0];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(3/2) dt
// Operations: 37 +, 73 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i3_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
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
    foot0 = ap0 - t0 * ab0 * ab_ap;
    foot1 = ap1 - t0 * ab1 * ab_ap;
    foot2 = ap2 - t0 * ab2 * ab_ap;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -ab_ap * inv_R2;
  float c = float(1) - inv_R2 * ap_ap;
  float D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c - (b - slope0) * si.t0));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c - si.t1 * (b - slope1)));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t1 = -slope1;
  float t2 = -slope0;
  float J1 = (atan(t1, r1 * root_minus_a) - atan(t2, root_minus_a * r0)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t3 = float(1) / a;
    float t4 = D * J1 + r1 * slope1 - slope0 * r0;
    F = -(float(1) / float(8)) * (float(2) * slope0 * q0 * r0 - float(2) * r1 * slope1 * q1 - float(3) * D * t3 * t4) * t3 * si.w[0];
    G_ap = (float(1) / float(2)) * t3 * t4 * si.w[0];
    float t5 = q0 * r0;
    float t6 = q1 * r1;
    G_E = -(float(1) / float(3)) * (t5 * si.w[0] - t6 * si.w[0]) * t3;
  }
  float g_factor = -float(3) * inv_R2 * length;
  f = F * length;
  grad[0] = (G_ap * foot0 - ab0 * G_E) * g_factor;
  grad[1] = -(ab1 * G_E - G_ap * foot1) * g_factor;
  grad[2] = g_factor * (foot2 * G_ap - ab2 * G_E);
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(3/2) dt
// Operations: 33 +, 59 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i3_w1_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ab2 * ap0 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - inv_R2 * ap_ap;
  float D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  float slope0 = si.t0 * a - b;
  float q0 = max(float(0), float(c - si.t0 * (b - slope0)));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c - (b - slope1) * si.t1));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t0 = -slope0;
  float t1 = -slope1;
  float J1 = -(atan(t0, r0 * root_minus_a) - atan(t1, r1 * root_minus_a)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t2 = float(1) / a;
    float t3 = float(3) * (r0 * slope0 - r1 * slope1 - D * J1) * D * t2 + float(2) * q0 * r0 * slope0 - float(2) * q1 * r1 * slope1;
    F = (float(1) / float(40)) * si.w[1] * t2 * (float(8) * q1 * q1 * r1 - float(8) * q0 * q0 * r0 - float(5) * b * t3 * t2) - (float(1) / float(8)) * t3 * si.w[0] * t2;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(3/2) dt
// Operations: 46 +, 101 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i3_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  float ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
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
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -ab_ap * inv_R2;
  float c = float(1) - inv_R2 * ap_ap;
  float D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  float slope0 = si.t0 * a - b;
  float q0 = max(float(0), float(c - si.t0 * (b - slope0)));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c - si.t1 * (b - slope1)));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t1 = -slope0;
  float t2 = -slope1;
  float J1 = -(atan(t1, r0 * root_minus_a) - atan(t2, r1 * root_minus_a)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t3 = r1 * slope1 + D * J1 - r0 * slope0;
    float t4 = float(1) / a;
    float t5 = float(2) * r1 * slope1 * q1 + float(3) * t3 * D * t4 - float(2) * r0 * slope0 * q0;
    F = (float(1) / float(8)) * t5 * si.w[0] * t4 - (float(1) / float(40)) * si.w[1] * (float(8) * r0 * q0 * q0 - float(5) * b * t5 * t4 - float(8) * r1 * q1 * q1) * t4;
    G_ap = (float(1) / float(2)) * t3 * si.w[0] * t4 + (float(1) / float(6)) * si.w[1] * (float(3) * b * t3 * t4 + float(2) * r1 * q1 - float(2) * r0 * q0) * t4;
    float t6 = q0 * r0;
    float t7 = q1 * r1;
    G_E = -(float(1) / float(24)) * t4 * (si.w[1] * t5 * t4 + float(8) * t6 * (si.w[1] * si.t0 + si.w[0]) - float(8) * t7 * (si.w[0] + si.w[1] * si.t1));
  }
  float g_factor = -float(3) * length * inv_R2;
  f = F * length;
  grad[0] = (G_ap * foot0 - ab0 * G_E) * g_factor;
  grad[1] = -g_factor * (ab1 * G_E - foot1 * G_ap);
  grad[2] = (foot2 * G_ap - ab2 * G_E) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(3/2) dt
// Operations: 38 +, 79 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i3_w2_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  float ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
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
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -ab_ap * inv_R2;
  float c = float(1) - ap_ap * inv_R2;
  float D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c - (b - slope0) * si.t0));
  float r0 = sqrt(q0);
  float slope1 = a * si.t1 - b;
  float q1 = max(float(0), float(c + (slope1 - b) * si.t1));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t0 = -slope0;
  float J1 = (atan(-slope1, root_minus_a * r1) - atan(t0, root_minus_a * r0)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t1 = float(1) / a;
    float t2 = float(3) * D * t1 * (D * J1 + slope1 * r1 - r0 * slope0) + float(2) * slope1 * q1 * r1 - float(2) * q0 * r0 * slope0;
    float t3 = q1 * q1;
    float t4 = q0 * q0;
    float t5 = float(5) * t1 * t2 * b + float(8) * t3 * r1 - float(8) * t4 * r0;
    F = (float(1) / float(8)) * t1 * t2 * si.w[0] + (float(1) / float(40)) * t1 * t5 * si.w[1] - (float(1) / float(240)) * t1 * si.w[2] * (float(5) * t1 * (float(8) * t4 * r0 * slope0 - float(8) * slope1 * t3 * r1 - float(5) * D * t1 * t2) + float(30) * t1 * t2 * c - float(12) * t1 * b * t5);
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(3/2) dt
// Operations: 57 +, 140 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i3_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
  float ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
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
    foot2 = ap2 - ab2 * t0 * ab_ap;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - inv_R2 * ap_ap;
  float D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c - (b - slope0) * si.t0));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c - (b - slope1) * si.t1));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t1 = -slope1;
  float t2 = -slope0;
  float J1 = (atan(t1, r1 * root_minus_a) - atan(t2, root_minus_a * r0)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t3 = D * J1 + r1 * slope1 - slope0 * r0;
    float t4 = float(1) / a;
    float t5 = float(3) * D * t3 * t4 + float(2) * r1 * slope1 * q1 - float(2) * slope0 * q0 * r0;
    float t6 = q0 * q0;
    float t7 = q1 * q1;
    float t8 = float(8) * t6 * r0 - float(8) * r1 * t7 - float(5) * t5 * b * t4;
    F = (float(1) / float(8)) * t5 * si.w[0] * t4 - (float(1) / float(40)) * t8 * si.w[1] * t4 - (float(1) / float(240)) * (float(12) * b * t8 * t4 + float(30) * t5 * c * t4 + float(5) * t4 * (float(8) * slope0 * t6 * r0 - float(5) * t5 * D * t4 - float(8) * r1 * slope1 * t7)) * t4 * si.w[2];
    float t9 = float(3) * b * t3 * t4 + float(2) * r1 * q1 - float(2) * q0 * r0;
    G_ap = (float(1) / float(2)) * si.w[0] * t3 * t4 + (float(1) / float(6)) * t9 * si.w[1] * t4 - (float(1) / float(24)) * (float(12) * c * t3 * t4 - float(8) * b * t9 * t4 - float(3) * t5 * t4) * t4 * si.w[2];
    float t10 = q1 * r1;
    float t11 = q0 * r0;
    G_E = (float(1) / float(120)) * (float(2) * t8 * t4 * si.w[2] + float(40) * t10 * (si.w[0] + si.t1 * si.w[1] + si.t1 * si.t1 * si.w[2]) - float(5) * t5 * si.w[1] * t4 - float(40) * (si.w[2] * si.t0 * si.t0 + si.w[0] + si.w[1] * si.t0) * t11) * t4;
  }
  float g_factor = -float(3) * inv_R2 * length;
  f = length * F;
  grad[0] = g_factor * (G_ap * foot0 - ab0 * G_E);
  grad[1] = -(ab1 * G_E - G_ap * foot1) * g_factor;
  grad[2] = g_factor * (foot2 * G_ap - ab2 * G_E);
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(3/2) dt
// Operations: 43 +, 99 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i3_w3_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
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
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - inv_R2 * ap_ap;
  float D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  float slope0 = si.t0 * a - b;
  float q0 = max(float(0), float(c - (b - slope0) * si.t0));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(si.t1 * (slope1 - b) + c));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t0 = -slope0;
  float J1 = -(atan(t0, r0 * root_minus_a) - atan(-slope1, r1 * root_minus_a)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t1 = q1 * q1;
    float t2 = float(1) / a;
    float t3 = float(3) * (slope1 * r1 + J1 * D - r0 * slope0) * t2 * D + float(2) * slope1 * q1 * r1 - float(2) * q0 * r0 * slope0;
    float t4 = q0 * q0;
    float t5 = float(8) * t1 * r1 + float(5) * t3 * b * t2 - float(8) * t4 * r0;
    float t6 = float(5) * t3 * t2 * D + float(8) * slope1 * t1 * r1 - float(8) * t4 * r0 * slope0;
    float t7 = float(5) * t2 * t6 + float(12) * b * t5 * t2 - float(30) * t3 * c * t2;
    float t8 = t1 * q1;
    float t9 = t4 * q0;
    F = (float(1) / float(40)) * si.w[1] * t5 * t2 + (float(1) / float(1680)) * si.w[3] * (float(14) * b * t7 * t2 + float(5) * (float(7) * b * t2 * t6 + float(48) * t8 * r1 - float(48) * t9 * r0) * t2 - float(42) * c * t5 * t2) * t2 + (float(1) / float(8)) * t3 * si.w[0] * t2 + (float(1) / float(240)) * t7 * si.w[2] * t2;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(3/2) dt
// Operations: 68 +, 178 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i3_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
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
    foot0 = ap0 - t0 * ab0 * ab_ap;
    foot1 = ap1 - t0 * ab1 * ab_ap;
    foot2 = ap2 - t0 * ab2 * ab_ap;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - ap_ap * inv_R2;
  float D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c - si.t0 * (b - slope0)));
  float r0 = sqrt(q0);
  float slope1 = a * si.t1 - b;
  float q1 = max(float(0), float(c - si.t1 * (b - slope1)));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t1 = -slope0;
  float t2 = -slope1;
  float J1 = -(atan(t1, r0 * root_minus_a) - atan(t2, r1 * root_minus_a)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t3 = float(1) / a;
    float t4 = q1 * q1;
    float t5 = q0 * q0;
    float t6 = D * J1 + r1 * slope1 - r0 * slope0;
    float t7 = float(2) * r0 * slope0 * q0 - float(2) * q1 * r1 * slope1 - float(3) * D * t6 * t3;
    float t8 = float(8) * t4 * r1 - float(8) * r0 * t5 - float(5) * t3 * t7 * b;
    float t9 = float(8) * r0 * slope0 * t5 + float(5) * D * t3 * t7 - float(8) * t4 * r1 * slope1;
    float t10 = float(30) * t3 * t7 * c + float(12) * t3 * b * t8 - float(5) * t3 * t9;
    float t11 = t4 * q1;
    float t12 = t5 * q0;
    F = (float(1) / float(40)) * t3 * t8 * si.w[1] + (float(1) / float(240)) * t10 * si.w[2] * t3 - (float(1) / float(8)) * t3 * t7 * si.w[0] - (float(1) / float(1680)) * t3 * si.w[3] * (float(42) * t3 * t8 * c - float(14) * t10 * t3 * b - float(5) * (float(48) * t11 * r1 - float(48) * r0 * t12 - float(7) * t3 * t9 * b) * t3);
    float t13 = float(3) * t6 * t3 * b + float(2) * q1 * r1 - float(2) * r0 * q0;
    float t14 = float(8) * t3 * t13 * b - float(3) * t3 * t7 - float(12) * t6 * t3 * c;
    G_ap = (float(1) / float(120)) * (float(10) * t3 * b * t14 + float(3) * t3 * t8 - float(20) * t3 * t13 * c) * t3 * si.w[3] + (float(1) / float(24)) * si.w[2] * t3 * t14 + (float(1) / float(2)) * t6 * t3 * si.w[0] + (float(1) / float(6)) * t3 * t13 * si.w[1];
    float t15 = si.t1 * si.t1;
    float t16 = t15 * si.t1;
    float t17 = q1 * r1;
    float t18 = q0 * r0;
    float t19 = si.t0 * si.t0;
    float t20 = t19 * si.t0;
    G_E = (float(1) / float(240)) * (float(80) * (si.w[2] * si.t1 * si.t1 + si.w[0] + si.t1 * si.w[1] + si.w[3] * t16) * t17 + float(10) * t3 * t7 * si.w[1] - t10 * t3 * si.w[3] - float(4) * si.w[2] * t3 * t8 - float(80) * t18 * (si.w[3] * t20 + si.t0 * si.w[1] + si.w[0] + si.w[2] * t19)) * t3;
  }
  float g_factor = -float(3) * inv_R2 * length;
  f = F * length;
  grad[0] = -g_factor * (G_E * ab0 - foot0 * G_ap);
  grad[1] = -(G_E * ab1 - foot1 * G_ap) * g_factor;
  grad[2] = -(G_E * ab2 - foot2 * G_ap) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(5/2) dt
// Operations: 32 +, 58 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i5_w0_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ap2 * ab1 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ap2 * ab0;
  float plain_cross2 = ap1 * ab0 - ap0 * ab1;
  float plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -inv_R2 * ab_ab;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - inv_R2 * ap_ap;
  float D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c + (slope0 - b) * si.t0));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c + si.t1 * (slope1 - b)));
  float r1 = sqrt(q1);
  float root_minus_a = length * inv_R;
  float J1 = (atan(-slope1, r1 * root_minus_a) - atan(-slope0, root_minus_a * r0)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t0 = float(1) / a;
    F = -(float(1) / float(48)) * t0 * (float(8) * slope0 * q0 * q0 * r0 + float(5) * t0 * D * (float(2) * slope0 * q0 * r0 - float(2) * r1 * slope1 * q1 - float(3) * t0 * D * (r1 * slope1 + D * J1 - slope0 * r0)) - float(8) * r1 * slope1 * q1 * q1) * si.w[0];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(5/2) dt
// Operations: 39 +, 86 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i5_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -ab_ap * inv_R2;
  float c = float(1) - inv_R2 * ap_ap;
  float D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c - (b - slope0) * si.t0));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c - si.t1 * (b - slope1)));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t1 = -slope1;
  float t2 = -slope0;
  float J1 = (atan(t1, r1 * root_minus_a) - atan(t2, root_minus_a * r0)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t3 = float(1) / a;
    float t4 = float(2) * slope0 * q0 * r0 - float(2) * r1 * slope1 * q1 - float(3) * (D * J1 + r1 * slope1 - slope0 * r0) * D * t3;
    F = -(float(1) / float(48)) * (float(5) * t4 * D * t3 + float(8) * slope0 * q0 * q0 * r0 - float(8) * r1 * slope1 * q1 * q1) * t3 * si.w[0];
    G_ap = -(float(1) / float(8)) * t4 * t3 * si.w[0];
    float t5 = q0 * q0 * r0;
    float t6 = q1 * q1 * r1;
    G_E = -(float(1) / float(5)) * (si.w[0] * t5 - t6 * si.w[0]) * t3;
  }
  float g_factor = -float(5) * length * inv_R2;
  f = length * F;
  grad[0] = (G_ap * foot0 - ab0 * G_E) * g_factor;
  grad[1] = -g_factor * (ab1 * G_E - G_ap * foot1);
  grad[2] = (foot2 * G_ap - ab2 * G_E) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(5/2) dt
// Operations: 35 +, 72 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i5_w1_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ab2 * ap0 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross1 * plain_cross1 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -ab_ap * inv_R2;
  float c = float(1) - inv_R2 * ap_ap;
  float D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  float slope0 = si.t0 * a - b;
  float q0 = max(float(0), float(c - si.t0 * (b - slope0)));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c + (slope1 - b) * si.t1));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t0 = -slope0;
  float J1 = (atan(-slope1, r1 * root_minus_a) - atan(t0, r0 * root_minus_a)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t1 = float(1) / a;
    float t2 = float(8) * q0 * q0 * r0 * slope0 - float(5) * (float(2) * slope1 * q1 * r1 - float(3) * (r0 * slope0 - slope1 * r1 - J1 * D) * D * t1 - float(2) * q0 * r0 * slope0) * D * t1 - float(8) * slope1 * q1 * q1 * r1;
    float t3 = q0 * q0;
    float t4 = t3 * q0;
    float t5 = q1 * q1;
    float t6 = t5 * q1;
    F = -(float(1) / float(336)) * si.w[1] * t1 * (float(7) * b * t2 * t1 + float(48) * t4 * r0 - float(48) * t6 * r1) - (float(1) / float(48)) * si.w[0] * t2 * t1;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(5/2) dt
// Operations: 48 +, 112 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i5_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  float ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  float ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  float plain_cross0 = ap2 * ab1 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ap2 * ab0;
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
    foot2 = ap2 - ab_ap * t0 * ab2;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -ab_ap * inv_R2;
  float c = float(1) - ap_ap * inv_R2;
  float D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c - si.t0 * (b - slope0)));
  float r0 = sqrt(q0);
  float slope1 = a * si.t1 - b;
  float q1 = max(float(0), float(c + (slope1 - b) * si.t1));
  float r1 = sqrt(q1);
  float root_minus_a = length * inv_R;
  float t1 = -slope0;
  float J1 = (atan(-slope1, r1 * root_minus_a) - atan(t1, r0 * root_minus_a)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t2 = float(1) / a;
    float t3 = float(2) * slope1 * q1 * r1 - float(2) * q0 * r0 * slope0 - float(3) * (r0 * slope0 - slope1 * r1 - D * J1) * t2 * D;
    float t4 = q1 * q1;
    float t5 = q0 * q0;
    float t6 = float(5) * t2 * D * t3 + float(8) * slope1 * t4 * r1 - float(8) * t5 * r0 * slope0;
    float t7 = t4 * q1;
    float t8 = t5 * q0;
    F = (float(1) / float(336)) * t2 * si.w[1] * (float(7) * t2 * t6 * b + float(48) * t7 * r1 - float(48) * t8 * r0) + (float(1) / float(48)) * si.w[0] * t2 * t6;
    G_ap = (float(1) / float(8)) * si.w[0] * t2 * t3 + (float(1) / float(40)) * t2 * si.w[1] * (float(5) * t2 * t3 * b + float(8) * t4 * r1 - float(8) * t5 * r0);
    float t9 = t5 * r0;
    float t10 = t4 * r1;
    G_E = -(float(1) / float(240)) * t2 * (t2 * t6 * si.w[1] + float(48) * (si.w[1] * si.t0 + si.w[0]) * t9 - float(48) * (si.w[0] + si.w[1] * si.t1) * t10);
  }
  float g_factor = -float(5) * length * inv_R2;
  f = length * F;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = -g_factor * (G_E * ab1 - foot1 * G_ap);
  grad[2] = -g_factor * (G_E * ab2 - foot2 * G_ap);
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(5/2) dt
// Operations: 40 +, 92 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i5_w2_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  float ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ap2 * ab1 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ap0 * ab1;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -inv_R2 * ab_ab;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - inv_R2 * ap_ap;
  float D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  float slope0 = si.t0 * a - b;
  float q0 = max(float(0), float(c + si.t0 * (slope0 - b)));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c + si.t1 * (slope1 - b)));
  float r1 = sqrt(q1);
  float root_minus_a = length * inv_R;
  float J1 = (atan(-slope1, r1 * root_minus_a) - atan(-slope0, root_minus_a * r0)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t0 = float(1) / a;
    float t1 = float(5) * t0 * D * (float(2) * slope0 * q0 * r0 - float(2) * r1 * slope1 * q1 - float(3) * t0 * D * (D * J1 + r1 * slope1 - slope0 * r0)) + float(8) * slope0 * q0 * q0 * r0 - float(8) * r1 * slope1 * q1 * q1;
    float t2 = q1 * q1;
    float t3 = t2 * q1;
    float t4 = q0 * q0;
    float t5 = t4 * q0;
    float t6 = float(48) * r1 * t3 - float(7) * t0 * b * t1 - float(48) * t5 * r0;
    F = (float(1) / float(2688)) * t0 * (float(56) * c * t0 * t1 + float(16) * t0 * b * t6 - float(7) * t0 * (float(7) * t0 * D * t1 + float(48) * slope0 * t5 * r0 - float(48) * r1 * slope1 * t3)) * si.w[2] + (float(1) / float(336)) * si.w[1] * t0 * t6 - (float(1) / float(48)) * t0 * t1 * si.w[0];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(5/2) dt
// Operations: 59 +, 151 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i5_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  float ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ab1 * ap2 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
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
    foot0 = ap0 - ab0 * ab_ap * t0;
    foot1 = ap1 - ab1 * ab_ap * t0;
    foot2 = ap2 - ab_ap * t0 * ab2;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -inv_R2 * ab_ab;
  float b = -ab_ap * inv_R2;
  float c = float(1) - inv_R2 * ap_ap;
  float D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float((slope0 - b) * si.t0 + c));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(si.t1 * (slope1 - b) + c));
  float r1 = sqrt(q1);
  float root_minus_a = length * inv_R;
  float J1 = -(atan(-slope0, root_minus_a * r0) - atan(-slope1, root_minus_a * r1)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t1 = q0 * q0;
    float t2 = t1 * q0;
    float t3 = float(1) / a;
    float t4 = q1 * q1;
    float t5 = float(2) * slope1 * q1 * r1 + float(3) * D * t3 * (slope1 * r1 + D * J1 - slope0 * r0) - float(2) * slope0 * q0 * r0;
    float t6 = float(8) * slope0 * t1 * r0 - float(8) * slope1 * t4 * r1 - float(5) * D * t3 * t5;
    float t7 = t4 * q1;
    float t8 = float(48) * t2 * r0 + float(7) * t3 * t6 * b - float(48) * t7 * r1;
    F = -(float(1) / float(336)) * t8 * si.w[1] * t3 - (float(1) / float(48)) * si.w[0] * t3 * t6 - (float(1) / float(2688)) * t3 * (float(7) * t3 * (float(7) * D * t3 * t6 + float(48) * slope0 * t2 * r0 - float(48) * slope1 * t7 * r1) + float(16) * t8 * t3 * b - float(56) * c * t3 * t6) * si.w[2];
    float t9 = float(8) * t1 * r0 - float(5) * t3 * b * t5 - float(8) * t4 * r1;
    G_ap = (float(1) / float(8)) * si.w[0] * t3 * t5 - (float(1) / float(40)) * si.w[1] * t3 * t9 - (float(1) / float(240)) * t3 * (float(30) * c * t3 * t5 + float(5) * t3 * t6 + float(12) * t3 * t9 * b) * si.w[2];
    float t10 = t4 * r1;
    float t11 = t1 * r0;
    G_E = (float(1) / float(1680)) * t3 * (float(2) * t8 * t3 * si.w[2] + float(7) * si.w[1] * t3 * t6 + float(336) * (si.w[0] + si.t1 * si.t1 * si.w[2] + si.t1 * si.w[1]) * t10 - float(336) * (si.w[0] + si.w[1] * si.t0 + si.t0 * si.t0 * si.w[2]) * t11);
  }
  float g_factor = -float(5) * inv_R2 * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_E - G_ap * foot0);
  grad[1] = g_factor * (G_ap * foot1 - ab1 * G_E);
  grad[2] = g_factor * (foot2 * G_ap - G_E * ab2);
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(5/2) dt
// Operations: 45 +, 111 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i5_w3_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
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
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - inv_R2 * ap_ap;
  float D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  float slope0 = si.t0 * a - b;
  float q0 = max(float(0), float(c - (b - slope0) * si.t0));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c - si.t1 * (b - slope1)));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t0 = -slope1;
  float t1 = -slope0;
  float J1 = (atan(t0, r1 * root_minus_a) - atan(t1, r0 * root_minus_a)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t2 = q1 * q1;
    float t3 = t2 * q1;
    float t4 = float(1) / a;
    float t5 = float(8) * r0 * slope0 * q0 * q0 - float(5) * (float(2) * q1 * r1 * slope1 - float(2) * r0 * slope0 * q0 - float(3) * D * (r0 * slope0 - r1 * slope1 - J1 * D) * t4) * D * t4 - float(8) * t2 * r1 * slope1;
    float t6 = q0 * q0;
    float t7 = t6 * q0;
    float t8 = float(48) * t3 * r1 - float(7) * b * t5 * t4 - float(48) * r0 * t7;
    float t9 = float(7) * t5 * D * t4 + float(48) * r0 * slope0 * t7 - float(48) * t3 * r1 * slope1;
    float t10 = float(7) * t9 * t4 - float(56) * t5 * c * t4 - float(16) * b * t8 * t4;
    float t11 = t6 * t6;
    float t12 = t2 * t2;
    F = (float(1) / float(336)) * t8 * si.w[1] * t4 - (float(1) / float(8064)) * t4 * (float(6) * b * t10 * t4 + float(7) * (float(128) * r0 * t11 + float(3) * b * t9 * t4 - float(128) * t12 * r1) * t4 + float(24) * t8 * c * t4) * si.w[3] - (float(1) / float(48)) * t5 * t4 * si.w[0] - (float(1) / float(2688)) * si.w[2] * t10 * t4;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(5/2) dt
// Operations: 70 +, 191 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i5_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  float ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  float ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
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
    foot0 = ap0 - ab0 * ab_ap * t0;
    foot1 = ap1 - ab1 * ab_ap * t0;
    foot2 = ap2 - ab2 * ab_ap * t0;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -inv_R2 * ab_ab;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - inv_R2 * ap_ap;
  float D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c + (slope0 - b) * si.t0));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c + si.t1 * (slope1 - b)));
  float r1 = sqrt(q1);
  float root_minus_a = length * inv_R;
  float J1 = (atan(-slope1, root_minus_a * r1) - atan(-slope0, root_minus_a * r0)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t1 = float(1) / a;
    float t2 = q1 * q1;
    float t3 = t2 * t2;
    float t4 = t2 * q1;
    float t5 = q0 * q0;
    float t6 = float(3) * D * t1 * (slope0 * r0 - slope1 * r1 - D * J1) + float(2) * slope0 * q0 * r0 - float(2) * slope1 * q1 * r1;
    float t7 = float(8) * slope1 * t2 * r1 - float(8) * slope0 * t5 * r0 - float(5) * D * t1 * t6;
    float t8 = t5 * q0;
    float t9 = float(48) * slope1 * t4 * r1 + float(7) * t7 * D * t1 - float(48) * slope0 * t8 * r0;
    float t10 = t5 * t5;
    float t11 = float(48) * t8 * r0 - float(48) * t4 * r1 - float(7) * t7 * t1 * b;
    float t12 = float(56) * t7 * c * t1 + float(16) * t1 * t11 * b - float(7) * t1 * t9;
    F = (float(1) / float(8064)) * t1 * (float(7) * t1 * (float(128) * t3 * r1 + float(3) * t1 * t9 * b - float(128) * t10 * r0) + float(24) * c * t1 * t11 - float(6) * t12 * t1 * b) * si.w[3] + (float(1) / float(48)) * t7 * t1 * si.w[0] - (float(1) / float(336)) * si.w[1] * t1 * t11 - (float(1) / float(2688)) * t12 * si.w[2] * t1;
    float t13 = float(8) * t5 * r0 + float(5) * t1 * t6 * b - float(8) * t2 * r1;
    float t14 = float(30) * c * t1 * t6 + float(5) * t7 * t1 - float(12) * t13 * t1 * b;
    G_ap = (float(1) / float(240)) * t14 * si.w[2] * t1 + (float(1) / float(1680)) * (float(42) * t13 * c * t1 + float(14) * t14 * t1 * b - float(5) * t1 * t11) * t1 * si.w[3] - (float(1) / float(40)) * t13 * si.w[1] * t1 - (float(1) / float(8)) * t1 * t6 * si.w[0];
    float t15 = t5 * r0;
    float t16 = si.t0 * si.t0;
    float t17 = t16 * si.t0;
    float t18 = si.t1 * si.t1;
    float t19 = t18 * si.t1;
    float t20 = t2 * r1;
    G_E = -(float(1) / float(13440)) * t1 * (float(2688) * t15 * (si.w[1] * si.t0 + si.w[2] * si.t0 * si.t0 + si.w[3] * t17 + si.w[0]) + float(56) * t7 * si.w[1] * t1 - float(3) * t12 * t1 * si.w[3] - float(16) * si.w[2] * t1 * t11 - float(2688) * (si.t1 * si.t1 * si.w[2] + t19 * si.w[3] + si.t1 * si.w[1] + si.w[0]) * t20);
  }
  float g_factor = -float(5) * inv_R2 * length;
  f = length * F;
  grad[0] = (G_ap * foot0 - ab0 * G_E) * g_factor;
  grad[1] = (G_ap * foot1 - ab1 * G_E) * g_factor;
  grad[2] = -g_factor * (ab2 * G_E - foot2 * G_ap);
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(7/2) dt
// Operations: 34 +, 71 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i7_w0_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  float ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
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
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - inv_R2 * ap_ap;
  float D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  float slope0 = si.t0 * a - b;
  float q0 = max(float(0), float(c - si.t0 * (b - slope0)));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c - si.t1 * (b - slope1)));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t0 = -slope1;
  float t1 = -slope0;
  float J1 = (atan(t0, r1 * root_minus_a) - atan(t1, r0 * root_minus_a)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t2 = float(1) / a;
    float t3 = q0 * q0;
    float t4 = t3 * q0;
    float t5 = q1 * q1;
    float t6 = t5 * q1;
    F = -(float(1) / float(384)) * (float(7) * (float(5) * (float(2) * q0 * r0 * slope0 + float(3) * (r0 * slope0 - r1 * slope1 - J1 * D) * D * t2 - float(2) * q1 * r1 * slope1) * D * t2 + float(8) * q0 * q0 * r0 * slope0 - float(8) * q1 * q1 * r1 * slope1) * D * t2 + float(48) * t4 * r0 * slope0 - float(48) * t6 * r1 * slope1) * t2 * si.w[0];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(7/2) dt
// Operations: 41 +, 95 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i7_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
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
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - ap_ap * inv_R2;
  float D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c - (b - slope0) * si.t0));
  float r0 = sqrt(q0);
  float slope1 = a * si.t1 - b;
  float q1 = max(float(0), float(c - si.t1 * (b - slope1)));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t1 = -slope1;
  float t2 = -slope0;
  float J1 = (atan(t1, r1 * root_minus_a) - atan(t2, r0 * root_minus_a)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t3 = float(1) / a;
    float t4 = q0 * q0;
    float t5 = t4 * q0;
    float t6 = q1 * q1;
    float t7 = t6 * q1;
    float t8 = float(8) * t6 * r1 * slope1 + float(5) * t3 * D * (float(3) * t3 * D * (r1 * slope1 + D * J1 - r0 * slope0) + float(2) * q1 * r1 * slope1 - float(2) * r0 * slope0 * q0) - float(8) * r0 * slope0 * t4;
    F = -(float(1) / float(384)) * t3 * si.w[0] * (float(48) * r0 * slope0 * t5 - float(48) * t7 * r1 * slope1 - float(7) * t3 * D * t8);
    G_ap = (float(1) / float(48)) * t3 * t8 * si.w[0];
    float t9 = t7 * r1;
    float t10 = t5 * r0;
    G_E = (float(1) / float(7)) * t3 * (si.w[0] * t9 - t10 * si.w[0]);
  }
  float g_factor = -float(7) * inv_R2 * length;
  f = F * length;
  grad[0] = -g_factor * (G_E * ab0 - foot0 * G_ap);
  grad[1] = -g_factor * (G_E * ab1 - foot1 * G_ap);
  grad[2] = -g_factor * (G_E * ab2 - foot2 * G_ap);
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(7/2) dt
// Operations: 37 +, 82 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i7_w1_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ab0 * ap0 + ap1 * ab1 + ab2 * ap2;
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
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - ap_ap * inv_R2;
  float D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c + (slope0 - b) * si.t0));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(si.t1 * (slope1 - b) + c));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float J1 = (atan(-slope1, root_minus_a * r1) - atan(-slope0, root_minus_a * r0)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t0 = float(1) / a;
    float t1 = q1 * q1;
    float t2 = t1 * t1;
    float t3 = t1 * q1;
    float t4 = q0 * q0;
    float t5 = t4 * q0;
    float t6 = float(7) * D * t0 * (float(8) * slope1 * t1 * r1 - float(5) * D * t0 * (float(2) * slope0 * q0 * r0 + float(3) * (slope0 * r0 - D * J1 - slope1 * r1) * D * t0 - float(2) * slope1 * q1 * r1) - float(8) * slope0 * q0 * q0 * r0) + float(48) * slope1 * t3 * r1 - float(48) * slope0 * t5 * r0;
    float t7 = t4 * t4;
    F = (float(1) / float(1152)) * t0 * si.w[1] * (float(128) * t2 * r1 + float(3) * t0 * b * t6 - float(128) * t7 * r0) + (float(1) / float(384)) * si.w[0] * t0 * t6;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(7/2) dt
// Operations: 50 +, 123 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i7_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  float ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ab1 * ap2 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
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
    foot2 = ap2 - t0 * ab_ap * ab2;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -ab_ap * inv_R2;
  float c = float(1) - inv_R2 * ap_ap;
  float D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c + (slope0 - b) * si.t0));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c + (slope1 - b) * si.t1));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float J1 = -(atan(-slope0, root_minus_a * r0) - atan(-slope1, r1 * root_minus_a)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t1 = float(1) / a;
    float t2 = q1 * q1;
    float t3 = t2 * t2;
    float t4 = q0 * q0;
    float t5 = t4 * q0;
    float t6 = float(5) * (float(3) * (D * J1 + r1 * slope1 - slope0 * r0) * D * t1 + float(2) * r1 * slope1 * q1 - float(2) * slope0 * q0 * r0) * D * t1 + float(8) * r1 * slope1 * t2 - float(8) * slope0 * t4 * r0;
    float t7 = t2 * q1;
    float t8 = float(48) * slope0 * t5 * r0 - float(7) * D * t1 * t6 - float(48) * r1 * slope1 * t7;
    float t9 = t4 * t4;
    F = (float(1) / float(1152)) * t1 * si.w[1] * (float(128) * r1 * t3 - float(3) * t8 * t1 * b - float(128) * t9 * r0) - (float(1) / float(384)) * t8 * si.w[0] * t1;
    G_ap = (float(1) / float(48)) * si.w[0] * t1 * t6 - (float(1) / float(336)) * t1 * si.w[1] * (float(48) * t5 * r0 - float(7) * t1 * t6 * b - float(48) * r1 * t7);
    float t10 = t7 * r1;
    float t11 = t5 * r0;
    G_E = (float(1) / float(2688)) * (t8 * t1 * si.w[1] + float(384) * t10 * (si.t1 * si.w[1] + si.w[0]) - float(384) * t11 * (si.w[0] + si.w[1] * si.t0)) * t1;
  }
  float g_factor = -float(7) * inv_R2 * length;
  f = length * F;
  grad[0] = g_factor * (G_ap * foot0 - ab0 * G_E);
  grad[1] = -g_factor * (ab1 * G_E - G_ap * foot1);
  grad[2] = (foot2 * G_ap - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(7/2) dt
// Operations: 42 +, 102 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i7_w2_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -ab_ap * inv_R2;
  float c = float(1) - inv_R2 * ap_ap;
  float D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  float slope0 = si.t0 * a - b;
  float q0 = max(float(0), float(c - (b - slope0) * si.t0));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c + (slope1 - b) * si.t1));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t0 = -slope0;
  float J1 = -(atan(t0, r0 * root_minus_a) - atan(-slope1, r1 * root_minus_a)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t1 = q1 * q1;
    float t2 = t1 * t1;
    float t3 = float(1) / a;
    float t4 = t1 * q1;
    float t5 = q0 * q0;
    float t6 = t5 * q0;
    float t7 = float(7) * (float(5) * D * (float(2) * slope1 * q1 * r1 - float(3) * D * t3 * (r0 * slope0 - slope1 * r1 - J1 * D) - float(2) * q0 * r0 * slope0) * t3 + float(8) * slope1 * t1 * r1 - float(8) * q0 * q0 * r0 * slope0) * D * t3 + float(48) * slope1 * t4 * r1 - float(48) * t6 * r0 * slope0;
    float t8 = t5 * t5;
    float t9 = float(128) * t2 * r1 + float(3) * b * t7 * t3 - float(128) * t8 * r0;
    F = (float(1) / float(1152)) * t9 * si.w[1] * t3 + (float(1) / float(384)) * si.w[0] * t7 * t3 - (float(1) / float(11520)) * t3 * si.w[2] * (float(30) * c * t7 * t3 + float(9) * (float(128) * t8 * r0 * slope0 - float(3) * t7 * D * t3 - float(128) * slope1 * t2 * r1) * t3 - float(20) * b * t9 * t3);
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(7/2) dt
// Operations: 61 +, 163 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i7_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  float ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ap2 * ab1 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
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
    foot2 = ap2 - ab_ap * t0 * ab2;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -inv_R2 * ab_ab;
  float b = -ab_ap * inv_R2;
  float c = float(1) - inv_R2 * ap_ap;
  float D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c - si.t0 * (b - slope0)));
  float r0 = sqrt(q0);
  float slope1 = a * si.t1 - b;
  float q1 = max(float(0), float(c + (slope1 - b) * si.t1));
  float r1 = sqrt(q1);
  float root_minus_a = length * inv_R;
  float t1 = -slope0;
  float J1 = -(atan(t1, root_minus_a * r0) - atan(-slope1, root_minus_a * r1)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t2 = float(1) / a;
    float t3 = q0 * q0;
    float t4 = t3 * q0;
    float t5 = float(5) * D * t2 * (float(3) * D * t2 * (slope1 * r1 + D * J1 - r0 * slope0) + float(2) * slope1 * q1 * r1 - float(2) * q0 * r0 * slope0) + float(8) * slope1 * q1 * q1 * r1 - float(8) * t3 * r0 * slope0;
    float t6 = q1 * q1;
    float t7 = t6 * q1;
    float t8 = float(48) * t4 * r0 * slope0 - float(7) * D * t2 * t5 - float(48) * slope1 * t7 * r1;
    float t9 = t3 * t3;
    float t10 = t6 * t6;
    float t11 = float(3) * t2 * b * t8 + float(128) * t9 * r0 - float(128) * t10 * r1;
    F = -(float(1) / float(1152)) * si.w[1] * t11 * t2 - (float(1) / float(11520)) * t2 * si.w[2] * (float(20) * t11 * t2 * b + float(9) * t2 * (float(3) * D * t2 * t8 + float(128) * t9 * r0 * slope0 - float(128) * slope1 * t10 * r1) - float(30) * c * t2 * t8) - (float(1) / float(384)) * t2 * t8 * si.w[0];
    float t12 = float(48) * t4 * r0 - float(7) * t2 * b * t5 - float(48) * t7 * r1;
    G_ap = (float(1) / float(48)) * t2 * t5 * si.w[0] - (float(1) / float(336)) * si.w[1] * t12 * t2 - (float(1) / float(2688)) * (float(16) * t12 * t2 * b + float(56) * c * t2 * t5 + float(7) * t2 * t8) * t2 * si.w[2];
    float t13 = t4 * r0;
    float t14 = t7 * r1;
    G_E = -(float(1) / float(8064)) * (float(1152) * (si.w[1] * si.t0 + si.t0 * si.t0 * si.w[2] + si.w[0]) * t13 - float(1152) * (si.w[2] * si.t1 * si.t1 + si.w[1] * si.t1 + si.w[0]) * t14 - float(2) * t11 * t2 * si.w[2] - float(3) * si.w[1] * t2 * t8) * t2;
  }
  float g_factor = -float(7) * length * inv_R2;
  f = length * F;
  grad[0] = (foot0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = (foot1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = (foot2 * G_ap - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(7/2) dt
// Operations: 47 +, 121 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i7_w3_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  float ab_ap = ap2 * ab2 + ab0 * ap0 + ab1 * ap1;
  float ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  float plain_cross0 = ab1 * ap2 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -ab_ap * inv_R2;
  float c = float(1) - ap_ap * inv_R2;
  float D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float((slope0 - b) * si.t0 + c));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(si.t1 * (slope1 - b) + c));
  float r1 = sqrt(q1);
  float root_minus_a = length * inv_R;
  float J1 = (atan(-slope1, r1 * root_minus_a) - atan(-slope0, root_minus_a * r0)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t0 = float(1) / a;
    float t1 = q1 * q1;
    float t2 = t1 * t1;
    float t3 = q0 * q0;
    float t4 = t3 * q0;
    float t5 = t1 * q1;
    float t6 = float(48) * slope0 * t4 * r0 + float(7) * D * t0 * (float(8) * slope0 * t3 * r0 - float(5) * D * t0 * (float(3) * D * t0 * (D * J1 + r1 * slope1 - slope0 * r0) + float(2) * r1 * slope1 * q1 - float(2) * slope0 * q0 * r0) - float(8) * r1 * slope1 * t1) - float(48) * r1 * slope1 * t5;
    float t7 = t3 * t3;
    float t8 = float(128) * r1 * t2 - float(3) * t0 * b * t6 - float(128) * t7 * r0;
    float t9 = t2 * q1;
    float t10 = float(128) * r1 * slope1 * t2 - float(128) * slope0 * t7 * r0 - float(3) * D * t0 * t6;
    float t11 = t7 * q0;
    float t12 = float(20) * t0 * b * t8 + float(9) * t0 * t10 + float(30) * t0 * t6 * c;
    F = (float(1) / float(1152)) * si.w[1] * t0 * t8 + (float(1) / float(126720)) * t0 * (float(9) * t0 * (float(1280) * r1 * t9 + float(11) * t0 * b * t10 - float(1280) * t11 * r0) + float(22) * t0 * b * t12 - float(110) * t0 * t8 * c) * si.w[3] + (float(1) / float(11520)) * t0 * si.w[2] * t12 - (float(1) / float(384)) * t0 * t6 * si.w[0];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(7/2) dt
// Operations: 72 +, 202 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i7_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  float ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
    foot2 = ap2 - ab2 * t0 * ab_ap;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - ap_ap * inv_R2;
  float D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  float slope0 = si.t0 * a - b;
  float q0 = max(float(0), float(c - si.t0 * (b - slope0)));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c - si.t1 * (b - slope1)));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t1 = -slope0;
  float t2 = -slope1;
  float J1 = -(atan(t1, r0 * root_minus_a) - atan(t2, r1 * root_minus_a)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t3 = q0 * q0;
    float t4 = t3 * q0;
    float t5 = float(1) / a;
    float t6 = float(8) * r0 * slope0 * t3 - float(5) * (float(2) * q1 * r1 * slope1 - float(2) * r0 * slope0 * q0 - float(3) * (r0 * slope0 - J1 * D - r1 * slope1) * D * t5) * D * t5 - float(8) * q1 * q1 * r1 * slope1;
    float t7 = q1 * q1;
    float t8 = t7 * q1;
    float t9 = float(48) * r0 * slope0 * t4 + float(7) * t6 * D * t5 - float(48) * t8 * r1 * slope1;
    float t10 = t7 * t7;
    float t11 = t3 * t3;
    float t12 = float(128) * t10 * r1 * slope1 - float(128) * r0 * slope0 * t11 - float(3) * t9 * D * t5;
    float t13 = float(3) * t9 * b * t5 + float(128) * r0 * t11 - float(128) * t10 * r1;
    float t14 = float(30) * t9 * c * t5 + float(9) * t12 * t5 - float(20) * t13 * b * t5;
    float t15 = t11 * q0;
    float t16 = t10 * q1;
    F = (float(1) / float(11520)) * t14 * si.w[2] * t5 - (float(1) / float(1152)) * t13 * si.w[1] * t5 - (float(1) / float(384)) * t9 * si.w[0] * t5 - (float(1) / float(126720)) * si.w[3] * (float(9) * (float(1280) * r0 * t15 - float(1280) * t16 * r1 - float(11) * t12 * b * t5) * t5 - float(22) * b * t14 * t5 - float(110) * t13 * c * t5) * t5;
    float t17 = float(7) * b * t6 * t5 + float(48) * r0 * t4 - float(48) * t8 * r1;
    float t18 = float(7) * t9 * t5 + float(16) * b * t17 * t5 - float(56) * c * t6 * t5;
    G_ap = -(float(1) / float(2688)) * t18 * si.w[2] * t5 - (float(1) / float(8064)) * si.w[3] * (float(6) * b * t18 * t5 + float(7) * t13 * t5 - float(24) * t17 * c * t5) * t5 - (float(1) / float(336)) * t17 * si.w[1] * t5 - (float(1) / float(48)) * si.w[0] * t6 * t5;
    float t19 = si.t0 * si.t0;
    float t20 = t19 * si.t0;
    float t21 = t4 * r0;
    float t22 = t8 * r1;
    float t23 = si.t1 * si.t1;
    float t24 = t23 * si.t1;
    G_E = -(float(1) / float(80640)) * (float(3) * si.w[3] * t14 * t5 + float(11520) * (si.w[0] + t20 * si.w[3] + t19 * si.w[2] + si.t0 * si.w[1]) * t21 - float(20) * t13 * si.w[2] * t5 - float(11520) * t22 * (si.t1 * si.w[1] + si.w[0] + si.t1 * si.t1 * si.w[2] + si.w[3] * t24) - float(30) * t9 * si.w[1] * t5) * t5;
  }
  float g_factor = -float(7) * inv_R2 * length;
  f = F * length;
  grad[0] = g_factor * (G_ap * foot0 - ab0 * G_E);
  grad[1] = -g_factor * (ab1 * G_E - foot1 * G_ap);
  grad[2] = -(ab2 * G_E - foot2 * G_ap) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(9/2) dt
// Operations: 36 +, 80 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i9_w0_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  float ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -ab_ap * inv_R2;
  float c = float(1) - ap_ap * inv_R2;
  float D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(si.t0 * (slope0 - b) + c));
  float r0 = sqrt(q0);
  float slope1 = a * si.t1 - b;
  float q1 = max(float(0), float(c + (slope1 - b) * si.t1));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float J1 = (atan(-slope1, root_minus_a * r1) - atan(-slope0, root_minus_a * r0)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t0 = float(1) / a;
    float t1 = q0 * q0;
    float t2 = t1 * t1;
    float t3 = q1 * q1;
    float t4 = t3 * q1;
    float t5 = t1 * q0;
    float t6 = t3 * t3;
    F = -(float(1) / float(1280)) * t0 * si.w[0] * (float(128) * slope0 * t2 * r0 - float(3) * D * t0 * (float(48) * slope1 * t4 * r1 + float(7) * D * t0 * (float(8) * slope1 * t3 * r1 - float(5) * D * t0 * (float(3) * D * t0 * (slope0 * r0 - D * J1 - slope1 * r1) + float(2) * slope0 * q0 * r0 - float(2) * slope1 * q1 * r1) - float(8) * slope0 * t1 * r0) - float(48) * slope0 * t5 * r0) - float(128) * slope1 * t6 * r1);
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(9/2) dt
// Operations: 43 +, 108 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i9_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
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
    foot2 = ap2 - ab_ap * ab2 * t0;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -inv_R2 * ab_ab;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - inv_R2 * ap_ap;
  float D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c - (b - slope0) * si.t0));
  float r0 = sqrt(q0);
  float slope1 = a * si.t1 - b;
  float q1 = max(float(0), float((slope1 - b) * si.t1 + c));
  float r1 = sqrt(q1);
  float root_minus_a = length * inv_R;
  float t1 = -slope0;
  float J1 = -(atan(t1, root_minus_a * r0) - atan(-slope1, root_minus_a * r1)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t2 = float(1) / a;
    float t3 = q0 * q0;
    float t4 = t3 * q0;
    float t5 = q1 * q1;
    float t6 = t5 * q1;
    float t7 = float(7) * (float(8) * q0 * q0 * r0 * slope0 - float(8) * slope1 * q1 * q1 * r1 - float(5) * D * t2 * (float(3) * (slope1 * r1 + D * J1 - r0 * slope0) * D * t2 + float(2) * slope1 * q1 * r1 - float(2) * q0 * r0 * slope0)) * D * t2 + float(48) * t4 * r0 * slope0 - float(48) * slope1 * t6 * r1;
    float t8 = t3 * t3;
    float t9 = t5 * t5;
    F = -(float(1) / float(1280)) * t2 * (float(3) * D * t2 * t7 + float(128) * t8 * r0 * slope0 - float(128) * slope1 * t9 * r1) * si.w[0];
    G_ap = -(float(1) / float(384)) * t2 * t7 * si.w[0];
    float t10 = t9 * r1;
    float t11 = t8 * r0;
    G_E = (float(1) / float(9)) * t2 * (si.w[0] * t10 - t11 * si.w[0]);
  }
  float g_factor = -float(9) * inv_R2 * length;
  f = length * F;
  grad[0] = (foot0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = -g_factor * (G_E * ab1 - foot1 * G_ap);
  grad[2] = -(G_E * ab2 - foot2 * G_ap) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(9/2) dt
// Operations: 39 +, 94 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i9_w1_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  float ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  float ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ab2 * ap0 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -inv_R2 * ab_ab;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - inv_R2 * ap_ap;
  float D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  float slope0 = si.t0 * a - b;
  float q0 = max(float(0), float(c + si.t0 * (slope0 - b)));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c + si.t1 * (slope1 - b)));
  float r1 = sqrt(q1);
  float root_minus_a = length * inv_R;
  float J1 = (atan(-slope1, r1 * root_minus_a) - atan(-slope0, r0 * root_minus_a)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t0 = float(1) / a;
    float t1 = q1 * q1;
    float t2 = t1 * q1;
    float t3 = q0 * q0;
    float t4 = t3 * q0;
    float t5 = t1 * t1;
    float t6 = t3 * t3;
    float t7 = float(3) * D * t0 * (float(7) * (float(8) * q1 * q1 * r1 * slope1 + float(5) * D * t0 * (float(3) * D * t0 * (r1 * slope1 + J1 * D - r0 * slope0) + float(2) * q1 * r1 * slope1 - float(2) * r0 * slope0 * q0) - float(8) * r0 * slope0 * q0 * q0) * D * t0 + float(48) * t2 * r1 * slope1 - float(48) * r0 * slope0 * t4) + float(128) * t5 * r1 * slope1 - float(128) * r0 * slope0 * t6;
    float t8 = t6 * q0;
    float t9 = t5 * q1;
    F = (float(1) / float(1280)) * si.w[0] * t0 * t7 - (float(1) / float(14080)) * (float(1280) * r0 * t8 - float(1280) * t9 * r1 - float(11) * t0 * t7 * b) * t0 * si.w[1];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(9/2) dt
// Operations: 52 +, 135 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i9_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
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
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -ab_ap * inv_R2;
  float c = float(1) - ap_ap * inv_R2;
  float D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c - si.t0 * (b - slope0)));
  float r0 = sqrt(q0);
  float slope1 = a * si.t1 - b;
  float q1 = max(float(0), float(c - (b - slope1) * si.t1));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t1 = -slope1;
  float t2 = -slope0;
  float J1 = (atan(t1, r1 * root_minus_a) - atan(t2, r0 * root_minus_a)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t3 = float(1) / a;
    float t4 = q0 * q0;
    float t5 = t4 * t4;
    float t6 = q1 * q1;
    float t7 = t6 * q1;
    float t8 = t4 * q0;
    float t9 = float(7) * D * t3 * (float(5) * D * t3 * (float(2) * q1 * r1 * slope1 + float(3) * D * t3 * (D * J1 + r1 * slope1 - r0 * slope0) - float(2) * r0 * slope0 * q0) + float(8) * q1 * q1 * r1 * slope1 - float(8) * r0 * slope0 * t4) + float(48) * t7 * r1 * slope1 - float(48) * r0 * slope0 * t8;
    float t10 = t6 * t6;
    float t11 = float(128) * r0 * slope0 * t5 - float(3) * D * t3 * t9 - float(128) * t10 * r1 * slope1;
    float t12 = t5 * q0;
    float t13 = t10 * q1;
    F = -(float(1) / float(14080)) * t3 * (float(11) * t3 * b * t11 + float(1280) * r0 * t12 - float(1280) * t13 * r1) * si.w[1] - (float(1) / float(1280)) * si.w[0] * t3 * t11;
    G_ap = (float(1) / float(1152)) * (float(3) * t3 * t9 * b + float(128) * t10 * r1 - float(128) * r0 * t5) * t3 * si.w[1] + (float(1) / float(384)) * si.w[0] * t3 * t9;
    float t14 = t5 * r0;
    float t15 = t10 * r1;
    G_E = -(float(1) / float(11520)) * (float(1280) * (si.w[0] + si.t0 * si.w[1]) * t14 - float(1280) * (si.w[0] + si.w[1] * si.t1) * t15 - t3 * si.w[1] * t11) * t3;
  }
  float g_factor = -float(9) * inv_R2 * length;
  f = F * length;
  grad[0] = -(ab0 * G_E - G_ap * foot0) * g_factor;
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = (foot2 * G_ap - ab2 * G_E) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(9/2) dt
// Operations: 44 +, 112 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i9_w2_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  float ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ab2 * ap0 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - inv_R2 * ap_ap;
  float D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  float slope0 = si.t0 * a - b;
  float q0 = max(float(0), float(c - si.t0 * (b - slope0)));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float((slope1 - b) * si.t1 + c));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t0 = -slope0;
  float J1 = -(atan(t0, r0 * root_minus_a) - atan(-slope1, r1 * root_minus_a)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t1 = q1 * q1;
    float t2 = t1 * t1;
    float t3 = q0 * q0;
    float t4 = t3 * q0;
    float t5 = float(1) / a;
    float t6 = t1 * q1;
    float t7 = t3 * t3;
    float t8 = float(128) * slope1 * t2 * r1 - float(3) * (float(48) * r0 * slope0 * t4 + float(7) * (float(8) * r0 * slope0 * t3 + float(5) * (float(2) * r0 * slope0 * q0 - float(2) * slope1 * q1 * r1 - float(3) * (J1 * D + slope1 * r1 - r0 * slope0) * D * t5) * D * t5 - float(8) * slope1 * t1 * r1) * D * t5 - float(48) * slope1 * t6 * r1) * D * t5 - float(128) * r0 * slope0 * t7;
    float t9 = t2 * q1;
    float t10 = t7 * q0;
    float t11 = float(1280) * t9 * r1 + float(11) * b * t8 * t5 - float(1280) * r0 * t10;
    F = (float(1) / float(1280)) * si.w[0] * t8 * t5 + (float(1) / float(168960)) * si.w[2] * (float(11) * (float(1280) * slope1 * t9 * r1 + float(11) * D * t8 * t5 - float(1280) * r0 * slope0 * t10) * t5 + float(24) * b * t5 * t11 - float(132) * c * t8 * t5) * t5 + (float(1) / float(14080)) * si.w[1] * t5 * t11;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(9/2) dt
// Operations: 63 +, 173 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i9_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
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
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -inv_R2 * ab_ab;
  float b = -ab_ap * inv_R2;
  float c = float(1) - inv_R2 * ap_ap;
  float D = inv_R2 * (inv_R2 * cross_cross - ab_ab);
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c + (slope0 - b) * si.t0));
  float r0 = sqrt(q0);
  float slope1 = a * si.t1 - b;
  float q1 = max(float(0), float(c + (slope1 - b) * si.t1));
  float r1 = sqrt(q1);
  float root_minus_a = length * inv_R;
  float J1 = (atan(-slope1, root_minus_a * r1) - atan(-slope0, root_minus_a * r0)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t1 = float(1) / a;
    float t2 = q0 * q0;
    float t3 = t2 * t2;
    float t4 = q1 * q1;
    float t5 = t4 * t4;
    float t6 = t4 * q1;
    float t7 = t2 * q0;
    float t8 = float(7) * (float(5) * t1 * D * (float(2) * slope1 * q1 * r1 + float(3) * t1 * D * (D * J1 + slope1 * r1 - slope0 * r0) - float(2) * slope0 * q0 * r0) + float(8) * slope1 * t4 * r1 - float(8) * slope0 * t2 * r0) * t1 * D + float(48) * slope1 * t6 * r1 - float(48) * slope0 * t7 * r0;
    float t9 = float(128) * slope0 * t3 * r0 - float(128) * slope1 * t5 * r1 - float(3) * t8 * t1 * D;
    float t10 = t3 * q0;
    float t11 = t5 * q1;
    float t12 = float(11) * t1 * b * t9 + float(1280) * t10 * r0 - float(1280) * t11 * r1;
    F = -(float(1) / float(168960)) * (float(24) * t1 * b * t12 + float(11) * t1 * (float(1280) * slope0 * t10 * r0 + float(11) * t1 * D * t9 - float(1280) * slope1 * t11 * r1) - float(132) * c * t1 * t9) * t1 * si.w[2] - (float(1) / float(14080)) * si.w[1] * t1 * t12 - (float(1) / float(1280)) * t1 * t9 * si.w[0];
    float t13 = float(3) * t8 * t1 * b + float(128) * t5 * r1 - float(128) * t3 * r0;
    G_ap = (float(1) / float(384)) * t8 * t1 * si.w[0] + (float(1) / float(1152)) * t13 * si.w[1] * t1 - (float(1) / float(11520)) * (float(9) * t1 * t9 + float(30) * c * t8 * t1 - float(20) * t13 * t1 * b) * t1 * si.w[2];
    float t14 = t3 * r0;
    float t15 = t5 * r1;
    G_E = -(float(1) / float(126720)) * (float(14080) * (si.w[1] * si.t0 + si.w[2] * si.t0 * si.t0 + si.w[0]) * t14 - float(14080) * (si.w[2] * si.t1 * si.t1 + si.w[0] + si.w[1] * si.t1) * t15 - float(2) * t1 * si.w[2] * t12 - float(11) * si.w[1] * t1 * t9) * t1;
  }
  float g_factor = -float(9) * inv_R2 * length;
  f = length * F;
  grad[0] = -g_factor * (G_E * ab0 - G_ap * foot0);
  grad[1] = g_factor * (G_ap * foot1 - G_E * ab1);
  grad[2] = (foot2 * G_ap - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(9/2) dt
// Operations: 49 +, 132 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i9_w3_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  float ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ab2 * ap0 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -inv_R2 * ab_ab;
  float b = -ab_ap * inv_R2;
  float c = float(1) - inv_R2 * ap_ap;
  float D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  float slope0 = si.t0 * a - b;
  float q0 = max(float(0), float(c - (b - slope0) * si.t0));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c - si.t1 * (b - slope1)));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t0 = -slope1;
  float t1 = -slope0;
  float J1 = (atan(t0, r1 * root_minus_a) - atan(t1, r0 * root_minus_a)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t2 = q0 * q0;
    float t3 = t2 * t2;
    float t4 = q1 * q1;
    float t5 = t4 * t4;
    float t6 = float(1) / a;
    float t7 = t4 * q1;
    float t8 = t2 * q0;
    float t9 = float(128) * r0 * slope0 * t3 - float(128) * t5 * r1 * slope1 - float(3) * (float(7) * (float(8) * t4 * r1 * slope1 + float(5) * (float(3) * D * t6 * (r1 * slope1 + J1 * D - r0 * slope0) + float(2) * q1 * r1 * slope1 - float(2) * r0 * slope0 * q0) * D * t6 - float(8) * r0 * slope0 * t2) * D * t6 + float(48) * t7 * r1 * slope1 - float(48) * r0 * slope0 * t8) * D * t6;
    float t10 = t5 * q1;
    float t11 = t3 * q0;
    float t12 = float(1280) * t10 * r1 * slope1 - float(1280) * r0 * slope0 * t11 - float(11) * D * t9 * t6;
    float t13 = float(11) * b * t9 * t6 + float(1280) * r0 * t11 - float(1280) * t10 * r1;
    float t14 = float(132) * c * t9 * t6 + float(11) * t12 * t6 - float(24) * b * t13 * t6;
    float t15 = t8 * t8;
    float t16 = t7 * t7;
    F = (float(1) / float(168960)) * t14 * si.w[2] * t6 - (float(1) / float(2196480)) * (float(11) * (float(15360) * r0 * t15 - float(15360) * t16 * r1 - float(13) * b * t12 * t6) * t6 - float(156) * c * t13 * t6 - float(26) * b * t14 * t6) * t6 * si.w[3] - (float(1) / float(14080)) * si.w[1] * t13 * t6 - (float(1) / float(1280)) * t9 * t6 * si.w[0];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(9/2) dt
// Operations: 74 +, 212 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i9_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ap2 * ab1 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ap2 * ab0;
  float plain_cross2 = ap1 * ab0 - ap0 * ab1;
  float plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross0 * plain_cross0 + plain_cross1 * plain_cross1;
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
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -inv_R2 * ab_ab;
  float b = -ab_ap * inv_R2;
  float c = float(1) - inv_R2 * ap_ap;
  float D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c - si.t0 * (b - slope0)));
  float r0 = sqrt(q0);
  float slope1 = a * si.t1 - b;
  float q1 = max(float(0), float(c + (slope1 - b) * si.t1));
  float r1 = sqrt(q1);
  float root_minus_a = length * inv_R;
  float t1 = -slope0;
  float J1 = (atan(-slope1, root_minus_a * r1) - atan(t1, root_minus_a * r0)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t2 = float(1) / a;
    float t3 = q1 * q1;
    float t4 = t3 * q1;
    float t5 = q0 * q0;
    float t6 = t5 * q0;
    float t7 = float(48) * slope1 * t4 * r1 + float(7) * D * t2 * (float(5) * (float(2) * slope1 * q1 * r1 - float(2) * q0 * r0 * slope0 - float(3) * (r0 * slope0 - D * J1 - slope1 * r1) * D * t2) * D * t2 + float(8) * slope1 * t3 * r1 - float(8) * q0 * q0 * r0 * slope0) - float(48) * t6 * r0 * slope0;
    float t8 = t3 * t3;
    float t9 = t5 * t5;
    float t10 = float(3) * D * t2 * t7 + float(128) * slope1 * t8 * r1 - float(128) * t9 * r0 * slope0;
    float t11 = t8 * q1;
    float t12 = t9 * q0;
    float t13 = float(1280) * t11 * r1 + float(11) * t2 * b * t10 - float(1280) * t12 * r0;
    float t14 = float(1280) * t12 * r0 * slope0 - float(11) * D * t2 * t10 - float(1280) * slope1 * t11 * r1;
    float t15 = float(11) * t2 * t14 + float(132) * c * t2 * t10 - float(24) * t2 * t13 * b;
    float t16 = t6 * t6;
    float t17 = t4 * t4;
    F = (float(1) / float(1280)) * t2 * si.w[0] * t10 + (float(1) / float(14080)) * si.w[1] * t2 * t13 - (float(1) / float(168960)) * si.w[2] * t2 * t15 - (float(1) / float(2196480)) * (float(156) * c * t2 * t13 + float(26) * t2 * b * t15 + float(11) * (float(15360) * t16 * r0 + float(13) * t2 * b * t14 - float(15360) * t17 * r1) * t2) * t2 * si.w[3];
    float t18 = float(128) * t8 * r1 + float(3) * t2 * b * t7 - float(128) * t9 * r0;
    float t19 = float(9) * t2 * t10 + float(20) * t18 * t2 * b - float(30) * c * t2 * t7;
    G_ap = (float(1) / float(384)) * t2 * si.w[0] * t7 + (float(1) / float(1152)) * si.w[1] * t18 * t2 + (float(1) / float(11520)) * si.w[2] * t19 * t2 - (float(1) / float(126720)) * t2 * (float(110) * t18 * c * t2 - float(22) * t19 * t2 * b - float(9) * t2 * t13) * si.w[3];
    float t20 = t9 * r0;
    float t21 = si.t0 * si.t0;
    float t22 = t21 * si.t0;
    float t23 = t8 * r1;
    float t24 = si.t1 * si.t1;
    float t25 = t24 * si.t1;
    G_E = -(float(1) / float(506880)) * t2 * (float(56320) * t20 * (si.w[1] * si.t0 + si.w[2] * si.t0 * si.t0 + si.w[3] * t22 + si.w[0]) + float(44) * si.w[1] * t2 * t10 + float(8) * si.w[2] * t2 * t13 - t2 * si.w[3] * t15 - float(56320) * t23 * (si.w[3] * t25 + si.w[0] + si.w[1] * si.t1 + si.w[2] * t24));
  }
  float g_factor = -float(9) * inv_R2 * length;
  f = length * F;
  grad[0] = -g_factor * (G_E * ab0 - G_ap * foot0);
  grad[1] = (G_ap * foot1 - G_E * ab1) * g_factor;
  grad[2] = g_factor * (G_ap * foot2 - G_E * ab2);
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(11/2) dt
// Operations: 38 +, 92 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i11_w0_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
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
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -inv_R2 * ab_ab;
  float b = -ab_ap * inv_R2;
  float c = float(1) - inv_R2 * ap_ap;
  float D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  float slope0 = si.t0 * a - b;
  float q0 = max(float(0), float(c + (slope0 - b) * si.t0));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c + si.t1 * (slope1 - b)));
  float r1 = sqrt(q1);
  float root_minus_a = length * inv_R;
  float J1 = -(atan(-slope0, r0 * root_minus_a) - atan(-slope1, r1 * root_minus_a)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t0 = float(1) / a;
    float t1 = q0 * q0;
    float t2 = t1 * t1;
    float t3 = t1 * q0;
    float t4 = q1 * q1;
    float t5 = t4 * q1;
    float t6 = t4 * t4;
    float t7 = t2 * q0;
    float t8 = t6 * q1;
    F = -(float(1) / float(15360)) * (float(11) * D * t0 * (float(128) * r0 * slope0 * t2 + float(3) * (float(7) * (float(8) * r0 * slope0 * t1 - float(8) * r1 * slope1 * q1 * q1 - float(5) * (float(2) * r1 * slope1 * q1 + float(3) * D * t0 * (J1 * D + r1 * slope1 - r0 * slope0) - float(2) * r0 * slope0 * q0) * D * t0) * D * t0 + float(48) * r0 * slope0 * t3 - float(48) * r1 * slope1 * t5) * D * t0 - float(128) * r1 * slope1 * t6) + float(1280) * r0 * slope0 * t7 - float(1280) * r1 * slope1 * t8) * t0 * si.w[0];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(11/2) dt
// Operations: 45 +, 117 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i11_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
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
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -ab_ap * inv_R2;
  float c = float(1) - inv_R2 * ap_ap;
  float D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c - (b - slope0) * si.t0));
  float r0 = sqrt(q0);
  float slope1 = a * si.t1 - b;
  float q1 = max(float(0), float(c - (b - slope1) * si.t1));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t1 = -slope0;
  float t2 = -slope1;
  float J1 = -(atan(t1, root_minus_a * r0) - atan(t2, root_minus_a * r1)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t3 = q1 * q1;
    float t4 = t3 * q1;
    float t5 = q0 * q0;
    float t6 = t5 * q0;
    float t7 = float(1) / a;
    float t8 = t3 * t3;
    float t9 = t5 * t5;
    float t10 = float(3) * (float(48) * slope1 * t4 * r1 - float(48) * slope0 * t6 * r0 - float(7) * (float(8) * slope0 * t5 * r0 - float(5) * (float(2) * slope1 * q1 * r1 + float(3) * (J1 * D + slope1 * r1 - slope0 * r0) * D * t7 - float(2) * slope0 * q0 * r0) * D * t7 - float(8) * slope1 * t3 * r1) * D * t7) * D * t7 + float(128) * slope1 * t8 * r1 - float(128) * slope0 * t9 * r0;
    float t11 = t8 * q1;
    float t12 = t9 * q0;
    F = (float(1) / float(15360)) * si.w[0] * (float(11) * t10 * D * t7 + float(1280) * slope1 * t11 * r1 - float(1280) * slope0 * t12 * r0) * t7;
    G_ap = (float(1) / float(1280)) * si.w[0] * t10 * t7;
    float t13 = t12 * r0;
    float t14 = t11 * r1;
    G_E = -(float(1) / float(11)) * (si.w[0] * t13 - si.w[0] * t14) * t7;
  }
  float g_factor = -float(11) * inv_R2 * length;
  f = F * length;
  grad[0] = -(ab0 * G_E - G_ap * foot0) * g_factor;
  grad[1] = -(ab1 * G_E - G_ap * foot1) * g_factor;
  grad[2] = -(ab2 * G_E - foot2 * G_ap) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(11/2) dt
// Operations: 41 +, 103 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i11_w1_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  float ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ap2 * ab1 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ap0 * ab1;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -inv_R2 * ab_ab;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - inv_R2 * ap_ap;
  float D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  float slope0 = si.t0 * a - b;
  float q0 = max(float(0), float(si.t0 * (slope0 - b) + c));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c + (slope1 - b) * si.t1));
  float r1 = sqrt(q1);
  float root_minus_a = length * inv_R;
  float J1 = -(atan(-slope0, r0 * root_minus_a) - atan(-slope1, r1 * root_minus_a)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t0 = q1 * q1;
    float t1 = t0 * q1;
    float t2 = t1 * t1;
    float t3 = q0 * q0;
    float t4 = t3 * t3;
    float t5 = t4 * q0;
    float t6 = float(1) / a;
    float t7 = t3 * q0;
    float t8 = t0 * t0;
    float t9 = t8 * q1;
    float t10 = float(1280) * r0 * slope0 * t5 - float(11) * (float(3) * D * t6 * (float(7) * (float(5) * D * t6 * (float(3) * (r1 * slope1 + D * J1 - r0 * slope0) * D * t6 + float(2) * r1 * slope1 * q1 - float(2) * r0 * slope0 * q0) + float(8) * r1 * slope1 * t0 - float(8) * r0 * slope0 * t3) * D * t6 + float(48) * r1 * slope1 * t1 - float(48) * r0 * slope0 * t7) + float(128) * r1 * slope1 * t8 - float(128) * r0 * slope0 * t4) * D * t6 - float(1280) * r1 * slope1 * t9;
    float t11 = t7 * t7;
    F = (float(1) / float(199680)) * (float(15360) * r1 * t2 - float(13) * t10 * t6 * b - float(15360) * r0 * t11) * t6 * si.w[1] - (float(1) / float(15360)) * t10 * si.w[0] * t6;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(11/2) dt
// Operations: 54 +, 145 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i11_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  float ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
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
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -ab_ap * inv_R2;
  float c = float(1) - ap_ap * inv_R2;
  float D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c - si.t0 * (b - slope0)));
  float r0 = sqrt(q0);
  float slope1 = a * si.t1 - b;
  float q1 = max(float(0), float(c - si.t1 * (b - slope1)));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t1 = -slope0;
  float t2 = -slope1;
  float J1 = -(atan(t1, r0 * root_minus_a) - atan(t2, r1 * root_minus_a)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t3 = float(1) / a;
    float t4 = q1 * q1;
    float t5 = t4 * t4;
    float t6 = t5 * q1;
    float t7 = q0 * q0;
    float t8 = t7 * t7;
    float t9 = t8 * q0;
    float t10 = t4 * q1;
    float t11 = t7 * q0;
    float t12 = float(128) * r0 * slope0 * t8 - float(128) * t5 * r1 * slope1 - float(3) * t3 * (float(48) * t10 * r1 * slope1 + float(7) * t3 * (float(8) * t4 * r1 * slope1 + float(5) * (float(3) * t3 * (r1 * slope1 + J1 * D - r0 * slope0) * D + float(2) * q1 * r1 * slope1 - float(2) * r0 * slope0 * q0) * t3 * D - float(8) * r0 * slope0 * t7) * D - float(48) * r0 * slope0 * t11) * D;
    float t13 = float(1280) * t6 * r1 * slope1 - float(1280) * r0 * slope0 * t9 - float(11) * t3 * t12 * D;
    float t14 = t11 * t11;
    float t15 = t10 * t10;
    F = (float(1) / float(15360)) * t3 * t13 * si.w[0] - (float(1) / float(199680)) * t3 * si.w[1] * (float(15360) * r0 * t14 - float(15360) * t15 * r1 - float(13) * t3 * b * t13);
    G_ap = -(float(1) / float(14080)) * t3 * si.w[1] * (float(1280) * r0 * t9 + float(11) * t3 * b * t12 - float(1280) * t6 * r1) - (float(1) / float(1280)) * t3 * t12 * si.w[0];
    float t16 = t9 * r0;
    float t17 = t6 * r1;
    G_E = -(float(1) / float(168960)) * (float(15360) * t16 * (si.w[1] * si.t0 + si.w[0]) + t3 * si.w[1] * t13 - float(15360) * t17 * (si.w[1] * si.t1 + si.w[0])) * t3;
  }
  float g_factor = -float(11) * length * inv_R2;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_E - G_ap * foot0);
  grad[1] = -(ab1 * G_E - foot1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_E - foot2 * G_ap) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(11/2) dt
// Operations: 46 +, 123 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i11_w2_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab1 * ap1 + ap0 * ab0 + ab2 * ap2;
  float ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ap0 * ab1;
  float plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -ab_ap * inv_R2;
  float c = float(1) - ap_ap * inv_R2;
  float D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float((slope0 - b) * si.t0 + c));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(si.t1 * (slope1 - b) + c));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float J1 = (atan(-slope1, root_minus_a * r1) - atan(-slope0, root_minus_a * r0)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t0 = q1 * q1;
    float t1 = t0 * q1;
    float t2 = t1 * t1;
    float t3 = float(1) / a;
    float t4 = q0 * q0;
    float t5 = t4 * t4;
    float t6 = t5 * q0;
    float t7 = t4 * q0;
    float t8 = t0 * t0;
    float t9 = t8 * q1;
    float t10 = float(1280) * slope0 * t6 * r0 + float(11) * D * t3 * (float(128) * slope0 * t5 * r0 - float(3) * D * t3 * (float(48) * slope1 * t1 * r1 + float(7) * D * t3 * (float(8) * slope1 * t0 * r1 - float(5) * D * t3 * (float(2) * slope0 * q0 * r0 + float(3) * (slope0 * r0 - slope1 * r1 - D * J1) * D * t3 - float(2) * slope1 * q1 * r1) - float(8) * slope0 * t4 * r0) - float(48) * slope0 * t7 * r0) - float(128) * slope1 * t8 * r1) - float(1280) * slope1 * t9 * r1;
    float t11 = t7 * t7;
    float t12 = float(15360) * t2 * r1 - float(13) * t3 * t10 * b - float(15360) * t11 * r0;
    F = (float(1) / float(199680)) * t12 * si.w[1] * t3 + (float(1) / float(2795520)) * t3 * si.w[2] * (float(28) * t12 * t3 * b + float(182) * t3 * t10 * c - float(13) * t3 * (float(13) * D * t3 * t10 + float(15360) * slope0 * t11 * r0 - float(15360) * slope1 * t2 * r1)) - (float(1) / float(15360)) * t3 * t10 * si.w[0];
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(11/2) dt
// Operations: 65 +, 185 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i11_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  float ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
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
    foot2 = ap2 - ab2 * t0 * ab_ap;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - inv_R2 * ap_ap;
  float D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  float slope0 = si.t0 * a - b;
  float q0 = max(float(0), float(c - si.t0 * (b - slope0)));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c - si.t1 * (b - slope1)));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t1 = -slope0;
  float t2 = -slope1;
  float J1 = -(atan(t1, r0 * root_minus_a) - atan(t2, r1 * root_minus_a)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t3 = float(1) / a;
    float t4 = q1 * q1;
    float t5 = t4 * q1;
    float t6 = q0 * q0;
    float t7 = t6 * q0;
    float t8 = t4 * t4;
    float t9 = t6 * t6;
    float t10 = float(3) * (float(48) * r1 * slope1 * t5 + float(7) * (float(5) * D * t3 * (float(3) * (r1 * slope1 + D * J1 - r0 * slope0) * D * t3 + float(2) * r1 * slope1 * q1 - float(2) * r0 * slope0 * q0) + float(8) * r1 * slope1 * t4 - float(8) * r0 * slope0 * q0 * q0) * D * t3 - float(48) * r0 * slope0 * t7) * D * t3 + float(128) * r1 * slope1 * t8 - float(128) * r0 * slope0 * t9;
    float t11 = t8 * q1;
    float t12 = t9 * q0;
    float t13 = float(11) * D * t3 * t10 + float(1280) * r1 * slope1 * t11 - float(1280) * r0 * slope0 * t12;
    float t14 = t5 * t5;
    float t15 = t7 * t7;
    float t16 = float(15360) * r1 * t14 + float(13) * b * t13 * t3 - float(15360) * r0 * t15;
    F = (float(1) / float(15360)) * si.w[0] * t13 * t3 + (float(1) / float(199680)) * t16 * si.w[1] * t3 - (float(1) / float(2795520)) * si.w[2] * (float(13) * (float(15360) * r0 * slope0 * t15 - float(13) * t13 * D * t3 - float(15360) * r1 * slope1 * t14) * t3 + float(182) * c * t13 * t3 - float(28) * b * t16 * t3) * t3;
    float t17 = float(1280) * r1 * t11 + float(11) * b * t3 * t10 - float(1280) * r0 * t12;
    G_ap = (float(1) / float(168960)) * si.w[2] * (float(24) * b * t17 * t3 + float(11) * t13 * t3 - float(132) * c * t3 * t10) * t3 + (float(1) / float(14080)) * t17 * si.w[1] * t3 + (float(1) / float(1280)) * si.w[0] * t3 * t10;
    float t18 = t12 * r0;
    float t19 = t11 * r1;
    G_E = -(float(1) / float(2196480)) * (float(2) * si.w[2] * t16 * t3 + float(199680) * t18 * (si.w[2] * si.t0 * si.t0 + si.w[0] + si.t0 * si.w[1]) + float(13) * t13 * si.w[1] * t3 - float(199680) * t19 * (si.w[0] + si.w[2] * si.t1 * si.t1 + si.t1 * si.w[1])) * t3;
  }
  float g_factor = -float(11) * inv_R2 * length;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_E - G_ap * foot0);
  grad[1] = -g_factor * (ab1 * G_E - foot1 * G_ap);
  grad[2] = g_factor * (foot2 * G_ap - ab2 * G_E);
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(11/2) dt
// Operations: 51 +, 142 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i11_w3_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  float ab_ap = ap2 * ab2 + ab0 * ap0 + ap1 * ab1;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ap2 * ab1 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ap0 * ab1;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -inv_R2 * ab_ab;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - inv_R2 * ap_ap;
  float D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  float slope0 = si.t0 * a - b;
  float q0 = max(float(0), float(c + si.t0 * (slope0 - b)));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c + (slope1 - b) * si.t1));
  float r1 = sqrt(q1);
  float root_minus_a = length * inv_R;
  float J1 = (atan(-slope1, r1 * root_minus_a) - atan(-slope0, r0 * root_minus_a)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t0 = float(1) / a;
    float t1 = q1 * q1;
    float t2 = t1 * q1;
    float t3 = t2 * t2;
    float t4 = t3 * q1;
    float t5 = q0 * q0;
    float t6 = t5 * q0;
    float t7 = t6 * t6;
    float t8 = t5 * t5;
    float t9 = t1 * t1;
    float t10 = t8 * q0;
    float t11 = t9 * q1;
    float t12 = float(11) * t0 * D * (float(128) * r0 * slope0 * t8 - float(3) * (float(7) * t0 * D * (float(8) * r1 * slope1 * t1 + float(5) * (float(2) * r1 * slope1 * q1 + float(3) * (D * J1 + r1 * slope1 - r0 * slope0) * t0 * D - float(2) * r0 * slope0 * q0) * t0 * D - float(8) * r0 * slope0 * t5) + float(48) * r1 * slope1 * t2 - float(48) * r0 * slope0 * t6) * t0 * D - float(128) * r1 * slope1 * t9) + float(1280) * r0 * slope0 * t10 - float(1280) * r1 * slope1 * t11;
    float t13 = float(15360) * r0 * slope0 * t7 + float(13) * t0 * D * t12 - float(15360) * r1 * slope1 * t3;
    float t14 = t7 * q0;
    float t15 = float(15360) * r1 * t3 - float(15360) * r0 * t7 - float(13) * t0 * b * t12;
    float t16 = float(13) * t13 * t0 - float(182) * c * t0 * t12 - float(28) * t15 * t0 * b;
    F = (float(1) / float(2795520)) * t0 * (float(13) * t0 * (float(14336) * r1 * t4 - t13 * t0 * b - float(14336) * r0 * t14) - float(14) * t15 * c * t0 - float(2) * t0 * t16 * b) * si.w[3] + (float(1) / float(199680)) * si.w[1] * t15 * t0 - (float(1) / float(15360)) * t0 * si.w[0] * t12 - (float(1) / float(2795520)) * si.w[2] * t0 * t16;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(11/2) dt
// Operations: 76 +, 223 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i11_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ap2 * ab1 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ap2 * ab0;
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
    foot2 = ap2 - ab_ap * t0 * ab2;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -ab_ap * inv_R2;
  float c = float(1) - ap_ap * inv_R2;
  float D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c - (b - slope0) * si.t0));
  float r0 = sqrt(q0);
  float slope1 = a * si.t1 - b;
  float q1 = max(float(0), float((slope1 - b) * si.t1 + c));
  float r1 = sqrt(q1);
  float root_minus_a = length * inv_R;
  float t1 = -slope0;
  float J1 = -(atan(t1, r0 * root_minus_a) - atan(-slope1, r1 * root_minus_a)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t2 = float(1) / a;
    float t3 = q1 * q1;
    float t4 = t3 * t3;
    float t5 = t4 * q1;
    float t6 = t3 * q1;
    float t7 = q0 * q0;
    float t8 = t7 * q0;
    float t9 = t7 * t7;
    float t10 = float(128) * slope1 * t4 * r1 + float(3) * (float(7) * D * t2 * (float(5) * D * t2 * (float(2) * slope1 * q1 * r1 + float(3) * D * (slope1 * r1 + D * J1 - r0 * slope0) * t2 - float(2) * q0 * r0 * slope0) + float(8) * slope1 * t3 * r1 - float(8) * q0 * q0 * r0 * slope0) + float(48) * slope1 * t6 * r1 - float(48) * t8 * r0 * slope0) * D * t2 - float(128) * t9 * r0 * slope0;
    float t11 = t9 * q0;
    float t12 = float(1280) * slope1 * t5 * r1 + float(11) * D * t2 * t10 - float(1280) * t11 * r0 * slope0;
    float t13 = t6 * t6;
    float t14 = t8 * t8;
    float t15 = float(15360) * t13 * r1 + float(13) * t2 * b * t12 - float(15360) * t14 * r0;
    float t16 = t13 * q1;
    float t17 = float(15360) * slope1 * t13 * r1 + float(13) * D * t2 * t12 - float(15360) * t14 * r0 * slope0;
    float t18 = t14 * q0;
    float t19 = float(182) * t2 * t12 * c - float(28) * t2 * t15 * b - float(13) * t2 * t17;
    F = (float(1) / float(15360)) * t2 * si.w[0] * t12 + (float(1) / float(199680)) * t2 * t15 * si.w[1] + (float(1) / float(2795520)) * (float(13) * t2 * (float(14336) * t16 * r1 + t2 * t17 * b - float(14336) * t18 * r0) - float(14) * t2 * t15 * c - float(2) * t2 * b * t19) * t2 * si.w[3] - (float(1) / float(2795520)) * si.w[2] * t2 * t19;
    float t20 = float(1280) * t11 * r0 - float(1280) * t5 * r1 - float(11) * t2 * b * t10;
    float t21 = float(11) * t2 * t12 - float(132) * t2 * c * t10 - float(24) * t2 * t20 * b;
    G_ap = (float(1) / float(1280)) * t2 * si.w[0] * t10 + (float(1) / float(2196480)) * t2 * si.w[3] * (float(156) * t2 * t20 * c + float(26) * t21 * t2 * b + float(11) * t2 * t15) + (float(1) / float(168960)) * t21 * si.w[2] * t2 - (float(1) / float(14080)) * t2 * t20 * si.w[1];
    float t22 = si.t0 * si.t0;
    float t23 = t22 * si.t0;
    float t24 = t11 * r0;
    float t25 = t5 * r1;
    float t26 = si.t1 * si.t1;
    float t27 = t26 * si.t1;
    G_E = -(float(1) / float(30750720)) * t2 * (float(28) * si.w[2] * t2 * t15 + float(182) * t2 * t12 * si.w[1] + float(2795520) * (si.w[3] * t23 + si.w[2] * t22 + si.w[0] + si.t0 * si.w[1]) * t24 - float(3) * t2 * si.w[3] * t19 - float(2795520) * t25 * (si.w[2] * si.t1 * si.t1 + si.w[0] + si.w[3] * t27 + si.t1 * si.w[1]));
  }
  float g_factor = -float(11) * length * inv_R2;
  f = length * F;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = -g_factor * (G_E * ab1 - foot1 * G_ap);
  grad[2] = -g_factor * (G_E * ab2 - foot2 * G_ap);
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(13/2) dt
// Operations: 40 +, 103 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i13_w0_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  float ab_ap = ap2 * ab2 + ab1 * ap1 + ab0 * ap0;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ab1 * ap2 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -inv_R2 * ab_ab;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - inv_R2 * ap_ap;
  float D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  float slope0 = si.t0 * a - b;
  float q0 = max(float(0), float(si.t0 * (slope0 - b) + c));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float((slope1 - b) * si.t1 + c));
  float r1 = sqrt(q1);
  float root_minus_a = length * inv_R;
  float J1 = (atan(-slope1, r1 * root_minus_a) - atan(-slope0, r0 * root_minus_a)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t0 = float(1) / a;
    float t1 = q0 * q0;
    float t2 = t1 * q0;
    float t3 = t2 * t2;
    float t4 = t1 * t1;
    float t5 = t4 * q0;
    float t6 = q1 * q1;
    float t7 = t6 * q1;
    float t8 = t6 * t6;
    float t9 = t8 * q1;
    float t10 = t7 * t7;
    F = -(float(1) / float(215040)) * t0 * si.w[0] * (float(15360) * r0 * slope0 * t3 + float(13) * t0 * D * (float(1280) * r0 * slope0 * t5 + float(11) * t0 * D * (float(128) * r0 * slope0 * t4 - float(3) * t0 * D * (float(7) * (float(8) * r1 * slope1 * q1 * q1 + float(5) * (float(2) * r1 * slope1 * q1 + float(3) * t0 * (D * J1 + r1 * slope1 - r0 * slope0) * D - float(2) * r0 * slope0 * q0) * t0 * D - float(8) * r0 * slope0 * t1) * t0 * D + float(48) * r1 * slope1 * t7 - float(48) * r0 * slope0 * t2) - float(128) * r1 * slope1 * t8) - float(1280) * r1 * slope1 * t9) - float(15360) * r1 * slope1 * t10);
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(13/2) dt
// Operations: 47 +, 129 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i13_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
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
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -ab_ap * inv_R2;
  float c = float(1) - inv_R2 * ap_ap;
  float D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  float slope0 = si.t0 * a - b;
  float q0 = max(float(0), float(c - si.t0 * (b - slope0)));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c - si.t1 * (b - slope1)));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t1 = -slope1;
  float t2 = -slope0;
  float J1 = (atan(t1, r1 * root_minus_a) - atan(t2, root_minus_a * r0)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t3 = q1 * q1;
    float t4 = t3 * q1;
    float t5 = float(1) / a;
    float t6 = q0 * q0;
    float t7 = t6 * q0;
    float t8 = t3 * t3;
    float t9 = t6 * t6;
    float t10 = t8 * q1;
    float t11 = t9 * q0;
    float t12 = float(11) * (float(3) * (float(48) * r1 * slope1 * t4 - float(7) * (float(8) * slope0 * q0 * q0 * r0 - float(8) * r1 * slope1 * t3 - float(5) * (float(2) * r1 * slope1 * q1 + float(3) * (D * J1 + r1 * slope1 - slope0 * r0) * D * t5 - float(2) * slope0 * q0 * r0) * D * t5) * D * t5 - float(48) * slope0 * t7 * r0) * D * t5 + float(128) * r1 * slope1 * t8 - float(128) * slope0 * t9 * r0) * D * t5 + float(1280) * r1 * slope1 * t10 - float(1280) * slope0 * t11 * r0;
    float t13 = t4 * t4;
    float t14 = t7 * t7;
    F = (float(1) / float(215040)) * (float(13) * t12 * D * t5 + float(15360) * r1 * slope1 * t13 - float(15360) * slope0 * t14 * r0) * t5 * si.w[0];
    G_ap = (float(1) / float(15360)) * t12 * t5 * si.w[0];
    float t15 = t14 * r0;
    float t16 = t13 * r1;
    G_E = -(float(1) / float(13)) * (si.w[0] * t15 - t16 * si.w[0]) * t5;
  }
  float g_factor = -float(13) * length * inv_R2;
  f = F * length;
  grad[0] = (G_ap * foot0 - ab0 * G_E) * g_factor;
  grad[1] = -g_factor * (ab1 * G_E - foot1 * G_ap);
  grad[2] = (foot2 * G_ap - ab2 * G_E) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(13/2) dt
// Operations: 43 +, 113 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i13_w1_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ab2 * ap0 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - inv_R2 * ap_ap;
  float D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c - (b - slope0) * si.t0));
  float r0 = sqrt(q0);
  float slope1 = a * si.t1 - b;
  float q1 = max(float(0), float((slope1 - b) * si.t1 + c));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t0 = -slope0;
  float J1 = -(atan(t0, root_minus_a * r0) - atan(-slope1, root_minus_a * r1)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t1 = float(1) / a;
    float t2 = q1 * q1;
    float t3 = t2 * q1;
    float t4 = t3 * t3;
    float t5 = t4 * q1;
    float t6 = q0 * q0;
    float t7 = t6 * q0;
    float t8 = t7 * t7;
    float t9 = t2 * t2;
    float t10 = t6 * t6;
    float t11 = t9 * q1;
    float t12 = t10 * q0;
    float t13 = float(15360) * t8 * r0 * slope0 - float(13) * D * t1 * (float(11) * D * t1 * (float(128) * slope1 * t9 * r1 - float(128) * t10 * r0 * slope0 - float(3) * D * t1 * (float(48) * t7 * r0 * slope0 - float(48) * slope1 * t3 * r1 - float(7) * D * t1 * (float(8) * slope1 * t2 * r1 - float(8) * t6 * r0 * slope0 - float(5) * D * t1 * (float(2) * q0 * r0 * slope0 - float(2) * slope1 * q1 * r1 - float(3) * D * t1 * (slope1 * r1 + D * J1 - r0 * slope0))))) + float(1280) * slope1 * t11 * r1 - float(1280) * t12 * r0 * slope0) - float(15360) * slope1 * t4 * r1;
    float t14 = t8 * q0;
    F = (float(1) / float(215040)) * t1 * si.w[1] * (float(14336) * t5 * r1 - t1 * b * t13 - float(14336) * t14 * r0) - (float(1) / float(215040)) * t1 * si.w[0] * t13;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(13/2) dt
// Operations: 56 +, 155 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i13_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  float ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
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
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -inv_R2 * ab_ab;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - inv_R2 * ap_ap;
  float D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c - (b - slope0) * si.t0));
  float r0 = sqrt(q0);
  float slope1 = a * si.t1 - b;
  float q1 = max(float(0), float((slope1 - b) * si.t1 + c));
  float r1 = sqrt(q1);
  float root_minus_a = length * inv_R;
  float t1 = -slope0;
  float J1 = -(atan(t1, root_minus_a * r0) - atan(-slope1, root_minus_a * r1)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t2 = q1 * q1;
    float t3 = t2 * t2;
    float t4 = q0 * q0;
    float t5 = t4 * q0;
    float t6 = float(1) / a;
    float t7 = t2 * q1;
    float t8 = t4 * t4;
    float t9 = t3 * q1;
    float t10 = t8 * q0;
    float t11 = float(11) * (float(128) * slope1 * t3 * r1 - float(3) * (float(48) * t5 * r0 * slope0 + float(7) * (float(8) * t4 * r0 * slope0 - float(8) * slope1 * t2 * r1 - float(5) * (float(2) * slope1 * q1 * r1 + float(3) * t6 * D * (D * J1 + slope1 * r1 - r0 * slope0) - float(2) * q0 * r0 * slope0) * t6 * D) * t6 * D - float(48) * slope1 * t7 * r1) * t6 * D - float(128) * t8 * r0 * slope0) * t6 * D + float(1280) * slope1 * t9 * r1 - float(1280) * t10 * r0 * slope0;
    float t12 = t7 * t7;
    float t13 = t5 * t5;
    float t14 = float(13) * t11 * t6 * D + float(15360) * slope1 * t12 * r1 - float(15360) * t13 * r0 * slope0;
    float t15 = t13 * q0;
    float t16 = t12 * q1;
    F = (float(1) / float(215040)) * si.w[0] * t14 * t6 - (float(1) / float(215040)) * t6 * si.w[1] * (float(14336) * t15 * r0 - t14 * t6 * b - float(14336) * t16 * r1);
    G_ap = (float(1) / float(15360)) * t11 * si.w[0] * t6 - (float(1) / float(199680)) * t6 * si.w[1] * (float(15360) * t13 * r0 - float(13) * t11 * t6 * b - float(15360) * t12 * r1);
    float t17 = t13 * r0;
    float t18 = t12 * r1;
    G_E = -(float(1) / float(2795520)) * t6 * (float(215040) * (si.w[0] + si.w[1] * si.t0) * t17 + t14 * t6 * si.w[1] - float(215040) * (si.w[0] + si.w[1] * si.t1) * t18);
  }
  float g_factor = -float(13) * inv_R2 * length;
  f = length * F;
  grad[0] = -g_factor * (G_E * ab0 - G_ap * foot0);
  grad[1] = g_factor * (G_ap * foot1 - G_E * ab1);
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(13/2) dt
// Operations: 48 +, 133 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i13_w2_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  float ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ab1 * ap2 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -inv_R2 * ab_ab;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - inv_R2 * ap_ap;
  float D = inv_R2 * (cross_cross * inv_R2 - ab_ab);
  float slope0 = si.t0 * a - b;
  float q0 = max(float(0), float(c + si.t0 * (slope0 - b)));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c + (slope1 - b) * si.t1));
  float r1 = sqrt(q1);
  float root_minus_a = length * inv_R;
  float J1 = (atan(-slope1, r1 * root_minus_a) - atan(-slope0, r0 * root_minus_a)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t0 = float(1) / a;
    float t1 = q0 * q0;
    float t2 = t1 * q0;
    float t3 = t2 * t2;
    float t4 = t3 * q0;
    float t5 = t1 * t1;
    float t6 = t5 * q0;
    float t7 = q1 * q1;
    float t8 = t7 * q1;
    float t9 = t7 * t7;
    float t10 = t9 * q1;
    float t11 = t8 * t8;
    float t12 = float(15360) * r0 * slope0 * t3 + float(13) * (float(1280) * r0 * slope0 * t6 + float(11) * t0 * D * (float(128) * r0 * slope0 * t5 - float(3) * t0 * D * (float(7) * (float(5) * (float(2) * q1 * r1 * slope1 + float(3) * t0 * (r1 * slope1 + D * J1 - r0 * slope0) * D - float(2) * r0 * slope0 * q0) * t0 * D + float(8) * q1 * q1 * r1 * slope1 - float(8) * r0 * slope0 * t1) * t0 * D + float(48) * t8 * r1 * slope1 - float(48) * r0 * slope0 * t2) - float(128) * t9 * r1 * slope1) - float(1280) * t10 * r1 * slope1) * t0 * D - float(15360) * t11 * r1 * slope1;
    float t13 = t11 * q1;
    float t14 = float(14336) * r0 * t4 + t12 * t0 * b - float(14336) * t13 * r1;
    F = -(float(1) / float(215040)) * si.w[1] * t0 * t14 - (float(1) / float(215040)) * si.w[0] * t12 * t0 - (float(1) / float(3440640)) * t0 * (float(32) * t0 * t14 * b + float(15) * (float(14336) * r0 * slope0 * t4 + t12 * t0 * D - float(14336) * t13 * r1 * slope1) * t0 - float(16) * c * t12 * t0) * si.w[2];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(13/2) dt
// Operations: 67 +, 193 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i13_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
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
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -ab_ap * inv_R2;
  float c = float(1) - ap_ap * inv_R2;
  float D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c - (b - slope0) * si.t0));
  float r0 = sqrt(q0);
  float slope1 = a * si.t1 - b;
  float q1 = max(float(0), float(c + (slope1 - b) * si.t1));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t1 = -slope0;
  float J1 = -(atan(t1, r0 * root_minus_a) - atan(-slope1, r1 * root_minus_a)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t2 = float(1) / a;
    float t3 = q1 * q1;
    float t4 = t3 * q1;
    float t5 = t4 * t4;
    float t6 = q0 * q0;
    float t7 = t6 * q0;
    float t8 = t3 * t3;
    float t9 = t6 * t6;
    float t10 = t8 * q1;
    float t11 = t9 * q0;
    float t12 = float(11) * D * t2 * (float(3) * D * t2 * (float(7) * D * t2 * (float(5) * D * t2 * (float(2) * slope1 * q1 * r1 + float(3) * D * t2 * (D * J1 + slope1 * r1 - r0 * slope0) - float(2) * q0 * r0 * slope0) + float(8) * slope1 * t3 * r1 - float(8) * q0 * q0 * r0 * slope0) + float(48) * slope1 * t4 * r1 - float(48) * t7 * r0 * slope0) + float(128) * slope1 * t8 * r1 - float(128) * t9 * r0 * slope0) + float(1280) * slope1 * t10 * r1 - float(1280) * t11 * r0 * slope0;
    float t13 = t7 * t7;
    float t14 = float(15360) * slope1 * t5 * r1 + float(13) * D * t2 * t12 - float(15360) * t13 * r0 * slope0;
    float t15 = t5 * q1;
    float t16 = t13 * q0;
    float t17 = t2 * b * t14 + float(14336) * t15 * r1 - float(14336) * t16 * r0;
    F = (float(1) / float(215040)) * si.w[1] * t2 * t17 + (float(1) / float(3440640)) * (float(32) * t2 * b * t17 + float(15) * (float(14336) * slope1 * t15 * r1 + D * t2 * t14 - float(14336) * t16 * r0 * slope0) * t2 - float(16) * t2 * t14 * c) * t2 * si.w[2] + (float(1) / float(215040)) * t2 * t14 * si.w[0];
    float t18 = float(13) * t2 * t12 * b + float(15360) * t5 * r1 - float(15360) * t13 * r0;
    G_ap = (float(1) / float(199680)) * si.w[1] * t2 * t18 + (float(1) / float(15360)) * t2 * t12 * si.w[0] - (float(1) / float(2795520)) * t2 * si.w[2] * (float(182) * t2 * t12 * c - float(28) * t2 * b * t18 - float(13) * t2 * t14);
    float t19 = t13 * r0;
    float t20 = t5 * r1;
    G_E = -(float(1) / float(2795520)) * (float(215040) * (si.w[1] * si.t0 + si.t0 * si.t0 * si.w[2] + si.w[0]) * t19 + si.w[1] * t2 * t14 + float(2) * t2 * si.w[2] * t17 - float(215040) * (si.w[1] * si.t1 + si.w[2] * si.t1 * si.t1 + si.w[0]) * t20) * t2;
  }
  float g_factor = -float(13) * inv_R2 * length;
  f = F * length;
  grad[0] = (foot0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = (foot1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = -(G_E * ab2 - foot2 * G_ap) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(13/2) dt
// Operations: 53 +, 153 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i13_w3_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  float ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  float plain_cross0 = ap2 * ab1 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ap2 * ab0;
  float plain_cross2 = ap1 * ab0 - ap0 * ab1;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -inv_R2 * ab_ab;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - inv_R2 * ap_ap;
  float D = inv_R2 * (inv_R2 * cross_cross - ab_ab);
  float slope0 = si.t0 * a - b;
  float q0 = max(float(0), float(c + (slope0 - b) * si.t0));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c + (slope1 - b) * si.t1));
  float r1 = sqrt(q1);
  float root_minus_a = length * inv_R;
  float J1 = (atan(-slope1, r1 * root_minus_a) - atan(-slope0, root_minus_a * r0)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t0 = float(1) / a;
    float t1 = q1 * q1;
    float t2 = t1 * q1;
    float t3 = q0 * q0;
    float t4 = t3 * q0;
    float t5 = t1 * t1;
    float t6 = t3 * t3;
    float t7 = t5 * q1;
    float t8 = t6 * q0;
    float t9 = t2 * t2;
    float t10 = t4 * t4;
    float t11 = float(13) * (float(11) * D * t0 * (float(3) * D * t0 * (float(48) * r1 * slope1 * t2 + float(7) * D * t0 * (float(8) * r1 * slope1 * t1 + float(5) * D * t0 * (float(2) * r1 * slope1 * q1 + float(3) * D * t0 * (D * J1 + r1 * slope1 - slope0 * r0) - float(2) * slope0 * q0 * r0) - float(8) * slope0 * q0 * q0 * r0) - float(48) * slope0 * t4 * r0) + float(128) * r1 * slope1 * t5 - float(128) * slope0 * t6 * r0) + float(1280) * r1 * slope1 * t7 - float(1280) * slope0 * t8 * r0) * D * t0 + float(15360) * r1 * slope1 * t9 - float(15360) * slope0 * t10 * r0;
    float t12 = t5 * t5;
    float t13 = t9 * q1;
    float t14 = t10 * q0;
    float t15 = D * t0 * t11 + float(14336) * r1 * slope1 * t13 - float(14336) * slope0 * t14 * r0;
    float t16 = t6 * t6;
    float t17 = t0 * t11 * b + float(14336) * r1 * t13 - float(14336) * t14 * r0;
    float t18 = float(32) * t0 * b * t17 + float(15) * t0 * t15 - float(16) * c * t0 * t11;
    F = (float(1) / float(215040)) * t0 * t11 * si.w[0] + (float(1) / float(58490880)) * t0 * (float(15) * t0 * (float(229376) * r1 * t12 + float(17) * t0 * t15 * b - float(229376) * t16 * r0) + float(34) * t18 * t0 * b - float(272) * c * t0 * t17) * si.w[3] + (float(1) / float(3440640)) * t18 * si.w[2] * t0 + (float(1) / float(215040)) * t0 * t17 * si.w[1];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(13/2) dt
// Operations: 78 +, 234 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i13_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  float ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  float ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  float plain_cross0 = ap2 * ab1 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ap2 * ab0;
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
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - ap_ap * inv_R2;
  float D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c - si.t0 * (b - slope0)));
  float r0 = sqrt(q0);
  float slope1 = a * si.t1 - b;
  float q1 = max(float(0), float(si.t1 * (slope1 - b) + c));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t1 = -slope0;
  float J1 = (atan(-slope1, r1 * root_minus_a) - atan(t1, r0 * root_minus_a)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t2 = float(1) / a;
    float t3 = q1 * q1;
    float t4 = t3 * q1;
    float t5 = t4 * t4;
    float t6 = t5 * q1;
    float t7 = t3 * t3;
    float t8 = t7 * q1;
    float t9 = q0 * q0;
    float t10 = t9 * q0;
    float t11 = t9 * t9;
    float t12 = t11 * q0;
    float t13 = float(1280) * slope1 * t8 * r1 + float(11) * D * (float(128) * slope1 * t7 * r1 - float(3) * D * t2 * (float(7) * D * t2 * (float(8) * q0 * q0 * r0 * slope0 - float(5) * D * t2 * (float(2) * slope1 * q1 * r1 - float(3) * D * t2 * (r0 * slope0 - D * J1 - slope1 * r1) - float(2) * q0 * r0 * slope0) - float(8) * slope1 * t3 * r1) + float(48) * t10 * r0 * slope0 - float(48) * slope1 * t4 * r1) - float(128) * t11 * r0 * slope0) * t2 - float(1280) * t12 * r0 * slope0;
    float t14 = t10 * t10;
    float t15 = float(15360) * slope1 * t5 * r1 + float(13) * D * t2 * t13 - float(15360) * t14 * r0 * slope0;
    float t16 = t14 * q0;
    float t17 = float(14336) * t6 * r1 + t2 * t15 * b - float(14336) * t16 * r0;
    float t18 = D * t2 * t15 + float(14336) * slope1 * t6 * r1 - float(14336) * t16 * r0 * slope0;
    float t19 = float(16) * t2 * t15 * c - float(32) * t2 * b * t17 - float(15) * t2 * t18;
    float t20 = t7 * t7;
    float t21 = t11 * t11;
    F = (float(1) / float(215040)) * t2 * t17 * si.w[1] + (float(1) / float(215040)) * t2 * t15 * si.w[0] - (float(1) / float(58490880)) * t2 * (float(272) * t2 * t17 * c + float(34) * t2 * t19 * b - float(15) * t2 * (float(229376) * t20 * r1 + float(17) * t2 * t18 * b - float(229376) * t21 * r0)) * si.w[3] - (float(1) / float(3440640)) * si.w[2] * t2 * t19;
    float t22 = float(15360) * t5 * r1 + float(13) * t2 * b * t13 - float(15360) * t14 * r0;
    float t23 = float(182) * t2 * c * t13 - float(28) * t2 * t22 * b - float(13) * t2 * t15;
    G_ap = (float(1) / float(15360)) * t2 * si.w[0] * t13 + (float(1) / float(199680)) * t2 * t22 * si.w[1] - (float(1) / float(2795520)) * si.w[2] * t2 * t23 - (float(1) / float(2795520)) * t2 * si.w[3] * (float(2) * t2 * b * t23 + float(14) * t2 * t22 * c - float(13) * t2 * t17);
    float t24 = t14 * r0;
    float t25 = si.t0 * si.t0;
    float t26 = t25 * si.t0;
    float t27 = t5 * r1;
    float t28 = si.t1 * si.t1;
    float t29 = t28 * si.t1;
    G_E = -(float(1) / float(44728320)) * t2 * (float(16) * t2 * t15 * si.w[1] + float(3440640) * t24 * (si.w[2] * si.t0 * si.t0 + si.t0 * si.w[1] + si.w[3] * t26 + si.w[0]) + float(32) * si.w[2] * t2 * t17 - float(3440640) * t27 * (si.t1 * si.w[1] + si.w[0] + si.w[2] * si.t1 * si.t1 + si.w[3] * t29) - float(3) * t2 * si.w[3] * t19);
  }
  float g_factor = -float(13) * inv_R2 * length;
  f = F * length;
  grad[0] = -(G_E * ab0 - foot0 * G_ap) * g_factor;
  grad[1] = (foot1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = (foot2 * G_ap - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(15/2) dt
// Operations: 42 +, 113 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i15_w0_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  float ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
  float ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  float plain_cross0 = ap2 * ab1 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ap2 * ab0;
  float plain_cross2 = ap1 * ab0 - ap0 * ab1;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -inv_R2 * ab_ab;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - inv_R2 * ap_ap;
  float D = (inv_R2 * cross_cross - ab_ab) * inv_R2;
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c + si.t0 * (slope0 - b)));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c + (slope1 - b) * si.t1));
  float r1 = sqrt(q1);
  float root_minus_a = length * inv_R;
  float J1 = (atan(-slope1, r1 * root_minus_a) - atan(-slope0, root_minus_a * r0)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t0 = q0 * q0;
    float t1 = t0 * q0;
    float t2 = t1 * t1;
    float t3 = t2 * q0;
    float t4 = float(1) / a;
    float t5 = q1 * q1;
    float t6 = t5 * q1;
    float t7 = t0 * t0;
    float t8 = t5 * t5;
    float t9 = t7 * q0;
    float t10 = t8 * q1;
    float t11 = t6 * t6;
    float t12 = t11 * q1;
    F = -(float(1) / float(229376)) * (float(14336) * slope0 * t3 * r0 + D * t4 * (float(15360) * slope0 * t2 * r0 + float(13) * (float(11) * (float(3) * (float(7) * (float(5) * (float(2) * slope0 * q0 * r0 + float(3) * (slope0 * r0 - D * J1 - r1 * slope1) * D * t4 - float(2) * r1 * slope1 * q1) * D * t4 + float(8) * slope0 * t0 * r0 - float(8) * r1 * slope1 * q1 * q1) * D * t4 + float(48) * slope0 * t1 * r0 - float(48) * r1 * slope1 * t6) * D * t4 + float(128) * slope0 * t7 * r0 - float(128) * r1 * slope1 * t8) * D * t4 + float(1280) * slope0 * t9 * r0 - float(1280) * r1 * slope1 * t10) * D * t4 - float(15360) * r1 * slope1 * t11) - float(14336) * r1 * slope1 * t12) * t4 * si.w[0];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(15/2) dt
// Operations: 49 +, 138 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i15_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  float ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  float ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  float plain_cross0 = ap2 * ab1 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ap2 * ab0;
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
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - ap_ap * inv_R2;
  float D = (cross_cross * inv_R2 - ab_ab) * inv_R2;
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c - si.t0 * (b - slope0)));
  float r0 = sqrt(q0);
  float slope1 = a * si.t1 - b;
  float q1 = max(float(0), float(c - (b - slope1) * si.t1));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t1 = -slope1;
  float t2 = -slope0;
  float J1 = (atan(t1, r1 * root_minus_a) - atan(t2, r0 * root_minus_a)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t3 = float(1) / a;
    float t4 = q0 * q0;
    float t5 = t4 * q0;
    float t6 = t5 * t5;
    float t7 = q1 * q1;
    float t8 = t7 * q1;
    float t9 = t8 * t8;
    float t10 = t7 * t7;
    float t11 = t10 * q1;
    float t12 = t4 * t4;
    float t13 = t12 * q0;
    float t14 = float(15360) * t6 * r0 * slope0 - float(15360) * t9 * r1 * slope1 - float(13) * t3 * (float(1280) * t11 * r1 * slope1 + float(11) * t3 * D * (float(128) * t10 * r1 * slope1 + float(3) * t3 * D * (float(7) * t3 * D * (float(8) * t7 * r1 * slope1 - float(5) * t3 * D * (float(2) * q0 * r0 * slope0 + float(3) * t3 * D * (r0 * slope0 - D * J1 - r1 * slope1) - float(2) * q1 * r1 * slope1) - float(8) * t4 * r0 * slope0) + float(48) * t8 * r1 * slope1 - float(48) * t5 * r0 * slope0) - float(128) * t12 * r0 * slope0) - float(1280) * t13 * r0 * slope0) * D;
    float t15 = t6 * q0;
    float t16 = t9 * q1;
    F = -(float(1) / float(229376)) * t3 * (t3 * D * t14 + float(14336) * t15 * r0 * slope0 - float(14336) * t16 * r1 * slope1) * si.w[0];
    G_ap = -(float(1) / float(215040)) * t3 * si.w[0] * t14;
    float t17 = t15 * r0;
    float t18 = t16 * r1;
    G_E = -(float(1) / float(15)) * t3 * (t17 * si.w[0] - si.w[0] * t18);
  }
  float g_factor = -float(15) * inv_R2 * length;
  f = F * length;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = -g_factor * (G_E * ab1 - foot1 * G_ap);
  grad[2] = -g_factor * (G_E * ab2 - foot2 * G_ap);
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(15/2) dt
// Operations: 45 +, 124 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i15_w1_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  float ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
  float ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  float plain_cross0 = ap2 * ab1 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ap2 * ab0;
  float plain_cross2 = ap1 * ab0 - ap0 * ab1;
  float plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -inv_R2 * ab_ab;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - inv_R2 * ap_ap;
  float D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  float slope0 = si.t0 * a - b;
  float q0 = max(float(0), float(si.t0 * (slope0 - b) + c));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(si.t1 * (slope1 - b) + c));
  float r1 = sqrt(q1);
  float root_minus_a = length * inv_R;
  float J1 = -(atan(-slope0, root_minus_a * r0) - atan(-slope1, r1 * root_minus_a)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t0 = q1 * q1;
    float t1 = t0 * q1;
    float t2 = t1 * t1;
    float t3 = t2 * q1;
    float t4 = q0 * q0;
    float t5 = t4 * q0;
    float t6 = t5 * t5;
    float t7 = float(1) / a;
    float t8 = t4 * t4;
    float t9 = t8 * q0;
    float t10 = t0 * t0;
    float t11 = t10 * q1;
    float t12 = t6 * q0;
    float t13 = float(14336) * r1 * slope1 * t3 + (float(15360) * r1 * slope1 * t2 - float(15360) * slope0 * t6 * r0 - float(13) * D * t7 * (float(1280) * slope0 * t9 * r0 - float(1280) * r1 * slope1 * t11 - float(11) * D * t7 * (float(128) * r1 * slope1 * t10 - float(128) * slope0 * t8 * r0 - float(3) * D * t7 * (float(7) * D * t7 * (float(8) * slope0 * t4 * r0 + float(5) * D * t7 * (float(2) * slope0 * q0 * r0 - float(2) * r1 * slope1 * q1 - float(3) * D * t7 * (r1 * slope1 + D * J1 - slope0 * r0)) - float(8) * r1 * slope1 * t0) + float(48) * slope0 * t5 * r0 - float(48) * r1 * slope1 * t1)))) * D * t7 - float(14336) * slope0 * t12 * r0;
    float t14 = t10 * t10;
    float t15 = t8 * t8;
    F = (float(1) / float(229376)) * si.w[0] * t13 * t7 + (float(1) / float(3899392)) * t7 * si.w[1] * (float(229376) * r1 * t14 + float(17) * t13 * t7 * b - float(229376) * t15 * r0);
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(15/2) dt
// Operations: 58 +, 165 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i15_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
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
    foot2 = ap2 - ab2 * t0 * ab_ap;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - inv_R2 * ap_ap;
  float D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  float slope0 = si.t0 * a - b;
  float q0 = max(float(0), float(c - si.t0 * (b - slope0)));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(c - (b - slope1) * si.t1));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t1 = -slope1;
  float t2 = -slope0;
  float J1 = (atan(t1, r1 * root_minus_a) - atan(t2, r0 * root_minus_a)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t3 = q0 * q0;
    float t4 = t3 * q0;
    float t5 = t4 * t4;
    float t6 = t5 * q0;
    float t7 = float(1) / a;
    float t8 = t3 * t3;
    float t9 = t8 * q0;
    float t10 = q1 * q1;
    float t11 = t10 * t10;
    float t12 = t11 * q1;
    float t13 = t10 * q1;
    float t14 = t13 * t13;
    float t15 = float(15360) * r0 * slope0 * t5 + float(13) * (float(1280) * r0 * slope0 * t9 - float(1280) * r1 * slope1 * t12 - float(11) * (float(3) * D * t7 * (float(48) * r1 * slope1 * t13 + float(7) * D * (float(8) * r1 * slope1 * t10 + float(5) * (float(2) * r1 * slope1 * q1 + float(3) * D * (D * J1 + r1 * slope1 - r0 * slope0) * t7 - float(2) * r0 * slope0 * q0) * D * t7 - float(8) * r0 * slope0 * t3) * t7 - float(48) * r0 * slope0 * t4) + float(128) * r1 * slope1 * t11 - float(128) * r0 * slope0 * t8) * D * t7) * D * t7 - float(15360) * r1 * slope1 * t14;
    float t16 = t14 * q1;
    float t17 = float(14336) * r0 * slope0 * t6 + D * t7 * t15 - float(14336) * r1 * slope1 * t16;
    float t18 = t8 * t8;
    float t19 = t11 * t11;
    F = -(float(1) / float(3899392)) * si.w[1] * (float(17) * b * t17 * t7 + float(229376) * r0 * t18 - float(229376) * r1 * t19) * t7 - (float(1) / float(229376)) * t17 * si.w[0] * t7;
    G_ap = -(float(1) / float(215040)) * si.w[1] * t7 * (float(14336) * r0 * t6 + b * t7 * t15 - float(14336) * r1 * t16) - (float(1) / float(215040)) * si.w[0] * t7 * t15;
    float t20 = t16 * r1;
    float t21 = t6 * r0;
    G_E = (float(1) / float(3440640)) * t7 * (float(229376) * t20 * (si.w[1] * si.t1 + si.w[0]) + si.w[1] * t17 * t7 - float(229376) * t21 * (si.w[1] * si.t0 + si.w[0]));
  }
  float g_factor = -float(15) * inv_R2 * length;
  f = length * F;
  grad[0] = g_factor * (G_ap * foot0 - ab0 * G_E);
  grad[1] = -g_factor * (ab1 * G_E - G_ap * foot1);
  grad[2] = g_factor * (foot2 * G_ap - ab2 * G_E);
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(15/2) dt
// Operations: 50 +, 144 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i15_w2_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  float ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ab2 * ap0 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - inv_R2 * ap_ap;
  float D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  float slope0 = si.t0 * a - b;
  float q0 = max(float(0), float(c + (slope0 - b) * si.t0));
  float r0 = sqrt(q0);
  float slope1 = a * si.t1 - b;
  float q1 = max(float(0), float(c - (b - slope1) * si.t1));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t0 = -slope1;
  float J1 = (atan(t0, root_minus_a * r1) - atan(-slope0, root_minus_a * r0)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t1 = float(1) / a;
    float t2 = q1 * q1;
    float t3 = t2 * q1;
    float t4 = t3 * t3;
    float t5 = t4 * q1;
    float t6 = q0 * q0;
    float t7 = t6 * q0;
    float t8 = t7 * t7;
    float t9 = t6 * t6;
    float t10 = t9 * q0;
    float t11 = t2 * t2;
    float t12 = t11 * q1;
    float t13 = t8 * q0;
    float t14 = float(14336) * slope1 * t5 * r1 + (float(15360) * slope1 * t4 * r1 - float(15360) * slope0 * t8 * r0 - float(13) * (float(1280) * slope0 * t10 * r0 + float(11) * (float(128) * slope0 * t9 * r0 - float(128) * slope1 * t11 * r1 - float(3) * (float(7) * D * t1 * (float(5) * D * t1 * (float(2) * slope1 * q1 * r1 - float(2) * slope0 * q0 * r0 - float(3) * (slope0 * r0 - J1 * D - slope1 * r1) * D * t1) + float(8) * slope1 * t2 * r1 - float(8) * slope0 * t6 * r0) + float(48) * slope1 * t3 * r1 - float(48) * slope0 * t7 * r0) * D * t1) * D * t1 - float(1280) * slope1 * t12 * r1) * D * t1) * D * t1 - float(14336) * slope0 * t13 * r0;
    float t15 = t9 * t9;
    float t16 = t11 * t11;
    float t17 = float(229376) * t15 * r0 - float(17) * b * t1 * t14 - float(229376) * t16 * r1;
    F = (float(1) / float(229376)) * si.w[0] * t1 * t14 - (float(1) / float(70189056)) * si.w[2] * (float(36) * t17 * b * t1 + float(306) * c * t1 * t14 - float(17) * (float(229376) * slope1 * t16 * r1 + float(17) * D * t1 * t14 - float(229376) * slope0 * t15 * r0) * t1) * t1 - (float(1) / float(3899392)) * t17 * si.w[1] * t1;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(15/2) dt
// Operations: 69 +, 204 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i15_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
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
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -ab_ap * inv_R2;
  float c = float(1) - inv_R2 * ap_ap;
  float D = -(ab_ab - cross_cross * inv_R2) * inv_R2;
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c + (slope0 - b) * si.t0));
  float r0 = sqrt(q0);
  float slope1 = si.t1 * a - b;
  float q1 = max(float(0), float(si.t1 * (slope1 - b) + c));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float J1 = (atan(-slope1, r1 * root_minus_a) - atan(-slope0, root_minus_a * r0)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t1 = float(1) / a;
    float t2 = q1 * q1;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = t2 * q1;
    float t6 = t5 * t5;
    float t7 = q0 * q0;
    float t8 = t7 * t7;
    float t9 = t8 * q0;
    float t10 = t7 * q0;
    float t11 = t3 * q1;
    float t12 = t10 * t10;
    float t13 = float(15360) * r1 * slope1 * t6 - float(13) * (float(1280) * slope0 * t9 * r0 + float(11) * D * t1 * (float(128) * slope0 * t8 * r0 - float(128) * r1 * slope1 * t3 - float(3) * D * t1 * (float(7) * (float(5) * (float(3) * D * t1 * (D * J1 + r1 * slope1 - slope0 * r0) + float(2) * r1 * slope1 * q1 - float(2) * slope0 * q0 * r0) * D * t1 + float(8) * r1 * slope1 * t2 - float(8) * slope0 * t7 * r0) * D * t1 + float(48) * r1 * slope1 * t5 - float(48) * slope0 * t10 * r0)) - float(1280) * r1 * slope1 * t11) * D * t1 - float(15360) * slope0 * t12 * r0;
    float t14 = t6 * q1;
    float t15 = t12 * q0;
    float t16 = t13 * D * t1 + float(14336) * r1 * slope1 * t14 - float(14336) * slope0 * t15 * r0;
    float t17 = t8 * t8;
    float t18 = float(229376) * r1 * t4 + float(17) * t16 * t1 * b - float(229376) * t17 * r0;
    F = (float(1) / float(70189056)) * t1 * si.w[2] * (float(36) * t18 * t1 * b - float(17) * (float(229376) * slope0 * t17 * r0 - float(17) * t16 * D * t1 - float(229376) * r1 * slope1 * t4) * t1 - float(306) * t16 * c * t1) + (float(1) / float(229376)) * t16 * si.w[0] * t1 + (float(1) / float(3899392)) * t18 * si.w[1] * t1;
    float t19 = t13 * t1 * b + float(14336) * r1 * t14 - float(14336) * t15 * r0;
    G_ap = (float(1) / float(215040)) * si.w[1] * t19 * t1 + (float(1) / float(215040)) * si.w[0] * t13 * t1 - (float(1) / float(3440640)) * (float(16) * c * t13 * t1 - float(32) * t19 * t1 * b - float(15) * t16 * t1) * t1 * si.w[2];
    float t20 = t15 * r0;
    float t21 = t14 * r1;
    G_E = -(float(1) / float(58490880)) * (float(17) * t16 * si.w[1] * t1 + float(2) * t18 * t1 * si.w[2] + float(3899392) * (si.w[0] + si.t0 * si.t0 * si.w[2] + si.w[1] * si.t0) * t20 - float(3899392) * t21 * (si.t1 * si.t1 * si.w[2] + si.w[0] + si.t1 * si.w[1])) * t1;
  }
  float g_factor = -float(15) * length * inv_R2;
  f = length * F;
  grad[0] = -(ab0 * G_E - G_ap * foot0) * g_factor;
  grad[1] = g_factor * (G_ap * foot1 - ab1 * G_E);
  grad[2] = -(ab2 * G_E - foot2 * G_ap) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(15/2) dt
// Operations: 55 +, 165 *, 3 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i15_w3_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
  float ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  float plain_cross0 = ap2 * ab1 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ap2 * ab0;
  float plain_cross2 = ap1 * ab0 - ap0 * ab1;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -inv_R2 * ab_ab;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - inv_R2 * ap_ap;
  float D = -inv_R2 * (ab_ab - inv_R2 * cross_cross);
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float((slope0 - b) * si.t0 + c));
  float r0 = sqrt(q0);
  float slope1 = a * si.t1 - b;
  float q1 = max(float(0), float(c - si.t1 * (b - slope1)));
  float r1 = sqrt(q1);
  float root_minus_a = length * inv_R;
  float t0 = -slope1;
  float J1 = (atan(t0, r1 * root_minus_a) - atan(-slope0, root_minus_a * r0)) / root_minus_a;
  float F;
  {
    // recurrence (1) downwards from J_0, J_1
    float t1 = float(1) / a;
    float t2 = q0 * q0;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = t2 * q0;
    float t6 = t5 * t5;
    float t7 = t6 * q0;
    float t8 = q1 * q1;
    float t9 = t8 * q1;
    float t10 = t8 * t8;
    float t11 = t10 * q1;
    float t12 = t3 * q0;
    float t13 = t9 * t9;
    float t14 = t13 * q1;
    float t15 = float(14336) * slope0 * t7 * r0 + D * t1 * (float(15360) * slope0 * t6 * r0 - float(13) * D * t1 * (float(11) * D * t1 * (float(3) * D * (float(7) * D * (float(8) * r1 * slope1 * q1 * q1 - float(5) * D * t1 * (float(2) * slope0 * q0 * r0 - float(2) * r1 * slope1 * q1 - float(3) * (r1 * slope1 + D * J1 - slope0 * r0) * D * t1) - float(8) * slope0 * t2 * r0) * t1 + float(48) * r1 * slope1 * t9 - float(48) * slope0 * t5 * r0) * t1 + float(128) * r1 * slope1 * t10 - float(128) * slope0 * t3 * r0) + float(1280) * r1 * slope1 * t11 - float(1280) * slope0 * t12 * r0) - float(15360) * r1 * slope1 * t13) - float(14336) * r1 * slope1 * t14;
    float t16 = t10 * t10;
    float t17 = float(229376) * t4 * r0 + float(17) * t15 * t1 * b - float(229376) * r1 * t16;
    float t18 = float(229376) * slope0 * t4 * r0 + float(17) * t15 * D * t1 - float(229376) * r1 * slope1 * t16;
    float t19 = float(17) * t1 * t18 + float(36) * t17 * t1 * b - float(306) * t15 * t1 * c;
    float t20 = t4 * q0;
    float t21 = t16 * q1;
    F = (float(1) / float(1333592064)) * t1 * si.w[3] * (float(342) * t17 * t1 * c - float(38) * t1 * b * t19 - float(17) * t1 * (float(4128768) * t20 * r0 + float(19) * t1 * b * t18 - float(4128768) * r1 * t21)) - (float(1) / float(70189056)) * si.w[2] * t1 * t19 - (float(1) / float(3899392)) * t17 * t1 * si.w[1] - (float(1) / float(229376)) * t15 * t1 * si.w[0];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(15/2) dt
// Operations: 80 +, 242 *, 4 /, 3 sqrt, 2 atan, 0 log/asinh (generic form).
float segment_compact_i15_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
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
    foot2 = ap2 - ab2 * t0 * ab_ap;
  }
  float length = sqrt(ab_ab);
  float inv_R = float(1) / si.R;
  float inv_R2 = inv_R * inv_R;
  float a = -ab_ab * inv_R2;
  float b = -inv_R2 * ab_ap;
  float c = float(1) - ap_ap * inv_R2;
  float D = -inv_R2 * (ab_ab - cross_cross * inv_R2);
  float slope0 = a * si.t0 - b;
  float q0 = max(float(0), float(c - si.t0 * (b - slope0)));
  float r0 = sqrt(q0);
  float slope1 = a * si.t1 - b;
  float q1 = max(float(0), float(c - (b - slope1) * si.t1));
  float r1 = sqrt(q1);
  float root_minus_a = inv_R * length;
  float t1 = -slope0;
  float t2 = -slope1;
  float J1 = -(atan(t1, r0 * root_minus_a) - atan(t2, r1 * root_minus_a)) / root_minus_a;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) downwards from J_0, J_1
    float t3 = float(1) / a;
    float t4 = q0 * q0;
    float t5 = t4 * t4;
    float t6 = t5 * q0;
    float t7 = q1 * q1;
    float t8 = t7 * t7;
    float t9 = t8 * q1;
    float t10 = t4 * q0;
    float t11 = t7 * q1;
    float t12 = t10 * t10;
    float t13 = t11 * t11;
    float t14 = float(13) * D * t3 * (float(1280) * t6 * r0 * slope0 - float(1280) * t9 * r1 * slope1 - float(11) * D * t3 * (float(128) * t8 * r1 * slope1 - float(128) * t5 * r0 * slope0 - float(3) * D * t3 * (float(7) * D * t3 * (float(8) * t4 * r0 * slope0 - float(5) * D * t3 * (float(3) * D * t3 * (D * J1 + r1 * slope1 - r0 * slope0) + float(2) * q1 * r1 * slope1 - float(2) * q0 * r0 * slope0) - float(8) * t7 * r1 * slope1) + float(48) * t10 * r0 * slope0 - float(48) * t11 * r1 * slope1))) + float(15360) * t12 * r0 * slope0 - float(15360) * t13 * r1 * slope1;
    float t15 = t12 * q0;
    float t16 = t13 * q1;
    float t17 = D * t3 * t14 + float(14336) * t15 * r0 * slope0 - float(14336) * t16 * r1 * slope1;
    float t18 = t5 * t5;
    float t19 = t8 * t8;
    float t20 = float(17) * t17 * t3 * b + float(229376) * t18 * r0 - float(229376) * t19 * r1;
    float t21 = float(17) * t17 * D * t3 + float(229376) * t18 * r0 * slope0 - float(229376) * t19 * r1 * slope1;
    float t22 = float(36) * t3 * b * t20 + float(17) * t3 * t21 - float(306) * t17 * t3 * c;
    float t23 = t18 * q0;
    float t24 = t19 * q1;
    F = -(float(1) / float(1333592064)) * t3 * si.w[3] * (float(38) * t3 * t22 * b + float(17) * t3 * (float(19) * t3 * b * t21 + float(4128768) * t23 * r0 - float(4128768) * t24 * r1) - float(342) * t3 * c * t20) - (float(1) / float(3899392)) * t3 * si.w[1] * t20 - (float(1) / float(70189056)) * si.w[2] * t3 * t22 - (float(1) / float(229376)) * t17 * t3 * si.w[0];
    float t25 = t3 * b * t14 + float(14336) * t15 * r0 - float(14336) * t16 * r1;
    float t26 = float(32) * t3 * t25 * b + float(15) * t17 * t3 - float(16) * t3 * c * t14;
    G_ap = -(float(1) / float(58490880)) * t3 * (float(34) * t3 * t26 * b + float(15) * t3 * t20 - float(272) * t3 * t25 * c) * si.w[3] - (float(1) / float(3440640)) * si.w[2] * t3 * t26 - (float(1) / float(215040)) * t3 * t25 * si.w[1] - (float(1) / float(215040)) * t3 * si.w[0] * t14;
    float t27 = t16 * r1;
    float t28 = si.t1 * si.t1;
    float t29 = t28 * si.t1;
    float t30 = si.t0 * si.t0;
    float t31 = t30 * si.t0;
    float t32 = t15 * r0;
    G_E = (float(1) / float(350945280)) * t3 * (float(23396352) * t27 * (si.t1 * si.w[1] + si.w[0] + si.w[2] * si.t1 * si.t1 + si.w[3] * t29) + float(102) * t17 * t3 * si.w[1] + t3 * t22 * si.w[3] + float(12) * si.w[2] * t3 * t20 - float(23396352) * (t31 * si.w[3] + si.w[2] * t30 + si.w[0] + si.t0 * si.w[1]) * t32);
  }
  float g_factor = -float(15) * inv_R2 * length;
  f = F * length;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = (foot1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = -g_factor * (G_E * ab2 - foot2 * G_ap);
  return f;
}

