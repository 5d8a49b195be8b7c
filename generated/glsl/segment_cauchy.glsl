// generated/glsl/segment_cauchy.glsl - segment kernels of the cauchy family in GLSL (float; ES 3.00 and 4.50), generic forms only.
//
// GENERATED FILE: DO NOT EDIT. Regenerate with
//     skelconv-codegen --inverse 1:16 --cauchy 1:16 --compact 2:16 --weights 0:3 --polygon-inverse 3:12 --polygon-cauchy 3:12 --polygon-compact 4:12 --scalis-inverse 2:10 --scalis-cauchy 2:10 --out generated
// Generator: skelconv-codegen 0.1.0 (GiNaC 1.8.6)
// From: codegen/segment_families.cpp (the families) and codegen/segment_moments.cpp
// (recurrence (1) of Hubert & Cani unrolled; SPEC sec. 2, Hubert 2012 sec. 3).

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
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-1/2) dt
// Operations: 28 +, 36 *, 2 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
float segment_cauchy_i1_w0_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t0 = sqrt(a);
    X = t0 * (a_minus_b * r0 + b * r1) / D;
  }
  float t1 = sqrt(a);
  float J1 = skelconv_asinh(X) / t1;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    F = si.w[0] * J1;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-1/2) dt
// Operations: 36 +, 61 *, 7 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
float segment_cauchy_i1_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
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
  float ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t1 = float(1) / D;
    float t2 = sqrt(a);
    X = t1 * (r1 * b + a_minus_b * r0) * t2;
  }
  float t3 = sqrt(a);
  float t4 = float(1) / t3;
  float J1 = skelconv_asinh(X) * t4;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    F = J1 * si.w[0];
    float t5 = float(1) / D;
    float t6 = float(1) / r0;
    float t7 = float(1) / r1;
    G_ap = t5 * (b * t6 + t7 * a_minus_b) * si.w[0];
    float t8 = float(1) / a;
    G_E = -(t7 * si.w[0] - si.w[0] * t6) * t8;
  }
  float g_factor = -length * si.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = -(ab1 * G_E - G_ap * foot1) * g_factor;
  grad[2] = -g_factor * (ab2 * G_E - foot2 * G_ap);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-1/2) dt
// Operations: 31 +, 40 *, 3 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
float segment_cauchy_i1_w1_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  float ab_ap = ap2 * ab2 + ab1 * ap1 + ab0 * ap0;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ab1 * ap2 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (cross_cross * si.s + ab_ab) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t0 = sqrt(a);
    X = t0 * (b * r1 + r0 * a_minus_b) / D;
  }
  float t1 = sqrt(a);
  float t2 = float(1) / t1;
  float J1 = t2 * skelconv_asinh(X);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t3 = float(1) / a;
    F = J1 * si.w[0] + t3 * (J1 * b + r1 - r0) * si.w[1];
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-1/2) dt
// Operations: 44 +, 69 *, 7 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
float segment_cauchy_i1_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
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
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = ab2 * bp2 + bp0 * ab0 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t1 = float(1) / D;
    float t2 = sqrt(a);
    X = t1 * t2 * (r1 * b + r0 * a_minus_b);
  }
  float t3 = sqrt(a);
  float t4 = float(1) / t3;
  float J1 = skelconv_asinh(X) * t4;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t5 = float(1) / a;
    F = si.w[0] * J1 - si.w[1] * t5 * (r0 - r1 - b * J1);
    float t6 = float(1) / r1;
    float t7 = float(1) / r0;
    float t8 = t6 * a_minus_b + t7 * b;
    float t9 = float(1) / D;
    G_ap = t8 * t9 * si.w[0] - si.w[1] * t5 * (t6 - t8 * t9 * b - t7);
    G_E = -t5 * ((si.w[1] + si.w[0]) * t6 - si.w[1] * J1 - t7 * si.w[0]);
  }
  float g_factor = -length * si.s;
  f = F * length;
  grad[0] = -(G_E * ab0 - foot0 * G_ap) * g_factor;
  grad[1] = -g_factor * (G_E * ab1 - foot1 * G_ap);
  grad[2] = g_factor * (foot2 * G_ap - G_E * ab2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-1/2) dt
// Operations: 36 +, 52 *, 3 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
float segment_cauchy_i1_w2_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t0 = sqrt(a);
    X = t0 * (r0 * a_minus_b + b * r1) / D;
  }
  float t1 = sqrt(a);
  float t2 = float(1) / t1;
  float J1 = t2 * skelconv_asinh(X);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t3 = float(1) / a;
    float t4 = J1 * b + r1 - r0;
    F = t3 * t4 * si.w[1] + si.w[0] * J1 - (float(1) / float(2)) * t3 * (float(2) * J1 * c - float(4) * t3 * t4 * b - t3 * (D * J1 + r0 * b + r1 * a_minus_b)) * si.w[2];
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-1/2) dt
// Operations: 54 +, 91 *, 7 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
float segment_cauchy_i1_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
    foot2 = ap2 - ab2 * t0 * ab_ap;
  }
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t1 = float(1) / D;
    float t2 = sqrt(a);
    X = (a_minus_b * r0 + r1 * b) * t1 * t2;
  }
  float t3 = sqrt(a);
  float t4 = float(1) / t3;
  float J1 = skelconv_asinh(X) * t4;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t5 = r1 + b * J1 - r0;
    float t6 = float(1) / a;
    F = t5 * si.w[1] * t6 + si.w[0] * J1 + (float(1) / float(2)) * si.w[2] * (float(4) * b * t5 * t6 + (J1 * D + b * r0 + a_minus_b * r1) * t6 - float(2) * c * J1) * t6;
    float t7 = float(1) / r0;
    float t8 = float(1) / r1;
    float t9 = b * t7 + a_minus_b * t8;
    float t10 = float(1) / D;
    float t11 = b * t9 * t10 + t7 - t8;
    G_ap = t11 * si.w[1] * t6 + si.w[0] * t9 * t10 - (t9 * c * t10 - float(2) * t11 * b * t6 - J1) * si.w[2] * t6;
    G_E = -((si.w[0] + si.w[1] + si.w[2]) * t8 - si.w[0] * t7 - float(2) * t5 * si.w[2] * t6 - si.w[1] * J1) * t6;
  }
  float g_factor = -length * si.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = g_factor * (G_ap * foot1 - ab1 * G_E);
  grad[2] = (foot2 * G_ap - ab2 * G_E) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-1/2) dt
// Operations: 41 +, 69 *, 3 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
float segment_cauchy_i1_w3_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (cross_cross * si.s + ab_ab) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t0 = sqrt(a);
    X = (b * r1 + r0 * a_minus_b) * t0 / D;
  }
  float t1 = sqrt(a);
  float t2 = float(1) / t1;
  float J1 = skelconv_asinh(X) * t2;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t3 = r0 - J1 * b - r1;
    float t4 = float(1) / a;
    float t5 = r0 * b + r1 * a_minus_b + J1 * D;
    float t6 = float(2) * J1 * c + float(4) * b * t3 * t4 - t4 * t5;
    F = J1 * si.w[0] - si.w[1] * t3 * t4 - (float(1) / float(2)) * t6 * si.w[2] * t4 - (float(1) / float(6)) * (float(6) * b * t6 * t4 - (float(2) * r1 * q1 + float(3) * b * t4 * t5 - float(2) * r0 * c) * t4 - float(6) * c * t3 * t4) * si.w[3] * t4;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-1/2) dt
// Operations: 64 +, 123 *, 7 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
float segment_cauchy_i1_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  float ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -ab_bp * si.s;
  float q1 = si.s * bp_bp + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t1 = float(1) / D;
    float t2 = sqrt(a);
    X = t1 * t2 * (r0 * a_minus_b + r1 * b);
  }
  float t3 = sqrt(a);
  float t4 = float(1) / t3;
  float J1 = t4 * skelconv_asinh(X);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t5 = float(1) / a;
    float t6 = r0 - J1 * b - r1;
    float t7 = r1 * a_minus_b + J1 * D + r0 * b;
    float t8 = t7 * t5 - float(2) * J1 * c - float(4) * t5 * b * t6;
    F = (float(1) / float(6)) * si.w[3] * (float(6) * t5 * t6 * c + float(6) * t8 * t5 * b + t5 * (float(2) * r1 * q1 + float(3) * t7 * t5 * b - float(2) * r0 * c)) * t5 + J1 * si.w[0] + (float(1) / float(2)) * t8 * t5 * si.w[2] - t5 * si.w[1] * t6;
    float t9 = float(1) / D;
    float t10 = float(1) / r1;
    float t11 = float(1) / r0;
    float t12 = t10 * a_minus_b + t11 * b;
    float t13 = t9 * b * t12 + t11 - t10;
    float t14 = J1 + float(2) * t5 * t13 * b - t9 * t12 * c;
    G_ap = si.w[3] * t5 * (float(2) * t14 * t5 * b - t5 * t13 * c - t5 * t6) + t9 * si.w[0] * t12 + t5 * t13 * si.w[1] + t14 * t5 * si.w[2];
    G_E = -(float(1) / float(2)) * t5 * (float(4) * t5 * t6 * si.w[2] + float(2) * t10 * (si.w[3] + si.w[0] + si.w[1] + si.w[2]) - float(2) * J1 * si.w[1] - float(3) * si.w[3] * t8 * t5 - float(2) * t11 * si.w[0]);
  }
  float g_factor = -si.s * length;
  f = F * length;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = -(G_E * ab1 - foot1 * G_ap) * g_factor;
  grad[2] = (foot2 * G_ap - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-2/2) dt
// Operations: 20 +, 20 *, 1 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i2_w0_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ab2 * ap0 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  float length = sqrt(ab_ab);
  float D = si.s * (ab_ab + si.s * cross_cross);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float J2 = atan(t0, c_minus_b) / t0;
    F = si.w[0] * J2;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-2/2) dt
// Operations: 39 +, 64 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i2_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  float ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
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
    foot0 = ap0 - ab_ap * t0 * ab0;
    foot1 = ap1 - ab_ap * t0 * ab1;
    foot2 = ap2 - ab_ap * t0 * ab2;
  }
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  float ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = atan(t1, c_minus_b) * t2;
    F = J2 * si.w[0];
    float t3 = float(1) / D;
    float t4 = float(1) / c;
    float t5 = float(1) / q1;
    G_ap = (float(1) / float(2)) * si.w[0] * t3 * (t4 * b + J2 * a + t5 * a_minus_b);
    G_E = -(float(1) / float(2)) * (t5 * si.w[0] - t4 * si.w[0]) / a;
  }
  float g_factor = -float(2) * length * si.s;
  f = length * F;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = -g_factor * (G_E * ab1 - G_ap * foot1);
  grad[2] = (G_ap * foot2 - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-2/2) dt
// Operations: 30 +, 37 *, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float segment_cauchy_i2_w1_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
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
  float ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (cross_cross * si.s + ab_ab) * si.s;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float log_ratio = log(q1 / c);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float J2 = atan(t0, c_minus_b) / t0;
    F = J2 * si.w[0] + (float(1) / float(2)) * (float(2) * J2 * b + log_ratio) * si.w[1] / a;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-2/2) dt
// Operations: 46 +, 77 *, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float segment_cauchy_i2_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  float ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ap0 * ab1;
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
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (ab_ab + si.s * cross_cross);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
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
    F = si.w[0] * J2 + (float(1) / float(2)) * si.w[1] * t4 * (log_ratio + float(2) * J2 * b);
    float t5 = float(1) / q1;
    float t6 = t1 * b + J2 * a + t5 * a_minus_b;
    float t7 = float(1) / D;
    G_ap = (float(1) / float(2)) * si.w[0] * t6 * t7 + (float(1) / float(2)) * si.w[1] * (t6 * t7 * b + t1 - t5) * t4;
    G_E = -(float(1) / float(2)) * (t5 * (si.w[0] + si.w[1]) - J2 * si.w[1] - si.w[0] * t1) * t4;
  }
  float g_factor = -float(2) * si.s * length;
  f = F * length;
  grad[0] = (foot0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = -(G_E * ab1 - G_ap * foot1) * g_factor;
  grad[2] = (G_ap * foot2 - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-2/2) dt
// Operations: 33 +, 43 *, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float segment_cauchy_i2_w2_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (si.s * cross_cross + ab_ab) * si.s;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float log_ratio = log(q1 / c);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float J2 = atan(t0, c_minus_b) / t0;
    float t1 = log_ratio + float(2) * b * J2;
    float t2 = float(1) / a;
    F = J2 * si.w[0] + (b * t1 * t2 + float(1) - c * J2) * si.w[2] * t2 + (float(1) / float(2)) * si.w[1] * t1 * t2;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-2/2) dt
// Operations: 54 +, 93 *, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float segment_cauchy_i2_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  float ab_ap = ab1 * ap1 + ab0 * ap0 + ap2 * ab2;
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
    foot2 = ap2 - ab_ap * ab2 * t0;
  }
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  float ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (cross_cross * si.s + ab_ab) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float t1 = float(1) / c;
  float log_ratio = log(q1 * t1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t2 = sqrt(D);
    float t3 = float(1) / t2;
    float J2 = t3 * atan(t2, c_minus_b);
    float t4 = log_ratio + float(2) * b * J2;
    float t5 = float(1) / a;
    F = si.w[0] * J2 + (b * t4 * t5 + float(1) - c * J2) * si.w[2] * t5 + (float(1) / float(2)) * si.w[1] * t4 * t5;
    float t6 = float(1) / q1;
    float t7 = b * t1 + a_minus_b * t6 + J2 * a;
    float t8 = float(1) / D;
    float t9 = t6 - b * t7 * t8 - t1;
    G_ap = (float(1) / float(2)) * si.w[0] * t7 * t8 - (float(1) / float(2)) * (c * t7 * t8 + float(2) * b * t9 * t5 - float(2) * J2) * si.w[2] * t5 - (float(1) / float(2)) * t9 * si.w[1] * t5;
    G_E = (float(1) / float(2)) * (si.w[0] * t1 + si.w[1] * J2 + t4 * si.w[2] * t5 - t6 * (si.w[0] + si.w[1] + si.w[2])) * t5;
  }
  float g_factor = -float(2) * length * si.s;
  f = F * length;
  grad[0] = -(ab0 * G_E - foot0 * G_ap) * g_factor;
  grad[1] = -(ab1 * G_E - G_ap * foot1) * g_factor;
  grad[2] = -(G_E * ab2 - foot2 * G_ap) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-2/2) dt
// Operations: 38 +, 53 *, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float segment_cauchy_i2_w3_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = ap_bp * si.s + float(1);
  float log_ratio = log(q1 / c);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float J2 = atan(t0, c_minus_b) / t0;
    float t1 = float(1) / a;
    float t2 = float(2) * J2 * b + log_ratio;
    float t3 = J2 * c - t1 * b * t2 - float(1);
    F = (float(1) / float(2)) * t1 * si.w[1] * t2 + si.w[0] * J2 - (float(1) / float(2)) * t1 * (float(4) * t3 * t1 * b + t1 * c * t2 - t1 * (float(2) * b + q1 - c)) * si.w[3] - t3 * t1 * si.w[2];
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-2/2) dt
// Operations: 64 +, 115 *, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float segment_cauchy_i2_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  float ab_ap = ap2 * ab2 + ab1 * ap1 + ab0 * ap0;
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  float ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float t1 = float(1) / c;
  float log_ratio = log(t1 * q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t2 = sqrt(D);
    float t3 = float(1) / t2;
    float J2 = t3 * atan(t2, c_minus_b);
    float t4 = float(1) / a;
    float t5 = log_ratio + float(2) * J2 * b;
    float t6 = t4 * b * t5 + float(1) - c * J2;
    F = t4 * si.w[2] * t6 + J2 * si.w[0] + (float(1) / float(2)) * si.w[1] * t4 * t5 - (float(1) / float(2)) * ((c - float(2) * b - q1) * t4 + c * t4 * t5 - float(4) * t4 * t6 * b) * t4 * si.w[3];
    float t7 = float(1) / q1;
    float t8 = J2 * a + a_minus_b * t7 + t1 * b;
    float t9 = float(1) / D;
    float t10 = t7 - t1 - t8 * t9 * b;
    float t11 = float(2) * J2 - float(2) * t10 * t4 * b - c * t8 * t9;
    G_ap = (float(1) / float(2)) * t8 * t9 * si.w[0] + (float(1) / float(2)) * t4 * si.w[3] * (c * t10 * t4 + float(2) * t11 * t4 * b + t4 * t5) + (float(1) / float(2)) * t11 * t4 * si.w[2] - (float(1) / float(2)) * si.w[1] * t10 * t4;
    G_E = (float(1) / float(2)) * t4 * (t4 * si.w[2] * t5 + t1 * si.w[0] + float(3) * t4 * t6 * si.w[3] + si.w[1] * J2 - (si.w[1] + si.w[2] + si.w[3] + si.w[0]) * t7);
  }
  float g_factor = -float(2) * si.s * length;
  f = F * length;
  grad[0] = (foot0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = (G_ap * foot2 - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-3/2) dt
// Operations: 28 +, 32 *, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i3_w0_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  float length = sqrt(ab_ab);
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    F = si.w[0] * (a_minus_b / r1 + b / r0) / D;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-3/2) dt
// Operations: 37 +, 68 *, 7 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i3_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
  float ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / r1;
    float t2 = float(1) / r0;
    float t3 = t1 * a_minus_b + t2 * b;
    float t4 = float(1) / D;
    F = t3 * t4 * si.w[0];
    G_ap = (float(1) / float(3)) * (t2 * b / c + t1 * a_minus_b / q1 + float(2) * t3 * t4 * a) * t4 * si.w[0];
    float t5 = t1 * t1;
    float t6 = t5 * t1;
    float t7 = t2 * t2;
    float t8 = t7 * t2;
    G_E = -(float(1) / float(3)) * (t6 * si.w[0] - t8 * si.w[0]) / a;
  }
  float g_factor = -float(3) * length * si.s;
  f = F * length;
  grad[0] = -(G_E * ab0 - foot0 * G_ap) * g_factor;
  grad[1] = (foot1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = -(G_E * ab2 - foot2 * G_ap) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-3/2) dt
// Operations: 31 +, 39 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i3_w1_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = bp0 * ab0 + ab2 * bp2 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / D;
    float t1 = float(1) / r0;
    float t2 = float(1) / r1;
    float t3 = t1 * b + t2 * a_minus_b;
    F = t0 * t3 * si.w[0] - si.w[1] * (t2 - t1 - t0 * t3 * b) / a;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-3/2) dt
// Operations: 45 +, 86 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i3_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -ab_bp * si.s;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / D;
    float t2 = float(1) / r1;
    float t3 = float(1) / r0;
    float t4 = t2 * a_minus_b + t3 * b;
    float t5 = float(1) / a;
    F = t1 * si.w[0] * t4 - si.w[1] * t5 * (t2 - t1 * b * t4 - t3);
    float t6 = t2 * t2;
    float t7 = t3 * t3;
    float t8 = float(2) * t1 * a * t4 + t2 * a_minus_b * t6 + t3 * b * t7;
    G_ap = (float(1) / float(3)) * t1 * si.w[0] * t8 + (float(1) / float(3)) * si.w[1] * (t1 * b * t8 + t3 * t7 - t2 * t6) * t5;
    float t9 = t2 * t2;
    float t10 = t9 * t2;
    float t11 = t3 * t3;
    float t12 = t11 * t3;
    G_E = -(float(1) / float(3)) * (t10 * (si.w[1] + si.w[0]) - si.w[1] * t1 * t4 - t12 * si.w[0]) * t5;
  }
  float g_factor = -float(3) * length * si.s;
  f = F * length;
  grad[0] = -(G_E * ab0 - foot0 * G_ap) * g_factor;
  grad[1] = -(G_E * ab1 - foot1 * G_ap) * g_factor;
  grad[2] = g_factor * (foot2 * G_ap - G_E * ab2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-3/2) dt
// Operations: 35 +, 52 *, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
float segment_cauchy_i3_w2_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
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
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (ab_ab + cross_cross * si.s);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t0 = sqrt(a);
    float t1 = float(1) / D;
    X = t0 * (b * r1 + r0 * a_minus_b) * t1;
  }
  float t2 = sqrt(a);
  float t3 = float(1) / t2;
  float J1 = t3 * skelconv_asinh(X);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t4 = float(1) / a;
    float t5 = float(1) / r0;
    float t6 = float(1) / r1;
    float t7 = t5 * b + a_minus_b * t6;
    float t8 = float(1) / D;
    float t9 = b * t7 * t8 + t5 - t6;
    F = t4 * (J1 + float(2) * t4 * b * t9 - t7 * c * t8) * si.w[2] + si.w[0] * t7 * t8 + t4 * si.w[1] * t9;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-3/2) dt
// Operations: 54 +, 111 *, 7 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
float segment_cauchy_i3_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  float ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
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
    foot0 = ap0 - ab0 * t0 * ab_ap;
    foot1 = ap1 - ab1 * t0 * ab_ap;
    foot2 = ap2 - t0 * ab2 * ab_ap;
  }
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t1 = float(1) / D;
    float t2 = sqrt(a);
    X = (r1 * b + a_minus_b * r0) * t1 * t2;
  }
  float t3 = sqrt(a);
  float t4 = float(1) / t3;
  float J1 = skelconv_asinh(X) * t4;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t5 = float(1) / r0;
    float t6 = float(1) / r1;
    float t7 = b * t5 + t6 * a_minus_b;
    float t8 = float(1) / D;
    float t9 = t7 * b * t8 + t5 - t6;
    float t10 = float(1) / a;
    F = si.w[1] * t9 * t10 + t7 * si.w[0] * t8 - si.w[2] * (t7 * c * t8 - float(2) * b * t9 * t10 - J1) * t10;
    float t11 = t6 * t6;
    float t12 = t5 * t5;
    float t13 = t6 * a_minus_b * t11 + float(2) * t7 * t8 * a + b * t12 * t5;
    float t14 = t6 * t11 - b * t13 * t8 - t12 * t5;
    G_ap = (float(1) / float(3)) * si.w[0] * t13 * t8 - (float(1) / float(3)) * t14 * si.w[1] * t10 - (float(1) / float(3)) * (c * t13 * t8 + float(2) * t14 * b * t10 - float(3) * t7 * t8) * si.w[2] * t10;
    float t15 = t5 * t5;
    float t16 = t15 * t5;
    float t17 = t6 * t6;
    float t18 = t17 * t6;
    G_E = (float(1) / float(3)) * (si.w[0] * t16 + t7 * si.w[1] * t8 + float(2) * t9 * si.w[2] * t10 - t18 * (si.w[0] + si.w[1] + si.w[2])) * t10;
  }
  float g_factor = -float(3) * length * si.s;
  f = F * length;
  grad[0] = (foot0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = (G_ap * foot1 - ab1 * G_E) * g_factor;
  grad[2] = -(ab2 * G_E - foot2 * G_ap) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-3/2) dt
// Operations: 40 +, 61 *, 6 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
float segment_cauchy_i3_w3_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
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
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -ab_bp * si.s;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t0 = float(1) / D;
    float t1 = sqrt(a);
    X = t0 * t1 * (a_minus_b * r0 + b * r1);
  }
  float t2 = sqrt(a);
  float t3 = float(1) / t2;
  float J1 = skelconv_asinh(X) * t3;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t4 = float(1) / a;
    float t5 = float(1) / r1;
    float t6 = float(1) / r0;
    float t7 = t5 * a_minus_b + b * t6;
    float t8 = float(1) / D;
    float t9 = t5 - t6 - b * t7 * t8;
    float t10 = c * t7 * t8 + float(2) * b * t4 * t9 - J1;
    F = si.w[3] * (c * t4 * t9 + (r1 + b * J1 - r0) * t4 - float(2) * b * t10 * t4) * t4 + t7 * si.w[0] * t8 - si.w[1] * t4 * t9 - t10 * si.w[2] * t4;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-3/2) dt
// Operations: 64 +, 133 *, 7 /, 5 sqrt, 0 atan, 1 log/asinh (generic form).
float segment_cauchy_i3_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = ab1 * bp1 + bp2 * ab2 + ab0 * bp0;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t1 = float(1) / D;
    float t2 = sqrt(a);
    X = (r1 * b + a_minus_b * r0) * t1 * t2;
  }
  float t3 = sqrt(a);
  float t4 = float(1) / t3;
  float J1 = skelconv_asinh(X) * t4;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t5 = float(1) / r0;
    float t6 = float(1) / r1;
    float t7 = b * t5 + a_minus_b * t6;
    float t8 = float(1) / D;
    float t9 = t5 + b * t7 * t8 - t6;
    float t10 = float(1) / a;
    float t11 = c * t7 * t8 - J1 - float(2) * b * t9 * t10;
    F = si.w[1] * t9 * t10 + t7 * t8 * si.w[0] - (float(2) * t11 * b * t10 + c * t9 * t10 - (r1 + b * J1 - r0) * t10) * si.w[3] * t10 - t11 * si.w[2] * t10;
    float t12 = t5 * t5;
    float t13 = t6 * t6;
    float t14 = b * t12 * t5 + a_minus_b * t6 * t13 + float(2) * t7 * t8 * a;
    float t15 = t6 * t13 - t14 * b * t8 - t12 * t5;
    float t16 = float(3) * t7 * t8 - float(2) * b * t15 * t10 - t14 * c * t8;
    G_ap = (float(1) / float(3)) * t14 * t8 * si.w[0] + (float(1) / float(3)) * (float(2) * b * t10 * t16 + float(3) * t9 * t10 + t15 * c * t10) * si.w[3] * t10 + (float(1) / float(3)) * si.w[2] * t10 * t16 - (float(1) / float(3)) * si.w[1] * t15 * t10;
    float t17 = t5 * t5;
    float t18 = t17 * t5;
    float t19 = t6 * t6;
    float t20 = t19 * t6;
    G_E = (float(1) / float(3)) * (float(2) * si.w[2] * t9 * t10 + t18 * si.w[0] + si.w[1] * t7 * t8 - t20 * (si.w[1] + si.w[2] + si.w[3] + si.w[0]) - float(3) * t11 * si.w[3] * t10) * t10;
  }
  float g_factor = -float(3) * length * si.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = (G_ap * foot1 - ab1 * G_E) * g_factor;
  grad[2] = -g_factor * (G_E * ab2 - foot2 * G_ap);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-4/2) dt
// Operations: 32 +, 41 *, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i4_w0_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  float ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, c_minus_b);
    float t2 = float(1) / D;
    F = (float(1) / float(2)) * si.w[0] * t2 * (a_minus_b / q1 + a * J2 + b / c);
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-4/2) dt
// Operations: 41 +, 75 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i4_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
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
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  float ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, c_minus_b);
    float t3 = float(1) / q1;
    float t4 = float(1) / c;
    float t5 = J2 * a + t3 * a_minus_b + t4 * b;
    float t6 = float(1) / D;
    F = (float(1) / float(2)) * t5 * si.w[0] * t6;
    float t7 = t4 * t4;
    float t8 = t3 * t3;
    G_ap = (float(1) / float(8)) * si.w[0] * (float(2) * t7 * b + float(2) * t8 * a_minus_b + float(3) * t5 * a * t6) * t6;
    G_E = -(float(1) / float(4)) * (t8 * si.w[0] - t7 * si.w[0]) / a;
  }
  float g_factor = -float(4) * length * si.s;
  f = F * length;
  grad[0] = (foot0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = (G_ap * foot1 - G_E * ab1) * g_factor;
  grad[2] = (G_ap * foot2 - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-4/2) dt
// Operations: 35 +, 47 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i4_w1_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  float ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = ap_bp * si.s + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, c_minus_b);
    float t2 = float(1) / c;
    float t3 = float(1) / q1;
    float t4 = b * t2 + t3 * a_minus_b + a * J2;
    float t5 = float(1) / D;
    F = (float(1) / float(2)) * t4 * t5 * si.w[0] + (float(1) / float(2)) * (t4 * t5 * b + t2 - t3) * si.w[1] / a;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-4/2) dt
// Operations: 49 +, 92 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i4_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  float ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
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
    foot0 = ap0 - t0 * ab0 * ab_ap;
    foot1 = ap1 - t0 * ab1 * ab_ap;
    foot2 = ap2 - ab2 * t0 * ab_ap;
  }
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, c_minus_b);
    float t3 = float(1) / q1;
    float t4 = float(1) / c;
    float t5 = J2 * a + a_minus_b * t3 + t4 * b;
    float t6 = float(1) / D;
    float t7 = float(1) / a;
    F = (float(1) / float(2)) * t5 * t6 * si.w[0] - (float(1) / float(2)) * si.w[1] * t7 * (t3 - t4 - t5 * t6 * b);
    float t8 = t4 * t4;
    float t9 = t3 * t3;
    float t10 = float(2) * t8 * b + float(3) * t5 * t6 * a + float(2) * a_minus_b * t9;
    G_ap = (float(1) / float(8)) * (float(2) * t8 + t6 * t10 * b - float(2) * t9) * si.w[1] * t7 + (float(1) / float(8)) * t6 * t10 * si.w[0];
    G_E = (float(1) / float(8)) * (t5 * si.w[1] * t6 + float(2) * t8 * si.w[0] - float(2) * (si.w[1] + si.w[0]) * t9) * t7;
  }
  float g_factor = -float(4) * si.s * length;
  f = F * length;
  grad[0] = -g_factor * (G_E * ab0 - foot0 * G_ap);
  grad[1] = (foot1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = (foot2 * G_ap - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-4/2) dt
// Operations: 38 +, 57 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i4_w2_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (ab_ab + si.s * cross_cross);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, c_minus_b);
    float t2 = float(1) / q1;
    float t3 = float(1) / c;
    float t4 = a * J2 + a_minus_b * t2 + t3 * b;
    float t5 = float(1) / D;
    float t6 = t2 - t4 * t5 * b - t3;
    float t7 = float(1) / a;
    F = (float(1) / float(2)) * t4 * t5 * si.w[0] - (float(1) / float(2)) * t6 * t7 * si.w[1] - (float(1) / float(2)) * si.w[2] * t7 * (float(2) * t6 * t7 * b + c * t4 * t5 - float(2) * J2);
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-4/2) dt
// Operations: 57 +, 114 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i4_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  float ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
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
    foot0 = ap0 - ab_ap * t0 * ab0;
    foot1 = ap1 - ab_ap * t0 * ab1;
    foot2 = ap2 - ab_ap * t0 * ab2;
  }
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  float ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (si.s * cross_cross + ab_ab) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = atan(t1, c_minus_b) * t2;
    float t3 = float(1) / c;
    float t4 = float(1) / q1;
    float t5 = t3 * b + t4 * a_minus_b + J2 * a;
    float t6 = float(1) / D;
    float t7 = t3 + t5 * t6 * b - t4;
    float t8 = float(1) / a;
    F = (float(1) / float(2)) * (float(2) * t7 * t8 * b + float(2) * J2 - c * t5 * t6) * si.w[2] * t8 + (float(1) / float(2)) * t5 * t6 * si.w[0] + (float(1) / float(2)) * si.w[1] * t7 * t8;
    float t9 = t4 * t4;
    float t10 = t3 * t3;
    float t11 = float(3) * t5 * t6 * a + float(2) * t9 * a_minus_b + float(2) * t10 * b;
    float t12 = t6 * t11 * b + float(2) * t10 - float(2) * t9;
    G_ap = (float(1) / float(8)) * si.w[2] * t8 * (float(4) * t5 * t6 + float(2) * t12 * t8 * b - c * t6 * t11) + (float(1) / float(8)) * t6 * t11 * si.w[0] + (float(1) / float(8)) * t12 * si.w[1] * t8;
    G_E = (float(1) / float(8)) * t8 * (float(2) * t7 * si.w[2] * t8 + float(2) * t10 * si.w[0] + si.w[1] * t5 * t6 - float(2) * t9 * (si.w[1] + si.w[2] + si.w[0]));
  }
  float g_factor = -float(4) * length * si.s;
  f = length * F;
  grad[0] = (foot0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = g_factor * (G_ap * foot1 - G_E * ab1);
  grad[2] = (G_ap * foot2 - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-4/2) dt
// Operations: 42 +, 69 *, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float segment_cauchy_i4_w3_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (cross_cross * si.s + ab_ab) * si.s;
  float a_minus_b = -ab_bp * si.s;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = ap_bp * si.s + float(1);
  float t0 = float(1) / c;
  float log_ratio = log(q1 * t0);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, c_minus_b);
    float t3 = float(1) / q1;
    float t4 = b * t0 + t3 * a_minus_b + a * J2;
    float t5 = float(1) / D;
    float t6 = float(1) / a;
    float t7 = t4 * t5 * b + t0 - t3;
    float t8 = float(2) * t6 * t7 * b + float(2) * J2 - t4 * t5 * c;
    F = (float(1) / float(2)) * t4 * t5 * si.w[0] + (float(1) / float(2)) * t8 * si.w[2] * t6 + (float(1) / float(2)) * (t6 * (float(2) * J2 * b + log_ratio) + float(2) * t8 * t6 * b - t6 * t7 * c) * t6 * si.w[3] + (float(1) / float(2)) * t6 * t7 * si.w[1];
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-4/2) dt
// Operations: 66 +, 139 *, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float segment_cauchy_i4_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
    foot2 = ap2 - ab2 * t0 * ab_ap;
  }
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  float ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = ap_bp * si.s + float(1);
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
    float t4 = float(1) / q1;
    float t5 = b * t1 + a_minus_b * t4 + a * J2;
    float t6 = float(1) / D;
    float t7 = float(1) / a;
    float t8 = b * t5 * t6 + t1 - t4;
    float t9 = t5 * c * t6 - float(2) * t7 * t8 * b - float(2) * J2;
    F = (float(1) / float(2)) * si.w[0] * t5 * t6 + (float(1) / float(2)) * t7 * t8 * si.w[1] - (float(1) / float(2)) * t7 * (float(2) * t7 * t9 * b + t7 * t8 * c - t7 * (log_ratio + float(2) * b * J2)) * si.w[3] - (float(1) / float(2)) * t7 * t9 * si.w[2];
    float t10 = t4 * t4;
    float t11 = t1 * t1;
    float t12 = float(3) * a * t5 * t6 + float(2) * a_minus_b * t10 + float(2) * b * t11;
    float t13 = float(2) * t10 - float(2) * t11 - t12 * b * t6;
    float t14 = t12 * c * t6 + float(2) * t7 * b * t13 - float(4) * t5 * t6;
    G_ap = (float(1) / float(8)) * si.w[0] * t12 * t6 + (float(1) / float(8)) * t7 * (t7 * c * t13 + float(4) * t7 * t8 - float(2) * t7 * b * t14) * si.w[3] - (float(1) / float(8)) * t7 * si.w[2] * t14 - (float(1) / float(8)) * t7 * si.w[1] * t13;
    G_E = (float(1) / float(8)) * t7 * (float(2) * si.w[0] * t11 + si.w[1] * t5 * t6 + float(2) * t7 * t8 * si.w[2] - float(3) * t7 * t9 * si.w[3] - float(2) * t10 * (si.w[0] + si.w[1] + si.w[2] + si.w[3]));
  }
  float g_factor = -float(4) * length * si.s;
  f = F * length;
  grad[0] = (foot0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = -(ab1 * G_E - G_ap * foot1) * g_factor;
  grad[2] = -(ab2 * G_E - foot2 * G_ap) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-5/2) dt
// Operations: 30 +, 42 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i5_w0_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  float ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
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
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (cross_cross * si.s + ab_ab) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / r0;
    float t1 = float(1) / r1;
    float t2 = float(1) / D;
    F = (float(1) / float(3)) * (t0 * b / c + t1 * a_minus_b / q1 + float(2) * (t1 * a_minus_b + t0 * b) * t2 * a) * si.w[0] * t2;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-5/2) dt
// Operations: 39 +, 86 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i5_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  float ab_ap = ab1 * ap1 + ab0 * ap0 + ap2 * ab2;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ab1 * ap2 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
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
    foot0 = ap0 - ab0 * ab_ap * t0;
    foot1 = ap1 - ab1 * ab_ap * t0;
    foot2 = ap2 - ab_ap * t0 * ab2;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (cross_cross * si.s + ab_ab) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / r1;
    float t2 = float(1) / r0;
    float t3 = float(1) / D;
    float t4 = t2 * t2;
    float t5 = t1 * t1;
    float t6 = float(2) * a * (a_minus_b * t1 + b * t2) * t3 + b * t4 * t2 + a_minus_b * t5 * t1;
    F = (float(1) / float(3)) * si.w[0] * t6 * t3;
    float t7 = t4 * t4;
    float t8 = t5 * t5;
    G_ap = (float(1) / float(15)) * si.w[0] * t3 * (float(3) * b * t7 * t2 + float(4) * t6 * a * t3 + float(3) * a_minus_b * t8 * t1);
    float t9 = t1 * t1;
    float t10 = t9 * t9;
    float t11 = t10 * t1;
    float t12 = t2 * t2;
    float t13 = t12 * t12;
    float t14 = t13 * t2;
    G_E = -(float(1) / float(5)) * (si.w[0] * t11 - si.w[0] * t14) / a;
  }
  float g_factor = -float(5) * length * si.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = -(ab1 * G_E - G_ap * foot1) * g_factor;
  grad[2] = -(G_E * ab2 - foot2 * G_ap) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-5/2) dt
// Operations: 33 +, 52 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i5_w1_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (ab_ab + cross_cross * si.s);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / D;
    float t1 = float(1) / r0;
    float t2 = t1 * t1;
    float t3 = float(1) / r1;
    float t4 = t3 * t3;
    float t5 = t1 * b * t2 + t3 * a_minus_b * t4 + float(2) * t0 * a * (t1 * b + t3 * a_minus_b);
    F = (float(1) / float(3)) * t0 * t5 * si.w[0] - (float(1) / float(3)) * si.w[1] * (t3 * t4 - t0 * t5 * b - t1 * t2) / a;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-5/2) dt
// Operations: 47 +, 107 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i5_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp2 * ab2 + ab0 * bp0 + ab1 * bp1;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (ab_ab + cross_cross * si.s);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / r1;
    float t2 = t1 * t1;
    float t3 = float(1) / r0;
    float t4 = t3 * t3;
    float t5 = float(1) / D;
    float t6 = a_minus_b * t1 * t2 + b * t4 * t3 + float(2) * t5 * a * (a_minus_b * t1 + b * t3);
    float t7 = float(1) / a;
    F = (float(1) / float(3)) * (t6 * b * t5 + t4 * t3 - t1 * t2) * si.w[1] * t7 + (float(1) / float(3)) * t6 * si.w[0] * t5;
    float t8 = t4 * t4;
    float t9 = t2 * t2;
    float t10 = float(3) * b * t8 * t3 + float(4) * t6 * t5 * a + float(3) * a_minus_b * t1 * t9;
    G_ap = (float(1) / float(15)) * si.w[1] * (float(3) * t8 * t3 + b * t10 * t5 - float(3) * t1 * t9) * t7 + (float(1) / float(15)) * si.w[0] * t10 * t5;
    float t11 = t1 * t1;
    float t12 = t11 * t11;
    float t13 = t12 * t1;
    float t14 = t3 * t3;
    float t15 = t14 * t14;
    float t16 = t15 * t3;
    G_E = -(float(1) / float(15)) * (float(3) * t13 * (si.w[0] + si.w[1]) - t6 * si.w[1] * t5 - float(3) * si.w[0] * t16) * t7;
  }
  float g_factor = -float(5) * length * si.s;
  f = F * length;
  grad[0] = (foot0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = (G_ap * foot1 - ab1 * G_E) * g_factor;
  grad[2] = (foot2 * G_ap - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-5/2) dt
// Operations: 36 +, 63 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i5_w2_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -ab_bp * si.s;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / r0;
    float t1 = t0 * t0;
    float t2 = float(1) / D;
    float t3 = float(1) / r1;
    float t4 = b * t0 + t3 * a_minus_b;
    float t5 = t3 * t3;
    float t6 = float(2) * t2 * a * t4 + t3 * a_minus_b * t5 + b * t1 * t0;
    float t7 = t1 * t0 + t6 * b * t2 - t3 * t5;
    float t8 = float(1) / a;
    F = (float(1) / float(3)) * si.w[1] * t7 * t8 + (float(1) / float(3)) * t6 * t2 * si.w[0] - (float(1) / float(3)) * si.w[2] * t8 * (t6 * c * t2 - float(2) * b * t7 * t8 - float(3) * t2 * t4);
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-5/2) dt
// Operations: 55 +, 130 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i5_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / a;
    float t2 = float(1) / r0;
    float t3 = t2 * t2;
    float t4 = float(1) / r1;
    float t5 = t4 * t4;
    float t6 = float(1) / D;
    float t7 = t2 * b + t4 * a_minus_b;
    float t8 = t5 * t4 * a_minus_b + float(2) * t6 * a * t7 + t2 * t3 * b;
    float t9 = t2 * t3 + t8 * t6 * b - t5 * t4;
    F = (float(1) / float(3)) * si.w[1] * t1 * t9 + (float(1) / float(3)) * si.w[2] * t1 * (float(2) * t1 * t9 * b + float(3) * t6 * t7 - c * t8 * t6) + (float(1) / float(3)) * t8 * t6 * si.w[0];
    float t10 = t3 * t3;
    float t11 = t5 * t5;
    float t12 = float(4) * t8 * t6 * a + float(3) * t2 * t10 * b + float(3) * t11 * t4 * a_minus_b;
    float t13 = float(3) * t11 * t4 - t6 * b * t12 - float(3) * t2 * t10;
    G_ap = (float(1) / float(15)) * t6 * si.w[0] * t12 - (float(1) / float(15)) * si.w[2] * (float(2) * t1 * t13 * b + c * t6 * t12 - float(5) * t8 * t6) * t1 - (float(1) / float(15)) * si.w[1] * t1 * t13;
    float t14 = t2 * t2;
    float t15 = t14 * t14;
    float t16 = t15 * t2;
    float t17 = t4 * t4;
    float t18 = t17 * t17;
    float t19 = t18 * t4;
    G_E = (float(1) / float(15)) * (si.w[1] * t8 * t6 + float(3) * t16 * si.w[0] + float(2) * si.w[2] * t1 * t9 - float(3) * (si.w[1] + si.w[2] + si.w[0]) * t19) * t1;
  }
  float g_factor = -float(5) * si.s * length;
  f = F * length;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = g_factor * (G_ap * foot1 - G_E * ab1);
  grad[2] = g_factor * (G_ap * foot2 - G_E * ab2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-5/2) dt
// Operations: 41 +, 75 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i5_w3_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  float ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
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
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (ab_ab + si.s * cross_cross);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / r0;
    float t1 = t0 * t0;
    float t2 = float(1) / r1;
    float t3 = t2 * t2;
    float t4 = float(1) / D;
    float t5 = a_minus_b * t2 + t0 * b;
    float t6 = t1 * t0 * b + a_minus_b * t3 * t2 + float(2) * t4 * a * t5;
    float t7 = t6 * t4 * b + t1 * t0 - t3 * t2;
    float t8 = float(1) / a;
    float t9 = float(2) * t7 * t8 * b + float(3) * t4 * t5 - c * t6 * t4;
    F = (float(1) / float(3)) * t9 * t8 * si.w[2] + (float(1) / float(3)) * t7 * t8 * si.w[1] + (float(1) / float(3)) * t6 * si.w[0] * t4 - (float(1) / float(3)) * (float(3) * t8 * (t2 - t4 * t5 * b - t0) + c * t7 * t8 - float(2) * t9 * t8 * b) * si.w[3] * t8;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-5/2) dt
// Operations: 65 +, 155 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i5_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -ab_bp * si.s;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / a;
    float t2 = float(1) / D;
    float t3 = float(1) / r0;
    float t4 = t3 * t3;
    float t5 = float(1) / r1;
    float t6 = t5 * t5;
    float t7 = t5 * a_minus_b + t3 * b;
    float t8 = t4 * t3 * b + t5 * a_minus_b * t6 + float(2) * a * t2 * t7;
    float t9 = t2 * t8 * b + t4 * t3 - t5 * t6;
    float t10 = float(3) * t2 * t7 + float(2) * t1 * t9 * b - c * t2 * t8;
    F = (float(1) / float(3)) * t1 * t9 * si.w[1] + (float(1) / float(3)) * t1 * t10 * si.w[2] + (float(1) / float(3)) * si.w[0] * t2 * t8 - (float(1) / float(3)) * si.w[3] * (c * t1 * t9 + float(3) * t1 * (t5 - t2 * b * t7 - t3) - float(2) * t1 * t10 * b) * t1;
    float t11 = t6 * t6;
    float t12 = t4 * t4;
    float t13 = float(3) * t5 * a_minus_b * t11 + float(4) * a * t2 * t8 + float(3) * t12 * t3 * b;
    float t14 = float(3) * t5 * t11 - float(3) * t12 * t3 - t2 * b * t13;
    float t15 = float(2) * t1 * b * t14 + c * t2 * t13 - float(5) * t2 * t8;
    G_ap = (float(1) / float(15)) * si.w[0] * t2 * t13 - (float(1) / float(15)) * t1 * si.w[1] * t14 - (float(1) / float(15)) * si.w[3] * t1 * (float(2) * t1 * b * t15 - float(5) * t1 * t9 - c * t1 * t14) - (float(1) / float(15)) * t1 * si.w[2] * t15;
    float t16 = t3 * t3;
    float t17 = t16 * t16;
    float t18 = t17 * t3;
    float t19 = t5 * t5;
    float t20 = t19 * t19;
    float t21 = t20 * t5;
    G_E = (float(1) / float(15)) * (float(2) * t1 * t9 * si.w[2] + t2 * si.w[1] * t8 + float(3) * si.w[3] * t1 * t10 + float(3) * si.w[0] * t18 - float(3) * (si.w[3] + si.w[0] + si.w[1] + si.w[2]) * t21) * t1;
  }
  float g_factor = -float(5) * length * si.s;
  f = F * length;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = (foot1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = -g_factor * (G_E * ab2 - foot2 * G_ap);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-6/2) dt
// Operations: 34 +, 52 *, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i6_w0_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  float ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
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
  float bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = atan(t0, c_minus_b) * t1;
    float t2 = float(1) / c;
    float t3 = float(1) / q1;
    float t4 = float(1) / D;
    float t5 = t3 * t3;
    float t6 = t2 * t2;
    F = (float(1) / float(8)) * (float(3) * (b * t2 + a * J2 + a_minus_b * t3) * t4 * a + float(2) * a_minus_b * t5 + float(2) * b * t6) * si.w[0] * t4;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-6/2) dt
// Operations: 43 +, 84 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i6_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
    foot0 = ap0 - ab0 * t0 * ab_ap;
    foot1 = ap1 - ab1 * t0 * ab_ap;
    foot2 = ap2 - ab2 * t0 * ab_ap;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  float ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = ap_bp * si.s + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, c_minus_b);
    float t3 = float(1) / D;
    float t4 = float(1) / q1;
    float t5 = t4 * t4;
    float t6 = float(1) / c;
    float t7 = t6 * t6;
    float t8 = float(2) * a_minus_b * t5 + float(3) * t3 * a * (b * t6 + a * J2 + a_minus_b * t4) + float(2) * b * t7;
    F = (float(1) / float(8)) * t3 * t8 * si.w[0];
    float t9 = t5 * t4;
    float t10 = t7 * t6;
    G_ap = (float(1) / float(48)) * t3 * (float(8) * a_minus_b * t9 + float(5) * t3 * a * t8 + float(8) * b * t10) * si.w[0];
    G_E = (float(1) / float(6)) * (t10 * si.w[0] - t9 * si.w[0]) / a;
  }
  float g_factor = -float(6) * length * si.s;
  f = F * length;
  grad[0] = g_factor * (foot0 * G_ap - ab0 * G_E);
  grad[1] = -g_factor * (ab1 * G_E - G_ap * foot1);
  grad[2] = g_factor * (foot2 * G_ap - ab2 * G_E);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-6/2) dt
// Operations: 37 +, 58 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i6_w1_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab1 * ap1 + ap0 * ab0 + ab2 * ap2;
  float ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ap0 * ab1;
  float plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = atan(t0, c_minus_b) * t1;
    float t2 = float(1) / c;
    float t3 = t2 * t2;
    float t4 = float(1) / q1;
    float t5 = t4 * t4;
    float t6 = float(1) / D;
    float t7 = float(2) * a_minus_b * t5 + float(2) * t3 * b + float(3) * (a * J2 + t2 * b + a_minus_b * t4) * a * t6;
    F = (float(1) / float(8)) * si.w[1] * (float(2) * t3 + t7 * t6 * b - float(2) * t5) / a + (float(1) / float(8)) * si.w[0] * t7 * t6;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-6/2) dt
// Operations: 51 +, 103 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i6_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
  float ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (cross_cross * si.s + ab_ab) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = atan(t1, c_minus_b) * t2;
    float t3 = float(1) / q1;
    float t4 = float(1) / c;
    float t5 = float(1) / D;
    float t6 = t4 * t4;
    float t7 = t3 * t3;
    float t8 = float(3) * (a_minus_b * t3 + b * t4 + J2 * a) * t5 * a + float(2) * b * t6 + float(2) * a_minus_b * t7;
    float t9 = float(1) / a;
    F = (float(1) / float(8)) * (t8 * b * t5 + float(2) * t6 - float(2) * t7) * si.w[1] * t9 + (float(1) / float(8)) * t8 * si.w[0] * t5;
    float t10 = t6 * t4;
    float t11 = t7 * t3;
    float t12 = float(5) * t8 * t5 * a + float(8) * b * t10 + float(8) * a_minus_b * t11;
    G_ap = (float(1) / float(48)) * (b * t5 * t12 + float(8) * t10 - float(8) * t11) * si.w[1] * t9 + (float(1) / float(48)) * si.w[0] * t5 * t12;
    G_E = (float(1) / float(48)) * (t8 * si.w[1] * t5 + float(8) * si.w[0] * t10 - float(8) * t11 * (si.w[0] + si.w[1])) * t9;
  }
  float g_factor = -float(6) * length * si.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = -g_factor * (G_E * ab1 - G_ap * foot1);
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-6/2) dt
// Operations: 40 +, 69 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i6_w2_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
  float ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (cross_cross * si.s + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = atan(t0, c_minus_b) * t1;
    float t2 = float(1) / c;
    float t3 = t2 * t2;
    float t4 = float(1) / q1;
    float t5 = t4 * t4;
    float t6 = b * t2 + a_minus_b * t4 + J2 * a;
    float t7 = float(1) / D;
    float t8 = float(2) * a_minus_b * t5 + float(3) * t6 * t7 * a + float(2) * b * t3;
    float t9 = float(2) * t3 + b * t8 * t7 - float(2) * t5;
    float t10 = float(1) / a;
    F = (float(1) / float(8)) * t9 * si.w[1] * t10 + (float(1) / float(8)) * si.w[0] * t8 * t7 + (float(1) / float(8)) * si.w[2] * t10 * (float(2) * b * t9 * t10 + float(4) * t6 * t7 - t8 * c * t7);
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-6/2) dt
// Operations: 59 +, 126 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i6_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  float ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ap0 * ab1;
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
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -ab_bp * si.s;
  float q1 = si.s * bp_bp + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = atan(t1, c_minus_b) * t2;
    float t3 = float(1) / c;
    float t4 = float(1) / q1;
    float t5 = t3 * b + J2 * a + t4 * a_minus_b;
    float t6 = float(1) / D;
    float t7 = t3 * t3;
    float t8 = t4 * t4;
    float t9 = float(3) * t5 * t6 * a + float(2) * t8 * a_minus_b + float(2) * t7 * b;
    float t10 = float(2) * t7 + t9 * t6 * b - float(2) * t8;
    float t11 = float(1) / a;
    F = (float(1) / float(8)) * (float(4) * t5 * t6 + float(2) * t10 * t11 * b - c * t9 * t6) * si.w[2] * t11 + (float(1) / float(8)) * t9 * t6 * si.w[0] + (float(1) / float(8)) * si.w[1] * t10 * t11;
    float t12 = t7 * t3;
    float t13 = t8 * t4;
    float t14 = float(8) * t12 * b + float(8) * t13 * a_minus_b + float(5) * t9 * t6 * a;
    float t15 = float(8) * t12 + t6 * t14 * b - float(8) * t13;
    G_ap = (float(1) / float(48)) * si.w[1] * t15 * t11 + (float(1) / float(48)) * t6 * t14 * si.w[0] + (float(1) / float(48)) * (float(2) * t15 * t11 * b + float(6) * t9 * t6 - c * t6 * t14) * si.w[2] * t11;
    G_E = (float(1) / float(48)) * (float(8) * t12 * si.w[0] + si.w[1] * t9 * t6 + float(2) * si.w[2] * t10 * t11 - float(8) * t13 * (si.w[1] + si.w[2] + si.w[0])) * t11;
  }
  float g_factor = -float(6) * si.s * length;
  f = F * length;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = g_factor * (G_ap * foot1 - G_E * ab1);
  grad[2] = g_factor * (G_ap * foot2 - G_E * ab2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-6/2) dt
// Operations: 45 +, 81 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i6_w3_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  float ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (ab_ab + cross_cross * si.s);
  float a_minus_b = -ab_bp * si.s;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = ap_bp * si.s + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, c_minus_b);
    float t2 = float(1) / D;
    float t3 = float(1) / q1;
    float t4 = float(1) / c;
    float t5 = t3 * a_minus_b + b * t4 + a * J2;
    float t6 = t3 * t3;
    float t7 = t4 * t4;
    float t8 = float(3) * t2 * a * t5 + float(2) * t6 * a_minus_b + float(2) * b * t7;
    float t9 = float(1) / a;
    float t10 = float(2) * t6 - t2 * b * t8 - float(2) * t7;
    float t11 = t2 * t8 * c + float(2) * t9 * b * t10 - float(4) * t2 * t5;
    F = (float(1) / float(8)) * si.w[0] * t2 * t8 - (float(1) / float(8)) * t9 * (float(2) * t9 * t11 * b - float(4) * t9 * (t4 + t2 * b * t5 - t3) - t9 * t10 * c) * si.w[3] - (float(1) / float(8)) * t9 * t11 * si.w[2] - (float(1) / float(8)) * t9 * si.w[1] * t10;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-6/2) dt
// Operations: 69 +, 151 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i6_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
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
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  float ap_bp = bp2 * ap2 + bp0 * ap0 + bp1 * ap1;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (cross_cross * si.s + ab_ab) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = ap_bp * si.s + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = atan(t1, c_minus_b) * t2;
    float t3 = float(1) / D;
    float t4 = float(1) / q1;
    float t5 = float(1) / c;
    float t6 = a_minus_b * t4 + b * t5 + J2 * a;
    float t7 = t5 * t5;
    float t8 = t4 * t4;
    float t9 = float(3) * t3 * a * t6 + float(2) * b * t7 + float(2) * a_minus_b * t8;
    float t10 = t3 * b * t9 + float(2) * t7 - float(2) * t8;
    float t11 = float(1) / a;
    float t12 = float(2) * t10 * t11 * b + float(4) * t3 * t6 - t3 * t9 * c;
    F = (float(1) / float(8)) * t10 * t11 * si.w[1] + (float(1) / float(8)) * t3 * si.w[0] * t9 + (float(1) / float(8)) * si.w[3] * t11 * (float(2) * t12 * t11 * b + float(4) * t11 * (t5 + t3 * t6 * b - t4) - t10 * t11 * c) + (float(1) / float(8)) * t12 * t11 * si.w[2];
    float t13 = t8 * t4;
    float t14 = t7 * t5;
    float t15 = float(5) * t3 * a * t9 + float(8) * a_minus_b * t13 + float(8) * b * t14;
    float t16 = float(8) * t13 - t3 * b * t15 - float(8) * t14;
    float t17 = float(2) * t16 * t11 * b + t3 * c * t15 - float(6) * t3 * t9;
    G_ap = (float(1) / float(48)) * t3 * si.w[0] * t15 - (float(1) / float(48)) * t11 * si.w[2] * t17 - (float(1) / float(48)) * t16 * t11 * si.w[1] - (float(1) / float(48)) * si.w[3] * t11 * (float(2) * t11 * b * t17 - float(6) * t10 * t11 - t16 * t11 * c);
    G_E = (float(1) / float(48)) * t11 * (float(8) * si.w[0] * t14 + t3 * si.w[1] * t9 + float(2) * t10 * t11 * si.w[2] + float(3) * si.w[3] * t12 * t11 - float(8) * (si.w[3] + si.w[0] + si.w[1] + si.w[2]) * t13);
  }
  float g_factor = -float(6) * length * si.s;
  f = F * length;
  grad[0] = -(G_E * ab0 - foot0 * G_ap) * g_factor;
  grad[1] = -(G_E * ab1 - foot1 * G_ap) * g_factor;
  grad[2] = (foot2 * G_ap - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-7/2) dt
// Operations: 32 +, 57 *, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i7_w0_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = ab2 * bp2 + bp0 * ab0 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -ab_bp * si.s;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / D;
    float t1 = float(1) / r1;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = float(1) / r0;
    float t5 = t4 * t4;
    float t6 = t5 * t5;
    F = (float(1) / float(15)) * si.w[0] * t0 * (float(3) * t3 * t1 * a_minus_b + float(4) * a * t0 * (t4 * b * t5 + float(2) * a * t0 * (t1 * a_minus_b + t4 * b) + t2 * t1 * a_minus_b) + float(3) * t4 * b * t6);
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-7/2) dt
// Operations: 41 +, 99 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i7_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = ab2 * bp2 + bp0 * ab0 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (cross_cross * si.s + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / D;
    float t2 = float(1) / r1;
    float t3 = float(1) / r0;
    float t4 = t2 * t2;
    float t5 = t3 * t3;
    float t6 = t5 * t5;
    float t7 = t4 * t4;
    float t8 = float(4) * a * t1 * (float(2) * (t2 * a_minus_b + t3 * b) * a * t1 + t2 * a_minus_b * t4 + t3 * b * t5) + float(3) * t3 * b * t6 + float(3) * t2 * a_minus_b * t7;
    F = (float(1) / float(15)) * si.w[0] * t8 * t1;
    float t9 = t6 * t5;
    float t10 = t7 * t4;
    G_ap = (float(1) / float(35)) * si.w[0] * t1 * (float(5) * t3 * b * t9 + float(5) * t2 * a_minus_b * t10 + float(2) * t8 * a * t1);
    float t11 = t3 * t3;
    float t12 = t11 * t3;
    float t13 = t12 * t12;
    float t14 = t13 * t3;
    float t15 = t2 * t2;
    float t16 = t15 * t2;
    float t17 = t16 * t16;
    float t18 = t17 * t2;
    G_E = (float(1) / float(7)) * (si.w[0] * t14 - si.w[0] * t18) / a;
  }
  float g_factor = -float(7) * length * si.s;
  f = F * length;
  grad[0] = (foot0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = -(G_E * ab1 - foot1 * G_ap) * g_factor;
  grad[2] = (foot2 * G_ap - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-7/2) dt
// Operations: 35 +, 65 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i7_w1_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (ab_ab + si.s * cross_cross);
  float a_minus_b = -ab_bp * si.s;
  float q1 = si.s * bp_bp + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / D;
    float t1 = float(1) / r1;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = float(1) / r0;
    float t5 = t4 * t4;
    float t6 = t5 * t5;
    float t7 = float(3) * t3 * t1 * a_minus_b + float(3) * t6 * t4 * b + float(4) * (float(2) * (t4 * b + t1 * a_minus_b) * t0 * a + t5 * t4 * b + t2 * t1 * a_minus_b) * t0 * a;
    F = (float(1) / float(15)) * t0 * t7 * si.w[0] - (float(1) / float(15)) * (float(3) * t3 * t1 - t0 * t7 * b - float(3) * t6 * t4) * si.w[1] / a;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-7/2) dt
// Operations: 49 +, 122 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i7_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -ab_bp * si.s;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / a;
    float t2 = float(1) / r0;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = float(1) / D;
    float t6 = float(1) / r1;
    float t7 = t6 * t6;
    float t8 = t7 * t7;
    float t9 = float(3) * t6 * a_minus_b * t8 + float(3) * t2 * b * t4 + float(4) * t5 * a * (float(2) * t5 * a * (t2 * b + t6 * a_minus_b) + t2 * b * t3 + t6 * a_minus_b * t7);
    F = (float(1) / float(15)) * si.w[1] * t1 * (float(3) * t2 * t4 + t5 * t9 * b - float(3) * t6 * t8) + (float(1) / float(15)) * t5 * t9 * si.w[0];
    float t10 = t8 * t7;
    float t11 = t4 * t3;
    float t12 = float(5) * t6 * a_minus_b * t10 + float(2) * t5 * a * t9 + float(5) * t2 * b * t11;
    G_ap = (float(1) / float(35)) * (t12 * t5 * b + float(5) * t2 * t11 - float(5) * t6 * t10) * si.w[1] * t1 + (float(1) / float(35)) * t12 * t5 * si.w[0];
    float t13 = t2 * t2;
    float t14 = t13 * t2;
    float t15 = t14 * t14;
    float t16 = t15 * t2;
    float t17 = t6 * t6;
    float t18 = t17 * t6;
    float t19 = t18 * t18;
    float t20 = t19 * t6;
    G_E = (float(1) / float(105)) * t1 * (float(15) * t16 * si.w[0] + si.w[1] * t5 * t9 - float(15) * t20 * (si.w[1] + si.w[0]));
  }
  float g_factor = -float(7) * length * si.s;
  f = F * length;
  grad[0] = -g_factor * (G_E * ab0 - foot0 * G_ap);
  grad[1] = -g_factor * (G_E * ab1 - foot1 * G_ap);
  grad[2] = (foot2 * G_ap - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-7/2) dt
// Operations: 38 +, 76 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i7_w2_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ap0 * ab0 + ab2 * ap2 + ap1 * ab1;
  float ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  float plain_cross0 = ab1 * ap2 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
  float plain_cross2 = ap1 * ab0 - ap0 * ab1;
  float plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (ab_ab + si.s * cross_cross);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / D;
    float t1 = float(1) / r0;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = float(1) / r1;
    float t5 = t4 * t4;
    float t6 = t4 * a_minus_b * t5 + float(2) * (b * t1 + t4 * a_minus_b) * t0 * a + b * t2 * t1;
    float t7 = t5 * t5;
    float t8 = float(3) * b * t3 * t1 + float(4) * t6 * t0 * a + float(3) * t4 * a_minus_b * t7;
    float t9 = float(3) * t4 * t7 - float(3) * t3 * t1 - b * t0 * t8;
    float t10 = float(1) / a;
    F = (float(1) / float(15)) * t0 * t8 * si.w[0] - (float(1) / float(15)) * (c * t0 * t8 + float(2) * b * t9 * t10 - float(5) * t6 * t0) * si.w[2] * t10 - (float(1) / float(15)) * si.w[1] * t9 * t10;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-7/2) dt
// Operations: 57 +, 146 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i7_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (ab_ab + si.s * cross_cross);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / r0;
    float t2 = t1 * t1;
    float t3 = float(1) / r1;
    float t4 = t3 * t3;
    float t5 = float(1) / D;
    float t6 = t2 * t1 * b + t3 * a_minus_b * t4 + float(2) * (t3 * a_minus_b + t1 * b) * t5 * a;
    float t7 = t4 * t4;
    float t8 = t2 * t2;
    float t9 = float(4) * t6 * t5 * a + float(3) * t3 * a_minus_b * t7 + float(3) * t8 * t1 * b;
    float t10 = float(1) / a;
    float t11 = float(3) * t3 * t7 - t9 * t5 * b - float(3) * t8 * t1;
    F = (float(1) / float(15)) * t9 * t5 * si.w[0] - (float(1) / float(15)) * si.w[1] * t10 * t11 - (float(1) / float(15)) * si.w[2] * t10 * (t9 * c * t5 + float(2) * t10 * t11 * b - float(5) * t6 * t5);
    float t12 = t7 * t4;
    float t13 = t8 * t2;
    float t14 = float(5) * t3 * a_minus_b * t12 + float(5) * t13 * t1 * b + float(2) * t9 * t5 * a;
    float t15 = t5 * t14 * b + float(5) * t13 * t1 - float(5) * t3 * t12;
    G_ap = (float(1) / float(105)) * (float(7) * t9 * t5 + float(6) * t10 * b * t15 - float(3) * c * t5 * t14) * si.w[2] * t10 + (float(1) / float(35)) * si.w[1] * t10 * t15 + (float(1) / float(35)) * t5 * si.w[0] * t14;
    float t16 = t1 * t1;
    float t17 = t16 * t1;
    float t18 = t17 * t17;
    float t19 = t18 * t1;
    float t20 = t3 * t3;
    float t21 = t20 * t3;
    float t22 = t21 * t21;
    float t23 = t22 * t3;
    G_E = (float(1) / float(105)) * (float(15) * t19 * si.w[0] + t9 * si.w[1] * t5 - float(15) * t23 * (si.w[1] + si.w[2] + si.w[0]) - float(2) * si.w[2] * t10 * t11) * t10;
  }
  float g_factor = -float(7) * si.s * length;
  f = F * length;
  grad[0] = -(G_E * ab0 - G_ap * foot0) * g_factor;
  grad[1] = -(G_E * ab1 - G_ap * foot1) * g_factor;
  grad[2] = (G_ap * foot2 - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-7/2) dt
// Operations: 43 +, 90 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i7_w3_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (cross_cross * si.s + ab_ab) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / D;
    float t1 = float(1) / r1;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = float(1) / r0;
    float t5 = t4 * t4;
    float t6 = t5 * t5;
    float t7 = float(2) * (t1 * a_minus_b + t4 * b) * t0 * a + t4 * b * t5 + t1 * a_minus_b * t2;
    float t8 = float(3) * t1 * a_minus_b * t3 + float(3) * t4 * b * t6 + float(4) * t7 * t0 * a;
    float t9 = b * t0 * t8 + float(3) * t4 * t6 - float(3) * t1 * t3;
    float t10 = float(1) / a;
    float t11 = float(5) * t7 * t0 + float(2) * b * t9 * t10 - c * t0 * t8;
    F = (float(1) / float(15)) * si.w[1] * t9 * t10 + (float(1) / float(15)) * si.w[2] * t11 * t10 + (float(1) / float(15)) * (float(2) * b * t11 * t10 - c * t9 * t10 - float(5) * (t1 * t2 - b * t7 * t0 - t4 * t5) * t10) * si.w[3] * t10 + (float(1) / float(15)) * si.w[0] * t0 * t8;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-7/2) dt
// Operations: 67 +, 174 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i7_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (ab_ab + si.s * cross_cross);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / r0;
    float t2 = t1 * t1;
    float t3 = float(1) / r1;
    float t4 = float(1) / D;
    float t5 = t3 * t3;
    float t6 = t2 * t1 * b + float(2) * (t3 * a_minus_b + t1 * b) * a * t4 + t5 * t3 * a_minus_b;
    float t7 = t5 * t5;
    float t8 = t2 * t2;
    float t9 = float(4) * a * t6 * t4 + float(3) * t7 * t3 * a_minus_b + float(3) * t8 * t1 * b;
    float t10 = t9 * t4 * b + float(3) * t8 * t1 - float(3) * t7 * t3;
    float t11 = float(1) / a;
    float t12 = c * t9 * t4 - float(5) * t6 * t4 - float(2) * t10 * t11 * b;
    F = (float(1) / float(15)) * si.w[0] * t9 * t4 + (float(1) / float(15)) * t10 * t11 * si.w[1] - (float(1) / float(15)) * si.w[3] * t11 * (float(5) * t11 * (t5 * t3 - t2 * t1 - t6 * t4 * b) + float(2) * t12 * t11 * b + t10 * c * t11) - (float(1) / float(15)) * si.w[2] * t12 * t11;
    float t13 = t7 * t5;
    float t14 = t8 * t2;
    float t15 = float(5) * t14 * t1 * b + float(2) * a * t9 * t4 + float(5) * t13 * t3 * a_minus_b;
    float t16 = float(5) * t13 * t3 - t15 * t4 * b - float(5) * t14 * t1;
    float t17 = float(6) * t11 * t16 * b + float(3) * t15 * c * t4 - float(7) * t9 * t4;
    G_ap = (float(1) / float(105)) * (float(7) * t10 * t11 + float(3) * c * t11 * t16 - float(2) * t17 * t11 * b) * si.w[3] * t11 + (float(1) / float(35)) * t15 * si.w[0] * t4 - (float(1) / float(35)) * t11 * t16 * si.w[1] - (float(1) / float(105)) * si.w[2] * t17 * t11;
    float t18 = t3 * t3;
    float t19 = t18 * t3;
    float t20 = t19 * t19;
    float t21 = t20 * t3;
    float t22 = t1 * t1;
    float t23 = t22 * t1;
    float t24 = t23 * t23;
    float t25 = t24 * t1;
    G_E = -(float(1) / float(105)) * (float(3) * si.w[3] * t12 * t11 + float(15) * (si.w[2] + si.w[3] + si.w[0] + si.w[1]) * t21 - t9 * t4 * si.w[1] - float(2) * si.w[2] * t10 * t11 - float(15) * si.w[0] * t25) * t11;
  }
  float g_factor = -float(7) * length * si.s;
  f = F * length;
  grad[0] = -g_factor * (G_E * ab0 - foot0 * G_ap);
  grad[1] = g_factor * (G_ap * foot1 - G_E * ab1);
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-8/2) dt
// Operations: 36 +, 61 *, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i8_w0_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = ab2 * bp2 + bp0 * ab0 + bp1 * ab1;
  float ap_bp = ap2 * bp2 + bp1 * ap1 + bp0 * ap0;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -ab_bp * si.s;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = ap_bp * si.s + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = atan(t0, c_minus_b) * t1;
    float t2 = float(1) / D;
    float t3 = float(1) / q1;
    float t4 = t3 * t3;
    float t5 = t4 * t3;
    float t6 = float(1) / c;
    float t7 = t6 * t6;
    float t8 = t7 * t6;
    F = (float(1) / float(48)) * si.w[0] * t2 * (float(8) * t5 * a_minus_b + float(5) * a * t2 * (float(2) * t4 * a_minus_b + float(2) * b * t7 + float(3) * (a * J2 + b * t6 + t3 * a_minus_b) * a * t2) + float(8) * b * t8);
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-8/2) dt
// Operations: 45 +, 93 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i8_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  float ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
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
    foot0 = ap0 - ab0 * t0 * ab_ap;
    foot1 = ap1 - t0 * ab1 * ab_ap;
    foot2 = ap2 - t0 * ab2 * ab_ap;
  }
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  float ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = atan(t1, c_minus_b) * t2;
    float t3 = float(1) / D;
    float t4 = float(1) / q1;
    float t5 = t4 * t4;
    float t6 = t5 * t4;
    float t7 = float(1) / c;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = float(8) * t6 * a_minus_b + float(5) * (float(2) * t5 * a_minus_b + float(2) * t8 * b + float(3) * a * t3 * (t7 * b + J2 * a + t4 * a_minus_b)) * a * t3 + float(8) * t9 * b;
    F = (float(1) / float(48)) * si.w[0] * t3 * t10;
    float t11 = t8 * t8;
    float t12 = t5 * t5;
    G_ap = (float(1) / float(384)) * si.w[0] * t3 * (float(48) * t11 * b + float(7) * a * t3 * t10 + float(48) * t12 * a_minus_b);
    G_E = (float(1) / float(8)) * (t11 * si.w[0] - t12 * si.w[0]) / a;
  }
  float g_factor = -float(8) * si.s * length;
  f = F * length;
  grad[0] = -g_factor * (G_E * ab0 - foot0 * G_ap);
  grad[1] = g_factor * (G_ap * foot1 - G_E * ab1);
  grad[2] = g_factor * (G_ap * foot2 - G_E * ab2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-8/2) dt
// Operations: 39 +, 67 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i8_w1_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  float ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (ab_ab + cross_cross * si.s);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = ap_bp * si.s + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, c_minus_b);
    float t2 = float(1) / D;
    float t3 = float(1) / c;
    float t4 = float(1) / q1;
    float t5 = t4 * t4;
    float t6 = t3 * t3;
    float t7 = t5 * t4;
    float t8 = t6 * t3;
    float t9 = float(5) * t2 * a * (float(3) * t2 * a * (b * t3 + a * J2 + a_minus_b * t4) + float(2) * a_minus_b * t5 + float(2) * b * t6) + float(8) * a_minus_b * t7 + float(8) * b * t8;
    F = (float(1) / float(48)) * t2 * t9 * si.w[0] + (float(1) / float(48)) * (float(8) * t8 + t2 * t9 * b - float(8) * t7) * si.w[1] / a;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-8/2) dt
// Operations: 53 +, 112 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i8_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  float ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
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
    foot0 = ap0 - t0 * ab0 * ab_ap;
    foot1 = ap1 - t0 * ab1 * ab_ap;
    foot2 = ap2 - ab2 * t0 * ab_ap;
  }
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  float ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (ab_ab + si.s * cross_cross);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, c_minus_b);
    float t3 = float(1) / q1;
    float t4 = t3 * t3;
    float t5 = t4 * t3;
    float t6 = float(1) / D;
    float t7 = float(1) / c;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = float(8) * t5 * a_minus_b + float(5) * (float(3) * t6 * a * (t7 * b + t3 * a_minus_b + J2 * a) + float(2) * t4 * a_minus_b + float(2) * t8 * b) * t6 * a + float(8) * t9 * b;
    float t11 = float(1) / a;
    F = (float(1) / float(48)) * si.w[0] * t10 * t6 + (float(1) / float(48)) * si.w[1] * t11 * (t10 * t6 * b + float(8) * t9 - float(8) * t5);
    float t12 = t8 * t8;
    float t13 = t4 * t4;
    float t14 = float(48) * t12 * b + float(7) * t10 * t6 * a + float(48) * t13 * a_minus_b;
    G_ap = (float(1) / float(384)) * (t6 * t14 * b + float(48) * t12 - float(48) * t13) * si.w[1] * t11 + (float(1) / float(384)) * si.w[0] * t6 * t14;
    G_E = -(float(1) / float(384)) * t11 * (float(48) * t13 * (si.w[0] + si.w[1]) - t10 * si.w[1] * t6 - float(48) * si.w[0] * t12);
  }
  float g_factor = -float(8) * si.s * length;
  f = F * length;
  grad[0] = -g_factor * (G_E * ab0 - foot0 * G_ap);
  grad[1] = -g_factor * (G_E * ab1 - foot1 * G_ap);
  grad[2] = (foot2 * G_ap - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-8/2) dt
// Operations: 42 +, 78 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i8_w2_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (ab_ab + si.s * cross_cross);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, c_minus_b);
    float t2 = float(1) / a;
    float t3 = float(1) / D;
    float t4 = float(1) / c;
    float t5 = float(1) / q1;
    float t6 = t5 * t5;
    float t7 = t4 * t4;
    float t8 = float(3) * t3 * a * (t4 * b + a_minus_b * t5 + a * J2) + float(2) * a_minus_b * t6 + float(2) * t7 * b;
    float t9 = t7 * t4;
    float t10 = t6 * t5;
    float t11 = float(8) * a_minus_b * t10 + float(5) * t8 * t3 * a + float(8) * t9 * b;
    float t12 = float(8) * t9 + t3 * b * t11 - float(8) * t10;
    F = (float(1) / float(48)) * si.w[2] * t2 * (float(6) * t8 * t3 + float(2) * t12 * t2 * b - c * t3 * t11) + (float(1) / float(48)) * t3 * si.w[0] * t11 + (float(1) / float(48)) * t12 * t2 * si.w[1];
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-8/2) dt
// Operations: 61 +, 135 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i8_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  float ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (si.s * cross_cross + ab_ab) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = atan(t1, c_minus_b) * t2;
    float t3 = float(1) / D;
    float t4 = float(1) / c;
    float t5 = t4 * t4;
    float t6 = float(1) / q1;
    float t7 = t6 * t6;
    float t8 = float(2) * t5 * b + float(3) * t3 * a * (t6 * a_minus_b + t4 * b + J2 * a) + float(2) * t7 * a_minus_b;
    float t9 = t5 * t4;
    float t10 = t7 * t6;
    float t11 = float(5) * t8 * t3 * a + float(8) * t9 * b + float(8) * t10 * a_minus_b;
    float t12 = t3 * t11 * b + float(8) * t9 - float(8) * t10;
    float t13 = float(1) / a;
    F = (float(1) / float(48)) * t12 * si.w[1] * t13 + (float(1) / float(48)) * t3 * t11 * si.w[0] + (float(1) / float(48)) * (float(2) * t12 * t13 * b + float(6) * t8 * t3 - c * t3 * t11) * si.w[2] * t13;
    float t14 = t7 * t7;
    float t15 = t5 * t5;
    float t16 = float(48) * t14 * a_minus_b + float(48) * t15 * b + float(7) * t3 * a * t11;
    float t17 = t3 * t16 * b + float(48) * t15 - float(48) * t14;
    G_ap = (float(1) / float(384)) * (float(2) * t13 * t17 * b + float(8) * t3 * t11 - c * t3 * t16) * si.w[2] * t13 + (float(1) / float(384)) * t3 * t16 * si.w[0] + (float(1) / float(384)) * si.w[1] * t13 * t17;
    G_E = (float(1) / float(384)) * (float(48) * t15 * si.w[0] + float(2) * t12 * si.w[2] * t13 + si.w[1] * t3 * t11 - float(48) * (si.w[1] + si.w[2] + si.w[0]) * t14) * t13;
  }
  float g_factor = -float(8) * length * si.s;
  f = length * F;
  grad[0] = -g_factor * (G_E * ab0 - foot0 * G_ap);
  grad[1] = -g_factor * (G_E * ab1 - G_ap * foot1);
  grad[2] = g_factor * (G_ap * foot2 - G_E * ab2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-8/2) dt
// Operations: 47 +, 92 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i8_w3_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
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
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = bp0 * ab0 + ab2 * bp2 + bp1 * ab1;
  float ap_bp = bp1 * ap1 + ap2 * bp2 + bp0 * ap0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (ab_ab + si.s * cross_cross);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, c_minus_b);
    float t2 = float(1) / D;
    float t3 = float(1) / c;
    float t4 = t3 * t3;
    float t5 = t4 * t3;
    float t6 = float(1) / q1;
    float t7 = t6 * t6;
    float t8 = t7 * t6;
    float t9 = float(2) * b * t4 + float(3) * (a_minus_b * t6 + a * J2 + b * t3) * t2 * a + float(2) * a_minus_b * t7;
    float t10 = float(8) * b * t5 + float(8) * a_minus_b * t8 + float(5) * t2 * t9 * a;
    float t11 = t2 * b * t10 + float(8) * t5 - float(8) * t8;
    float t12 = float(1) / a;
    float t13 = float(6) * t2 * t9 + float(2) * t11 * t12 * b - t2 * t10 * c;
    F = (float(1) / float(48)) * t11 * t12 * si.w[1] + (float(1) / float(48)) * si.w[0] * t2 * t10 + (float(1) / float(48)) * t12 * t13 * si.w[2] - (float(1) / float(48)) * (t11 * t12 * c - float(6) * t12 * (t2 * t9 * b + float(2) * t4 - float(2) * t7) - float(2) * t12 * t13 * b) * si.w[3] * t12;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-8/2) dt
// Operations: 71 +, 162 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i8_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  float ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (ab_ab + si.s * cross_cross);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, c_minus_b);
    float t3 = float(1) / c;
    float t4 = t3 * t3;
    float t5 = t4 * t3;
    float t6 = float(1) / q1;
    float t7 = float(1) / D;
    float t8 = t6 * t6;
    float t9 = float(3) * (t3 * b + a_minus_b * t6 + J2 * a) * t7 * a + float(2) * a_minus_b * t8 + float(2) * t4 * b;
    float t10 = t8 * t6;
    float t11 = float(5) * t9 * t7 * a + float(8) * a_minus_b * t10 + float(8) * t5 * b;
    float t12 = float(8) * t5 + t11 * t7 * b - float(8) * t10;
    float t13 = float(1) / a;
    float t14 = t11 * c * t7 - float(2) * t12 * t13 * b - float(6) * t9 * t7;
    F = (float(1) / float(48)) * t12 * t13 * si.w[1] + (float(1) / float(48)) * t11 * t7 * si.w[0] - (float(1) / float(48)) * si.w[2] * t13 * t14 - (float(1) / float(48)) * (float(2) * t13 * t14 * b + c * t12 * t13 - float(6) * (float(2) * t4 + t9 * t7 * b - float(2) * t8) * t13) * si.w[3] * t13;
    float t15 = t4 * t4;
    float t16 = t8 * t8;
    float t17 = float(48) * t15 * b + float(48) * a_minus_b * t16 + float(7) * t11 * t7 * a;
    float t18 = float(48) * t15 + t7 * t17 * b - float(48) * t16;
    float t19 = float(8) * t11 * t7 + float(2) * t13 * b * t18 - c * t7 * t17;
    G_ap = (float(1) / float(384)) * si.w[2] * t13 * t19 + (float(1) / float(384)) * t13 * si.w[1] * t18 + (float(1) / float(384)) * t7 * si.w[0] * t17 - (float(1) / float(384)) * si.w[3] * t13 * (c * t13 * t18 - float(2) * t13 * b * t19 - float(8) * t12 * t13);
    G_E = -(float(1) / float(384)) * (float(3) * si.w[3] * t13 * t14 + float(48) * (si.w[2] + si.w[3] + si.w[0] + si.w[1]) * t16 - float(2) * si.w[2] * t12 * t13 - float(48) * t15 * si.w[0] - t11 * t7 * si.w[1]) * t13;
  }
  float g_factor = -float(8) * si.s * length;
  f = F * length;
  grad[0] = -g_factor * (G_E * ab0 - G_ap * foot0);
  grad[1] = -(G_E * ab1 - G_ap * foot1) * g_factor;
  grad[2] = g_factor * (G_ap * foot2 - G_E * ab2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-9/2) dt
// Operations: 34 +, 68 *, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i9_w0_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  float ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (ab_ab + si.s * cross_cross);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / D;
    float t1 = float(1) / r1;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t2;
    float t5 = float(1) / r0;
    float t6 = t5 * t5;
    float t7 = t6 * t6;
    float t8 = t7 * t6;
    F = (float(1) / float(35)) * si.w[0] * t0 * (float(5) * a_minus_b * t4 * t1 + float(5) * t8 * t5 * b + float(2) * (float(3) * a_minus_b * t3 * t1 + float(4) * t0 * a * (t6 * t5 * b + float(2) * (a_minus_b * t1 + t5 * b) * t0 * a + a_minus_b * t2 * t1) + float(3) * t7 * t5 * b) * t0 * a);
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-9/2) dt
// Operations: 43 +, 110 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i9_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / D;
    float t2 = float(1) / r1;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = t4 * t3;
    float t6 = float(1) / r0;
    float t7 = t6 * t6;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = float(5) * t2 * a_minus_b * t5 + float(2) * (float(3) * t2 * a_minus_b * t4 + float(4) * (t7 * t6 * b + float(2) * t1 * a * (t2 * a_minus_b + t6 * b) + t2 * a_minus_b * t3) * t1 * a + float(3) * t8 * t6 * b) * t1 * a + float(5) * t9 * t6 * b;
    F = (float(1) / float(35)) * si.w[0] * t1 * t10;
    float t11 = t4 * t4;
    float t12 = t8 * t8;
    G_ap = (float(1) / float(315)) * (float(35) * t2 * a_minus_b * t11 + float(35) * t12 * t6 * b + float(8) * t1 * t10 * a) * si.w[0] * t1;
    float t13 = t6 * t6;
    float t14 = t13 * t13;
    float t15 = t14 * t14;
    float t16 = t15 * t6;
    float t17 = t2 * t2;
    float t18 = t17 * t17;
    float t19 = t18 * t18;
    float t20 = t19 * t2;
    G_E = (float(1) / float(9)) * (t16 * si.w[0] - si.w[0] * t20) / a;
  }
  float g_factor = -float(9) * si.s * length;
  f = F * length;
  grad[0] = -g_factor * (G_E * ab0 - foot0 * G_ap);
  grad[1] = g_factor * (foot1 * G_ap - G_E * ab1);
  grad[2] = g_factor * (foot2 * G_ap - G_E * ab2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-9/2) dt
// Operations: 37 +, 76 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i9_w1_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ab_bp = ab2 * bp2 + ab1 * bp1 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / r0;
    float t1 = t0 * t0;
    float t2 = t1 * t1;
    float t3 = t2 * t1;
    float t4 = float(1) / D;
    float t5 = float(1) / r1;
    float t6 = t5 * t5;
    float t7 = t6 * t6;
    float t8 = t7 * t6;
    float t9 = float(5) * t8 * t5 * a_minus_b + float(2) * t4 * a * (float(3) * t0 * b * t2 + float(3) * t7 * t5 * a_minus_b + float(4) * t4 * a * (float(2) * t4 * a * (t0 * b + t5 * a_minus_b) + t6 * t5 * a_minus_b + t0 * b * t1)) + float(5) * t0 * b * t3;
    F = (float(1) / float(35)) * (float(5) * t0 * t3 + t4 * b * t9 - float(5) * t8 * t5) * si.w[1] / a + (float(1) / float(35)) * t4 * si.w[0] * t9;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-9/2) dt
// Operations: 51 +, 133 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i9_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
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
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / D;
    float t2 = float(1) / r0;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = float(1) / r1;
    float t6 = t5 * t5;
    float t7 = t6 * t6;
    float t8 = t4 * t3;
    float t9 = t7 * t6;
    float t10 = float(2) * t1 * (float(3) * b * t4 * t2 + float(4) * t1 * (float(2) * t1 * (b * t2 + t5 * a_minus_b) * a + t5 * a_minus_b * t6 + b * t3 * t2) * a + float(3) * t5 * a_minus_b * t7) * a + float(5) * b * t8 * t2 + float(5) * t5 * a_minus_b * t9;
    float t11 = float(1) / a;
    F = (float(1) / float(35)) * t1 * si.w[0] * t10 - (float(1) / float(35)) * (float(5) * t5 * t9 - float(5) * t8 * t2 - t1 * b * t10) * si.w[1] * t11;
    float t12 = t4 * t4;
    float t13 = t7 * t7;
    float t14 = float(8) * t1 * t10 * a + float(35) * b * t12 * t2 + float(35) * t5 * a_minus_b * t13;
    G_ap = (float(1) / float(315)) * t1 * t14 * si.w[0] - (float(1) / float(315)) * (float(35) * t5 * t13 - float(35) * t12 * t2 - t1 * t14 * b) * si.w[1] * t11;
    float t15 = t5 * t5;
    float t16 = t15 * t15;
    float t17 = t16 * t16;
    float t18 = t17 * t5;
    float t19 = t2 * t2;
    float t20 = t19 * t19;
    float t21 = t20 * t20;
    float t22 = t21 * t2;
    G_E = -(float(1) / float(315)) * (float(35) * t18 * (si.w[0] + si.w[1]) - t1 * si.w[1] * t10 - float(35) * si.w[0] * t22) * t11;
  }
  float g_factor = -float(9) * length * si.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = -g_factor * (ab1 * G_E - G_ap * foot1);
  grad[2] = -g_factor * (ab2 * G_E - foot2 * G_ap);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-9/2) dt
// Operations: 40 +, 88 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i9_w2_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  float ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
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
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (cross_cross * si.s + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / r1;
    float t1 = t0 * t0;
    float t2 = t1 * t1;
    float t3 = t2 * t1;
    float t4 = float(1) / r0;
    float t5 = t4 * t4;
    float t6 = t5 * t5;
    float t7 = t6 * t5;
    float t8 = float(1) / D;
    float t9 = float(3) * t4 * b * t6 + float(3) * a_minus_b * t0 * t2 + float(4) * (float(2) * (a_minus_b * t0 + t4 * b) * t8 * a + a_minus_b * t0 * t1 + t4 * b * t5) * t8 * a;
    float t10 = float(5) * a_minus_b * t0 * t3 + float(5) * t4 * b * t7 + float(2) * t9 * t8 * a;
    float t11 = b * t10 * t8 + float(5) * t4 * t7 - float(5) * t0 * t3;
    float t12 = float(1) / a;
    F = (float(1) / float(35)) * si.w[0] * t10 * t8 + (float(1) / float(35)) * t11 * si.w[1] * t12 + (float(1) / float(105)) * (float(6) * b * t11 * t12 + float(7) * t9 * t8 - float(3) * c * t10 * t8) * si.w[2] * t12;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-9/2) dt
// Operations: 59 +, 157 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i9_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
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
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (ab_ab + si.s * cross_cross);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / D;
    float t2 = float(1) / r1;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = float(1) / r0;
    float t6 = t5 * t5;
    float t7 = t6 * t6;
    float t8 = float(3) * t4 * t2 * a_minus_b + float(3) * t7 * t5 * b + float(4) * (float(2) * (t5 * b + t2 * a_minus_b) * a * t1 + t6 * t5 * b + t3 * t2 * a_minus_b) * a * t1;
    float t9 = t7 * t6;
    float t10 = t4 * t3;
    float t11 = float(5) * t10 * t2 * a_minus_b + float(2) * a * t1 * t8 + float(5) * t9 * t5 * b;
    float t12 = float(5) * t9 * t5 + t11 * t1 * b - float(5) * t10 * t2;
    float t13 = float(1) / a;
    F = (float(1) / float(105)) * (float(7) * t1 * t8 + float(6) * t12 * t13 * b - float(3) * c * t11 * t1) * si.w[2] * t13 + (float(1) / float(35)) * si.w[1] * t12 * t13 + (float(1) / float(35)) * t11 * t1 * si.w[0];
    float t14 = t7 * t7;
    float t15 = t4 * t4;
    float t16 = float(8) * t11 * a * t1 + float(35) * t14 * t5 * b + float(35) * t15 * t2 * a_minus_b;
    float t17 = t16 * t1 * b + float(35) * t14 * t5 - float(35) * t15 * t2;
    G_ap = (float(1) / float(315)) * t16 * t1 * si.w[0] + (float(1) / float(315)) * si.w[1] * t13 * t17 + (float(1) / float(315)) * si.w[2] * t13 * (float(9) * t11 * t1 + float(2) * t13 * b * t17 - c * t16 * t1);
    float t18 = t5 * t5;
    float t19 = t18 * t18;
    float t20 = t19 * t19;
    float t21 = t20 * t5;
    float t22 = t2 * t2;
    float t23 = t22 * t22;
    float t24 = t23 * t23;
    float t25 = t24 * t2;
    G_E = (float(1) / float(315)) * t13 * (si.w[1] * t11 * t1 + float(2) * t12 * si.w[2] * t13 + float(35) * t21 * si.w[0] - float(35) * (si.w[1] + si.w[2] + si.w[0]) * t25);
  }
  float g_factor = -float(9) * si.s * length;
  f = F * length;
  grad[0] = -(G_E * ab0 - foot0 * G_ap) * g_factor;
  grad[1] = -(G_E * ab1 - G_ap * foot1) * g_factor;
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-9/2) dt
// Operations: 45 +, 105 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i9_w3_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  float ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
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
  float ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / D;
    float t1 = float(1) / r0;
    float t2 = float(1) / r1;
    float t3 = t2 * t2;
    float t4 = t1 * t1;
    float t5 = t4 * t4;
    float t6 = t3 * t3;
    float t7 = float(4) * t0 * (float(2) * t0 * (t1 * b + t2 * a_minus_b) * a + t2 * a_minus_b * t3 + t1 * b * t4) * a + float(3) * t1 * b * t5 + float(3) * t2 * a_minus_b * t6;
    float t8 = t5 * t4;
    float t9 = t6 * t3;
    float t10 = float(2) * t0 * t7 * a + float(5) * t1 * b * t8 + float(5) * t2 * a_minus_b * t9;
    float t11 = float(1) / a;
    float t12 = float(5) * t2 * t9 - t0 * b * t10 - float(5) * t1 * t8;
    float t13 = float(3) * t0 * t10 * c + float(6) * b * t12 * t11 - float(7) * t0 * t7;
    F = (float(1) / float(35)) * t0 * t10 * si.w[0] - (float(1) / float(105)) * (float(7) * (float(3) * t2 * t6 - t0 * b * t7 - float(3) * t1 * t5) * t11 + float(2) * t13 * b * t11 - float(3) * c * t12 * t11) * si.w[3] * t11 - (float(1) / float(35)) * si.w[1] * t12 * t11 - (float(1) / float(105)) * t13 * si.w[2] * t11;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-9/2) dt
// Operations: 69 +, 186 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i9_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ap1 * ab1 + ap2 * ab2 + ap0 * ab0;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ap2 * ab1 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ap2 * ab0;
  float plain_cross2 = ap1 * ab0 - ap0 * ab1;
  float plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
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
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (cross_cross * si.s + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / r1;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = float(1) / r0;
    float t5 = t4 * t4;
    float t6 = t5 * t5;
    float t7 = float(1) / D;
    float t8 = float(3) * a_minus_b * t3 * t1 + float(3) * b * t6 * t4 + float(4) * t7 * (float(2) * (b * t4 + a_minus_b * t1) * t7 * a + b * t5 * t4 + a_minus_b * t2 * t1) * a;
    float t9 = t3 * t2;
    float t10 = t6 * t5;
    float t11 = float(2) * t8 * t7 * a + float(5) * a_minus_b * t9 * t1 + float(5) * b * t10 * t4;
    float t12 = b * t11 * t7 + float(5) * t10 * t4 - float(5) * t9 * t1;
    float t13 = float(1) / a;
    float t14 = float(7) * t8 * t7 + float(6) * b * t12 * t13 - float(3) * t11 * c * t7;
    F = (float(1) / float(105)) * si.w[2] * t14 * t13 + (float(1) / float(105)) * (float(7) * (b * t8 * t7 + float(3) * t6 * t4 - float(3) * t3 * t1) * t13 + float(2) * b * t14 * t13 - float(3) * c * t12 * t13) * si.w[3] * t13 + (float(1) / float(35)) * t11 * si.w[0] * t7 + (float(1) / float(35)) * si.w[1] * t12 * t13;
    float t15 = t6 * t6;
    float t16 = t3 * t3;
    float t17 = float(35) * b * t15 * t4 + float(8) * t11 * t7 * a + float(35) * a_minus_b * t16 * t1;
    float t18 = b * t17 * t7 + float(35) * t15 * t4 - float(35) * t16 * t1;
    float t19 = t17 * c * t7 - float(2) * b * t18 * t13 - float(9) * t11 * t7;
    G_ap = (float(1) / float(315)) * si.w[1] * t18 * t13 + (float(1) / float(315)) * t17 * si.w[0] * t7 + (float(1) / float(315)) * (float(9) * t12 * t13 - float(2) * t19 * b * t13 - c * t18 * t13) * si.w[3] * t13 - (float(1) / float(315)) * t19 * si.w[2] * t13;
    float t20 = t4 * t4;
    float t21 = t20 * t20;
    float t22 = t21 * t21;
    float t23 = t22 * t4;
    float t24 = t1 * t1;
    float t25 = t24 * t24;
    float t26 = t25 * t25;
    float t27 = t26 * t1;
    G_E = (float(1) / float(315)) * (t14 * si.w[3] * t13 + float(35) * t23 * si.w[0] + si.w[1] * t11 * t7 + float(2) * si.w[2] * t12 * t13 - float(35) * (si.w[1] + si.w[2] + si.w[3] + si.w[0]) * t27) * t13;
  }
  float g_factor = -float(9) * length * si.s;
  f = F * length;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = g_factor * (G_ap * foot1 - G_E * ab1);
  grad[2] = -g_factor * (G_E * ab2 - foot2 * G_ap);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-10/2) dt
// Operations: 38 +, 70 *, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i10_w0_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  float ab_ap = ab0 * ap0 + ab2 * ap2 + ab1 * ap1;
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  float ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (ab_ab + si.s * cross_cross);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, c_minus_b);
    float t2 = float(1) / D;
    float t3 = float(1) / c;
    float t4 = t3 * t3;
    float t5 = t4 * t4;
    float t6 = float(1) / q1;
    float t7 = t6 * t6;
    float t8 = t7 * t6;
    float t9 = t4 * t3;
    float t10 = t7 * t7;
    F = (float(1) / float(384)) * si.w[0] * t2 * (float(48) * t5 * b + float(7) * (float(5) * (float(3) * t2 * a * (t3 * b + a_minus_b * t6 + a * J2) + float(2) * a_minus_b * t7 + float(2) * t4 * b) * t2 * a + float(8) * a_minus_b * t8 + float(8) * t9 * b) * t2 * a + float(48) * a_minus_b * t10);
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-10/2) dt
// Operations: 47 +, 102 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i10_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
    foot2 = ap2 - ab2 * t0 * ab_ap;
  }
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = bp0 * ab0 + ab2 * bp2 + bp1 * ab1;
  float ap_bp = bp1 * ap1 + ap2 * bp2 + bp0 * ap0;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -ab_bp * si.s;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = ap_bp * si.s + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, c_minus_b);
    float t3 = float(1) / D;
    float t4 = float(1) / q1;
    float t5 = float(1) / c;
    float t6 = t5 * t5;
    float t7 = t4 * t4;
    float t8 = t6 * t5;
    float t9 = t7 * t4;
    float t10 = t7 * t7;
    float t11 = t6 * t6;
    float t12 = float(7) * t3 * a * (float(5) * (float(3) * t3 * a * (a_minus_b * t4 + b * t5 + J2 * a) + float(2) * b * t6 + float(2) * a_minus_b * t7) * t3 * a + float(8) * b * t8 + float(8) * a_minus_b * t9) + float(48) * a_minus_b * t10 + float(48) * b * t11;
    F = (float(1) / float(384)) * si.w[0] * t3 * t12;
    float t13 = t10 * t4;
    float t14 = t11 * t5;
    G_ap = (float(1) / float(1280)) * si.w[0] * t3 * (float(128) * a_minus_b * t13 + float(128) * b * t14 + float(3) * t3 * a * t12);
    G_E = (float(1) / float(10)) * (si.w[0] * t14 - si.w[0] * t13) / a;
  }
  float g_factor = -float(10) * length * si.s;
  f = F * length;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = -(G_E * ab1 - foot1 * G_ap) * g_factor;
  grad[2] = g_factor * (foot2 * G_ap - G_E * ab2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-10/2) dt
// Operations: 41 +, 76 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i10_w1_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
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
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  float ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = atan(t0, c_minus_b) * t1;
    float t2 = float(1) / c;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = float(1) / q1;
    float t6 = t5 * t5;
    float t7 = t6 * t6;
    float t8 = t6 * t5;
    float t9 = float(1) / D;
    float t10 = t3 * t2;
    float t11 = float(48) * t4 * b + float(48) * a_minus_b * t7 + float(7) * (float(8) * a_minus_b * t8 + float(5) * a * t9 * (float(2) * a_minus_b * t6 + float(2) * t3 * b + float(3) * a * t9 * (a * J2 + t2 * b + a_minus_b * t5)) + float(8) * t10 * b) * a * t9;
    F = (float(1) / float(384)) * (t11 * t9 * b + float(48) * t4 - float(48) * t7) * si.w[1] / a + (float(1) / float(384)) * t11 * si.w[0] * t9;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-10/2) dt
// Operations: 55 +, 121 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i10_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
    foot0 = ap0 - ab0 * ab_ap * t0;
    foot1 = ap1 - ab1 * ab_ap * t0;
    foot2 = ap2 - ab2 * ab_ap * t0;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  float ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (cross_cross * si.s + ab_ab) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = atan(t1, c_minus_b) * t2;
    float t3 = float(1) / a;
    float t4 = float(1) / c;
    float t5 = t4 * t4;
    float t6 = t5 * t5;
    float t7 = float(1) / q1;
    float t8 = t7 * t7;
    float t9 = t8 * t8;
    float t10 = t5 * t4;
    float t11 = t8 * t7;
    float t12 = float(1) / D;
    float t13 = float(48) * a_minus_b * t9 + float(7) * a * (float(8) * b * t10 + float(8) * a_minus_b * t11 + float(5) * a * t12 * (float(2) * b * t5 + float(2) * a_minus_b * t8 + float(3) * a * (a * J2 + a_minus_b * t7 + b * t4) * t12)) * t12 + float(48) * b * t6;
    F = (float(1) / float(384)) * t3 * (float(48) * t6 + b * t13 * t12 - float(48) * t9) * si.w[1] + (float(1) / float(384)) * si.w[0] * t13 * t12;
    float t14 = t6 * t4;
    float t15 = t9 * t7;
    float t16 = float(128) * a_minus_b * t15 + float(3) * a * t13 * t12 + float(128) * b * t14;
    G_ap = (float(1) / float(1280)) * t3 * si.w[1] * (float(128) * t14 + b * t16 * t12 - float(128) * t15) + (float(1) / float(1280)) * si.w[0] * t16 * t12;
    G_E = (float(1) / float(3840)) * t3 * (t13 * si.w[1] * t12 + float(384) * si.w[0] * t14 - float(384) * t15 * (si.w[0] + si.w[1]));
  }
  float g_factor = -float(10) * length * si.s;
  f = F * length;
  grad[0] = (foot0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = -(ab1 * G_E - G_ap * foot1) * g_factor;
  grad[2] = g_factor * (foot2 * G_ap - ab2 * G_E);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-10/2) dt
// Operations: 44 +, 87 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i10_w2_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
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
  float ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  float ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (cross_cross * si.s + ab_ab) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = ap_bp * si.s + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = atan(t0, c_minus_b) * t1;
    float t2 = float(1) / c;
    float t3 = t2 * t2;
    float t4 = t3 * t2;
    float t5 = float(1) / q1;
    float t6 = t5 * t5;
    float t7 = t6 * t5;
    float t8 = float(1) / D;
    float t9 = float(8) * b * t4 + float(8) * t7 * a_minus_b + float(5) * (float(2) * t6 * a_minus_b + float(2) * b * t3 + float(3) * (t5 * a_minus_b + J2 * a + b * t2) * t8 * a) * t8 * a;
    float t10 = t3 * t3;
    float t11 = t6 * t6;
    float t12 = float(7) * t9 * t8 * a + float(48) * b * t10 + float(48) * t11 * a_minus_b;
    float t13 = float(48) * t11 - t12 * b * t8 - float(48) * t10;
    float t14 = float(1) / a;
    F = (float(1) / float(384)) * t12 * si.w[0] * t8 - (float(1) / float(384)) * si.w[2] * (float(2) * b * t13 * t14 + t12 * c * t8 - float(8) * t9 * t8) * t14 - (float(1) / float(384)) * si.w[1] * t13 * t14;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-10/2) dt
// Operations: 63 +, 145 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i10_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
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
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ab_bp = ab1 * bp1 + ab2 * bp2 + bp0 * ab0;
  float ap_bp = ap1 * bp1 + bp0 * ap0 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (cross_cross * si.s + ab_ab) * si.s;
  float a_minus_b = -ab_bp * si.s;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = ap_bp * si.s + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = atan(t1, c_minus_b) * t2;
    float t3 = float(1) / D;
    float t4 = float(1) / q1;
    float t5 = float(1) / c;
    float t6 = t5 * t5;
    float t7 = t4 * t4;
    float t8 = t6 * t5;
    float t9 = t7 * t4;
    float t10 = float(5) * t3 * a * (float(3) * t3 * a * (a * J2 + a_minus_b * t4 + b * t5) + float(2) * b * t6 + float(2) * a_minus_b * t7) + float(8) * b * t8 + float(8) * a_minus_b * t9;
    float t11 = t7 * t7;
    float t12 = t6 * t6;
    float t13 = float(7) * t3 * a * t10 + float(48) * a_minus_b * t11 + float(48) * b * t12;
    float t14 = float(1) / a;
    float t15 = t3 * t13 * b + float(48) * t12 - float(48) * t11;
    F = (float(1) / float(384)) * t3 * si.w[0] * t13 + (float(1) / float(384)) * t14 * t15 * si.w[1] - (float(1) / float(384)) * si.w[2] * t14 * (t3 * t13 * c - float(2) * t14 * t15 * b - float(8) * t3 * t10);
    float t16 = t11 * t4;
    float t17 = t12 * t5;
    float t18 = float(128) * a_minus_b * t16 + float(128) * b * t17 + float(3) * t3 * a * t13;
    float t19 = t3 * b * t18 + float(128) * t17 - float(128) * t16;
    G_ap = (float(1) / float(1280)) * t3 * si.w[0] * t18 + (float(1) / float(1280)) * t14 * t19 * si.w[1] + (float(1) / float(3840)) * si.w[2] * t14 * (float(10) * t3 * t13 + float(6) * t14 * t19 * b - float(3) * t3 * t18 * c);
    G_E = (float(1) / float(3840)) * t14 * (float(2) * si.w[2] * t14 * t15 + t3 * t13 * si.w[1] + float(384) * si.w[0] * t17 - float(384) * (si.w[2] + si.w[0] + si.w[1]) * t16);
  }
  float g_factor = -float(10) * length * si.s;
  f = F * length;
  grad[0] = (foot0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = g_factor * (foot1 * G_ap - G_E * ab1);
  grad[2] = (foot2 * G_ap - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-10/2) dt
// Operations: 49 +, 101 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i10_w3_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ap2 * ab1 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ap2 * ab0;
  float plain_cross2 = ap1 * ab0 - ap0 * ab1;
  float plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  float ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (cross_cross * si.s + ab_ab) * si.s;
  float a_minus_b = -ab_bp * si.s;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = ap_bp * si.s + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, c_minus_b);
    float t2 = float(1) / c;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = float(1) / D;
    float t6 = float(1) / q1;
    float t7 = t6 * t6;
    float t8 = t3 * t2;
    float t9 = t7 * t6;
    float t10 = float(5) * (float(2) * b * t3 + float(2) * a_minus_b * t7 + float(3) * (a_minus_b * t6 + b * t2 + J2 * a) * t5 * a) * t5 * a + float(8) * b * t8 + float(8) * a_minus_b * t9;
    float t11 = t7 * t7;
    float t12 = float(7) * t10 * t5 * a + float(48) * a_minus_b * t11 + float(48) * b * t4;
    float t13 = float(48) * t4 + b * t5 * t12 - float(48) * t11;
    float t14 = float(1) / a;
    float t15 = c * t5 * t12 - float(2) * b * t13 * t14 - float(8) * t10 * t5;
    F = (float(1) / float(384)) * si.w[1] * t13 * t14 + (float(1) / float(384)) * si.w[0] * t5 * t12 - (float(1) / float(384)) * t15 * si.w[2] * t14 - (float(1) / float(384)) * (t13 * c * t14 + float(2) * b * t15 * t14 - float(8) * (float(8) * t8 + b * t10 * t5 - float(8) * t9) * t14) * si.w[3] * t14;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-10/2) dt
// Operations: 73 +, 173 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i10_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  float ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = ap_bp * si.s + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = atan(t1, c_minus_b) * t2;
    float t3 = float(1) / c;
    float t4 = t3 * t3;
    float t5 = t4 * t4;
    float t6 = float(1) / q1;
    float t7 = t6 * t6;
    float t8 = t7 * t7;
    float t9 = t4 * t3;
    float t10 = float(1) / D;
    float t11 = t7 * t6;
    float t12 = float(8) * b * t9 + float(5) * (float(2) * b * t4 + float(3) * t10 * a * (a_minus_b * t6 + J2 * a + b * t3) + float(2) * a_minus_b * t7) * t10 * a + float(8) * a_minus_b * t11;
    float t13 = float(48) * b * t5 + float(48) * a_minus_b * t8 + float(7) * t12 * t10 * a;
    float t14 = float(48) * t8 - float(48) * t5 - t13 * b * t10;
    float t15 = float(1) / a;
    float t16 = t13 * c * t10 + float(2) * t14 * b * t15 - float(8) * t12 * t10;
    F = (float(1) / float(384)) * t13 * t10 * si.w[0] - (float(1) / float(384)) * t14 * si.w[1] * t15 - (float(1) / float(384)) * t16 * si.w[2] * t15 - (float(1) / float(384)) * (float(2) * t16 * b * t15 - float(8) * (float(8) * t9 + b * t12 * t10 - float(8) * t11) * t15 - t14 * c * t15) * si.w[3] * t15;
    float t17 = t5 * t3;
    float t18 = t8 * t6;
    float t19 = float(3) * t13 * t10 * a + float(128) * b * t17 + float(128) * a_minus_b * t18;
    float t20 = float(128) * t18 - float(128) * t17 - b * t19 * t10;
    float t21 = float(6) * b * t20 * t15 + float(3) * t19 * c * t10 - float(10) * t13 * t10;
    G_ap = (float(1) / float(1280)) * t19 * t10 * si.w[0] - (float(1) / float(3840)) * t21 * si.w[2] * t15 - (float(1) / float(1280)) * si.w[1] * t20 * t15 - (float(1) / float(3840)) * (float(2) * t21 * b * t15 + float(10) * t14 * t15 - float(3) * c * t20 * t15) * si.w[3] * t15;
    G_E = (float(1) / float(3840)) * (float(384) * t17 * si.w[0] + t13 * si.w[1] * t10 - float(384) * t18 * (si.w[1] + si.w[2] + si.w[3] + si.w[0]) - float(3) * t16 * si.w[3] * t15 - float(2) * t14 * si.w[2] * t15) * t15;
  }
  float g_factor = -float(10) * length * si.s;
  f = F * length;
  grad[0] = (foot0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = -(ab1 * G_E - G_ap * foot1) * g_factor;
  grad[2] = -(ab2 * G_E - foot2 * G_ap) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-11/2) dt
// Operations: 36 +, 79 *, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i11_w0_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab1 * ap1 + ap0 * ab0 + ab2 * ap2;
  float ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ap0 * ab1;
  float plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = ap_ap * si.s + float(1);
  float D = (si.s * cross_cross + ab_ab) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / D;
    float t1 = float(1) / r0;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = float(1) / r1;
    float t5 = t4 * t4;
    float t6 = t5 * t5;
    float t7 = t6 * t5;
    float t8 = t3 * t2;
    float t9 = t3 * t3;
    float t10 = t6 * t6;
    F = (float(1) / float(315)) * (float(8) * a * t0 * (float(2) * a * t0 * (float(3) * t3 * t1 * b + float(4) * a * t0 * (t4 * a_minus_b * t5 + t2 * t1 * b + float(2) * (t1 * b + t4 * a_minus_b) * a * t0) + float(3) * t4 * a_minus_b * t6) + float(5) * t4 * a_minus_b * t7 + float(5) * t8 * t1 * b) + float(35) * t9 * t1 * b + float(35) * t4 * a_minus_b * t10) * si.w[0] * t0;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-11/2) dt
// Operations: 45 +, 123 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i11_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / D;
    float t2 = float(1) / r0;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = t4 * t4;
    float t6 = float(1) / r1;
    float t7 = t6 * t6;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = t4 * t3;
    float t11 = t8 * t8;
    float t12 = float(35) * t5 * t2 * b + float(8) * a * t1 * (float(2) * (float(3) * t4 * t2 * b + float(4) * a * t1 * (t7 * t6 * a_minus_b + float(2) * a * t1 * (t6 * a_minus_b + t2 * b) + t3 * t2 * b) + float(3) * t8 * t6 * a_minus_b) * a * t1 + float(5) * t9 * t6 * a_minus_b + float(5) * t10 * t2 * b) + float(35) * t11 * t6 * a_minus_b;
    F = (float(1) / float(315)) * si.w[0] * t1 * t12;
    float t13 = t5 * t3;
    float t14 = t11 * t7;
    G_ap = (float(1) / float(693)) * si.w[0] * t1 * (float(2) * a * t1 * t12 + float(63) * t13 * t2 * b + float(63) * t14 * t6 * a_minus_b);
    float t15 = t6 * t6;
    float t16 = t15 * t15;
    float t17 = t16 * t6;
    float t18 = t17 * t17;
    float t19 = t18 * t6;
    float t20 = t2 * t2;
    float t21 = t20 * t20;
    float t22 = t21 * t2;
    float t23 = t22 * t22;
    float t24 = t23 * t2;
    G_E = -(float(1) / float(11)) * (si.w[0] * t19 - si.w[0] * t24) / a;
  }
  float g_factor = -float(11) * si.s * length;
  f = F * length;
  grad[0] = (foot0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = g_factor * (G_ap * foot1 - G_E * ab1);
  grad[2] = g_factor * (G_ap * foot2 - G_E * ab2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-11/2) dt
// Operations: 39 +, 87 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i11_w1_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -ab_bp * si.s;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / r1;
    float t1 = t0 * t0;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = float(1) / r0;
    float t5 = t4 * t4;
    float t6 = t5 * t5;
    float t7 = t6 * t6;
    float t8 = t6 * t5;
    float t9 = float(1) / D;
    float t10 = t2 * t1;
    float t11 = float(35) * t0 * a_minus_b * t3 + float(35) * b * t7 * t4 + float(8) * (float(5) * b * t8 * t4 + float(2) * (float(4) * t9 * a * (t0 * a_minus_b * t1 + float(2) * (b * t4 + t0 * a_minus_b) * t9 * a + b * t5 * t4) + float(3) * b * t6 * t4 + float(3) * t0 * a_minus_b * t2) * t9 * a + float(5) * t0 * a_minus_b * t10) * t9 * a;
    F = (float(1) / float(315)) * si.w[0] * t11 * t9 - (float(1) / float(315)) * (float(35) * t0 * t3 - float(35) * t7 * t4 - b * t11 * t9) * si.w[1] / a;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-11/2) dt
// Operations: 53 +, 146 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i11_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (ab_ab + si.s * cross_cross);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / r0;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = float(1) / D;
    float t6 = float(1) / r1;
    float t7 = t6 * t6;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = t3 * t2;
    float t11 = t8 * t8;
    float t12 = float(35) * t4 * t1 * b + float(8) * t5 * a * (float(5) * t9 * t6 * a_minus_b + float(2) * (float(4) * (t2 * t1 * b + t7 * t6 * a_minus_b + float(2) * (t1 * b + t6 * a_minus_b) * t5 * a) * t5 * a + float(3) * t8 * t6 * a_minus_b + float(3) * t3 * t1 * b) * t5 * a + float(5) * t10 * t1 * b) + float(35) * t11 * t6 * a_minus_b;
    float t13 = float(1) / a;
    F = (float(1) / float(315)) * (float(35) * t4 * t1 + t5 * b * t12 - float(35) * t11 * t6) * si.w[1] * t13 + (float(1) / float(315)) * si.w[0] * t5 * t12;
    float t14 = t11 * t7;
    float t15 = t4 * t2;
    float t16 = float(2) * t5 * a * t12 + float(63) * t14 * t6 * a_minus_b + float(63) * t15 * t1 * b;
    G_ap = (float(1) / float(693)) * si.w[0] * t5 * t16 + (float(1) / float(693)) * (float(63) * t15 * t1 + t5 * t16 * b - float(63) * t14 * t6) * si.w[1] * t13;
    float t17 = t1 * t1;
    float t18 = t17 * t17;
    float t19 = t18 * t1;
    float t20 = t19 * t19;
    float t21 = t20 * t1;
    float t22 = t6 * t6;
    float t23 = t22 * t22;
    float t24 = t23 * t6;
    float t25 = t24 * t24;
    float t26 = t25 * t6;
    G_E = (float(1) / float(3465)) * (float(315) * si.w[0] * t21 + si.w[1] * t5 * t12 - float(315) * t26 * (si.w[0] + si.w[1])) * t13;
  }
  float g_factor = -float(11) * si.s * length;
  f = F * length;
  grad[0] = -(G_E * ab0 - foot0 * G_ap) * g_factor;
  grad[1] = -(G_E * ab1 - G_ap * foot1) * g_factor;
  grad[2] = (G_ap * foot2 - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-11/2) dt
// Operations: 42 +, 98 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i11_w2_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  float ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
  float ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -ab_bp * si.s;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / a;
    float t1 = float(1) / r0;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = float(1) / r1;
    float t6 = t5 * t5;
    float t7 = t6 * t6;
    float t8 = t7 * t7;
    float t9 = float(1) / D;
    float t10 = t3 * t2;
    float t11 = t7 * t6;
    float t12 = float(5) * t10 * t1 * b + float(5) * t11 * t5 * a_minus_b + float(2) * (float(3) * t3 * t1 * b + float(3) * t7 * t5 * a_minus_b + float(4) * (t6 * t5 * a_minus_b + float(2) * t9 * a * (t1 * b + t5 * a_minus_b) + t2 * t1 * b) * t9 * a) * t9 * a;
    float t13 = float(35) * t8 * t5 * a_minus_b + float(35) * t4 * t1 * b + float(8) * t9 * a * t12;
    float t14 = float(35) * t4 * t1 + t13 * t9 * b - float(35) * t8 * t5;
    F = (float(1) / float(315)) * t0 * t14 * si.w[1] + (float(1) / float(315)) * si.w[2] * t0 * (float(2) * t0 * b * t14 + float(9) * t9 * t12 - c * t13 * t9) + (float(1) / float(315)) * t13 * t9 * si.w[0];
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-11/2) dt
// Operations: 61 +, 170 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i11_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -ab_bp * si.s;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / a;
    float t2 = float(1) / r0;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = t4 * t4;
    float t6 = float(1) / D;
    float t7 = float(1) / r1;
    float t8 = t7 * t7;
    float t9 = t8 * t8;
    float t10 = t9 * t9;
    float t11 = t9 * t8;
    float t12 = t4 * t3;
    float t13 = float(5) * t7 * a_minus_b * t11 + float(5) * t2 * b * t12 + float(2) * t6 * a * (float(4) * (float(2) * t6 * a * (t2 * b + t7 * a_minus_b) + t2 * b * t3 + t7 * a_minus_b * t8) * t6 * a + float(3) * t7 * a_minus_b * t9 + float(3) * t2 * b * t4);
    float t14 = float(35) * t2 * b * t5 + float(35) * t7 * a_minus_b * t10 + float(8) * t13 * t6 * a;
    float t15 = float(35) * t2 * t5 + t6 * t14 * b - float(35) * t7 * t10;
    F = (float(1) / float(315)) * t1 * t15 * si.w[1] + (float(1) / float(315)) * t6 * t14 * si.w[0] + (float(1) / float(315)) * si.w[2] * t1 * (float(9) * t13 * t6 + float(2) * t1 * t15 * b - t6 * t14 * c);
    float t16 = t5 * t3;
    float t17 = t10 * t8;
    float t18 = float(63) * t2 * b * t16 + float(2) * t6 * a * t14 + float(63) * t7 * a_minus_b * t17;
    float t19 = float(63) * t2 * t16 + t6 * b * t18 - float(63) * t7 * t17;
    G_ap = (float(1) / float(3465)) * si.w[2] * t1 * (float(10) * t1 * t19 * b + float(11) * t6 * t14 - float(5) * t6 * t18 * c) + (float(1) / float(693)) * t6 * si.w[0] * t18 + (float(1) / float(693)) * t1 * t19 * si.w[1];
    float t20 = t2 * t2;
    float t21 = t20 * t20;
    float t22 = t21 * t2;
    float t23 = t22 * t22;
    float t24 = t23 * t2;
    float t25 = t7 * t7;
    float t26 = t25 * t25;
    float t27 = t26 * t7;
    float t28 = t27 * t27;
    float t29 = t28 * t7;
    G_E = (float(1) / float(3465)) * t1 * (t6 * t14 * si.w[1] + float(2) * si.w[2] * t1 * t15 + float(315) * t24 * si.w[0] - float(315) * (si.w[2] + si.w[0] + si.w[1]) * t29);
  }
  float g_factor = -float(11) * length * si.s;
  f = F * length;
  grad[0] = (foot0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = -g_factor * (G_E * ab1 - G_ap * foot1);
  grad[2] = (foot2 * G_ap - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-11/2) dt
// Operations: 47 +, 114 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i11_w3_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / a;
    float t1 = float(1) / r1;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = float(1) / D;
    float t6 = float(1) / r0;
    float t7 = t6 * t6;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = t3 * t2;
    float t11 = float(2) * t5 * a * (float(3) * t8 * t6 * b + float(4) * (t1 * a_minus_b * t2 + float(2) * t5 * a * (t1 * a_minus_b + t6 * b) + t7 * t6 * b) * t5 * a + float(3) * t1 * a_minus_b * t3) + float(5) * t9 * t6 * b + float(5) * t1 * a_minus_b * t10;
    float t12 = t8 * t8;
    float t13 = float(8) * t11 * t5 * a + float(35) * t12 * t6 * b + float(35) * t1 * a_minus_b * t4;
    float t14 = float(35) * t1 * t4 - t13 * t5 * b - float(35) * t12 * t6;
    float t15 = c * t13 * t5 + float(2) * t0 * b * t14 - float(9) * t11 * t5;
    F = (float(1) / float(315)) * si.w[3] * t0 * (c * t0 * t14 + float(9) * t0 * (float(5) * t9 * t6 + t11 * t5 * b - float(5) * t1 * t10) - float(2) * t15 * t0 * b) + (float(1) / float(315)) * t13 * si.w[0] * t5 - (float(1) / float(315)) * t0 * si.w[1] * t14 - (float(1) / float(315)) * si.w[2] * t15 * t0;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-11/2) dt
// Operations: 71 +, 200 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i11_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab1 * ab1 + ab0 * ab0 + ab2 * ab2;
  float ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  float ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  float plain_cross0 = ab1 * ap2 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ap2 * ab0;
  float plain_cross2 = ap1 * ab0 - ab1 * ap0;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  float foot0;
  float foot1;
  float foot2;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
    float t0 = float(1) / ab_ab;
    foot0 = ap0 - ab_ap * ab0 * t0;
    foot1 = ap1 - ab1 * ab_ap * t0;
    foot2 = ap2 - ab_ap * t0 * ab2;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab1 * bp1 + bp2 * ab2 + ab0 * bp0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (ab_ab + cross_cross * si.s);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / r0;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t2;
    float t5 = float(1) / r1;
    float t6 = t5 * t5;
    float t7 = t6 * t6;
    float t8 = t7 * t6;
    float t9 = float(1) / D;
    float t10 = float(5) * b * t4 * t1 + float(5) * t5 * a_minus_b * t8 + float(2) * (float(4) * (t5 * a_minus_b * t6 + b * t2 * t1 + float(2) * (t5 * a_minus_b + b * t1) * a * t9) * a * t9 + float(3) * b * t3 * t1 + float(3) * t5 * a_minus_b * t7) * a * t9;
    float t11 = t3 * t3;
    float t12 = t7 * t7;
    float t13 = float(8) * a * t10 * t9 + float(35) * b * t11 * t1 + float(35) * t5 * a_minus_b * t12;
    float t14 = b * t13 * t9 + float(35) * t11 * t1 - float(35) * t5 * t12;
    float t15 = float(1) / a;
    float t16 = float(9) * t10 * t9 + float(2) * b * t14 * t15 - c * t13 * t9;
    F = (float(1) / float(315)) * si.w[1] * t14 * t15 + (float(1) / float(315)) * si.w[0] * t13 * t9 + (float(1) / float(315)) * t16 * t15 * si.w[2] - (float(1) / float(315)) * si.w[3] * (c * t14 * t15 - float(9) * (float(5) * t4 * t1 + b * t10 * t9 - float(5) * t5 * t8) * t15 - float(2) * b * t16 * t15) * t15;
    float t17 = t12 * t6;
    float t18 = t11 * t2;
    float t19 = float(63) * b * t18 * t1 + float(2) * t13 * a * t9 + float(63) * t5 * a_minus_b * t17;
    float t20 = float(63) * t5 * t17 - b * t19 * t9 - float(63) * t18 * t1;
    float t21 = float(10) * b * t20 * t15 + float(5) * t19 * c * t9 - float(11) * t13 * t9;
    G_ap = (float(1) / float(3465)) * si.w[3] * (float(11) * t14 * t15 + float(5) * c * t20 * t15 - float(2) * b * t21 * t15) * t15 + (float(1) / float(693)) * t19 * si.w[0] * t9 - (float(1) / float(3465)) * t21 * t15 * si.w[2] - (float(1) / float(693)) * si.w[1] * t20 * t15;
    float t22 = t1 * t1;
    float t23 = t22 * t22;
    float t24 = t23 * t1;
    float t25 = t24 * t24;
    float t26 = t25 * t1;
    float t27 = t5 * t5;
    float t28 = t27 * t27;
    float t29 = t28 * t5;
    float t30 = t29 * t29;
    float t31 = t30 * t5;
    G_E = (float(1) / float(3465)) * (float(2) * t14 * t15 * si.w[2] + float(3) * si.w[3] * t16 * t15 + float(315) * si.w[0] * t26 + t13 * si.w[1] * t9 - float(315) * t31 * (si.w[3] + si.w[0] + si.w[1] + si.w[2])) * t15;
  }
  float g_factor = -float(11) * length * si.s;
  f = F * length;
  grad[0] = g_factor * (foot0 * G_ap - ab0 * G_E);
  grad[1] = (G_ap * foot1 - ab1 * G_E) * g_factor;
  grad[2] = g_factor * (foot2 * G_ap - G_E * ab2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-12/2) dt
// Operations: 40 +, 79 *, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i12_w0_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, c_minus_b);
    float t2 = float(1) / D;
    float t3 = float(1) / c;
    float t4 = t3 * t3;
    float t5 = t4 * t3;
    float t6 = float(1) / q1;
    float t7 = t6 * t6;
    float t8 = t7 * t6;
    float t9 = t7 * t7;
    float t10 = t4 * t4;
    float t11 = t10 * t3;
    float t12 = t9 * t6;
    F = (float(1) / float(1280)) * si.w[0] * t2 * (float(3) * a * t2 * (float(7) * a * t2 * (float(8) * t5 * b + float(8) * a_minus_b * t8 + float(5) * a * t2 * (float(2) * t4 * b + float(3) * a * t2 * (a_minus_b * t6 + a * J2 + t3 * b) + float(2) * a_minus_b * t7)) + float(48) * a_minus_b * t9 + float(48) * t10 * b) + float(128) * t11 * b + float(128) * a_minus_b * t12);
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-12/2) dt
// Operations: 49 +, 111 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i12_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
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
  float ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = atan(t1, c_minus_b) * t2;
    float t3 = float(1) / q1;
    float t4 = t3 * t3;
    float t5 = t4 * t4;
    float t6 = t5 * t3;
    float t7 = float(1) / c;
    float t8 = t7 * t7;
    float t9 = t8 * t8;
    float t10 = t9 * t7;
    float t11 = float(1) / D;
    float t12 = t4 * t3;
    float t13 = t8 * t7;
    float t14 = float(128) * t6 * a_minus_b + float(128) * b * t10 + float(3) * a * t11 * (float(48) * t5 * a_minus_b + float(48) * b * t9 + float(7) * a * t11 * (float(8) * t12 * a_minus_b + float(8) * b * t13 + float(5) * (float(2) * t4 * a_minus_b + float(3) * a * t11 * (b * t7 + J2 * a + t3 * a_minus_b) + float(2) * b * t8) * a * t11));
    F = (float(1) / float(1280)) * si.w[0] * t14 * t11;
    float t15 = t12 * t12;
    float t16 = t13 * t13;
    G_ap = (float(1) / float(15360)) * (float(1280) * t15 * a_minus_b + float(1280) * b * t16 + float(11) * t14 * a * t11) * si.w[0] * t11;
    G_E = (float(1) / float(12)) * (t16 * si.w[0] - t15 * si.w[0]) / a;
  }
  float g_factor = -float(12) * length * si.s;
  f = F * length;
  grad[0] = -(G_E * ab0 - foot0 * G_ap) * g_factor;
  grad[1] = -(G_E * ab1 - G_ap * foot1) * g_factor;
  grad[2] = -(G_E * ab2 - G_ap * foot2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-12/2) dt
// Operations: 43 +, 85 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i12_w1_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  float ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = ap_bp * si.s + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, c_minus_b);
    float t2 = float(1) / q1;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = t4 * t2;
    float t6 = float(1) / D;
    float t7 = float(1) / c;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = t3 * t2;
    float t11 = t8 * t8;
    float t12 = t11 * t7;
    float t13 = float(128) * t5 * a_minus_b + float(3) * t6 * a * (float(7) * t6 * a * (float(5) * t6 * a * (float(3) * t6 * a * (b * t7 + t2 * a_minus_b + a * J2) + float(2) * t3 * a_minus_b + float(2) * b * t8) + float(8) * b * t9 + float(8) * t10 * a_minus_b) + float(48) * t4 * a_minus_b + float(48) * b * t11) + float(128) * b * t12;
    F = (float(1) / float(1280)) * t13 * t6 * si.w[0] - (float(1) / float(1280)) * (float(128) * t5 - float(128) * t12 - t13 * t6 * b) * si.w[1] / a;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-12/2) dt
// Operations: 57 +, 130 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i12_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
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
    foot0 = ap0 - t0 * ab0 * ab_ap;
    foot1 = ap1 - t0 * ab1 * ab_ap;
    foot2 = ap2 - ab2 * t0 * ab_ap;
  }
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  float ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (ab_ab + si.s * cross_cross);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = atan(t1, c_minus_b) * t2;
    float t3 = float(1) / D;
    float t4 = float(1) / c;
    float t5 = t4 * t4;
    float t6 = t5 * t5;
    float t7 = t6 * t4;
    float t8 = float(1) / q1;
    float t9 = t8 * t8;
    float t10 = t9 * t9;
    float t11 = t9 * t8;
    float t12 = t5 * t4;
    float t13 = t10 * t8;
    float t14 = float(128) * t7 * b + float(3) * (float(48) * t6 * b + float(48) * t10 * a_minus_b + float(7) * t3 * a * (float(5) * (float(3) * (t4 * b + t8 * a_minus_b + J2 * a) * t3 * a + float(2) * t9 * a_minus_b + float(2) * t5 * b) * t3 * a + float(8) * t11 * a_minus_b + float(8) * t12 * b)) * t3 * a + float(128) * t13 * a_minus_b;
    float t15 = float(1) / a;
    F = (float(1) / float(1280)) * si.w[0] * t3 * t14 - (float(1) / float(1280)) * si.w[1] * t15 * (float(128) * t13 - float(128) * t7 - t3 * t14 * b);
    float t16 = t12 * t12;
    float t17 = t11 * t11;
    float t18 = float(1280) * t16 * b + float(11) * t3 * a * t14 + float(1280) * t17 * a_minus_b;
    G_ap = (float(1) / float(15360)) * si.w[1] * t15 * (float(1280) * t16 + t3 * t18 * b - float(1280) * t17) + (float(1) / float(15360)) * si.w[0] * t3 * t18;
    G_E = -(float(1) / float(15360)) * (float(1280) * t17 * (si.w[0] + si.w[1]) - float(1280) * si.w[0] * t16 - si.w[1] * t3 * t14) * t15;
  }
  float g_factor = -float(12) * si.s * length;
  f = F * length;
  grad[0] = -(G_E * ab0 - G_ap * foot0) * g_factor;
  grad[1] = -(G_E * ab1 - G_ap * foot1) * g_factor;
  grad[2] = g_factor * (G_ap * foot2 - G_E * ab2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-12/2) dt
// Operations: 46 +, 97 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i12_w2_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  float ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = atan(t0, c_minus_b) * t1;
    float t2 = float(1) / a;
    float t3 = float(1) / D;
    float t4 = float(1) / q1;
    float t5 = t4 * t4;
    float t6 = t5 * t5;
    float t7 = t6 * t4;
    float t8 = float(1) / c;
    float t9 = t8 * t8;
    float t10 = t9 * t8;
    float t11 = t5 * t4;
    float t12 = t9 * t9;
    float t13 = float(48) * a_minus_b * t6 + float(7) * (float(8) * t10 * b + float(5) * t3 * a * (float(2) * a_minus_b * t5 + float(3) * (t8 * b + a_minus_b * t4 + a * J2) * t3 * a + float(2) * t9 * b) + float(8) * a_minus_b * t11) * t3 * a + float(48) * t12 * b;
    float t14 = t12 * t8;
    float t15 = float(128) * a_minus_b * t7 + float(3) * t3 * a * t13 + float(128) * t14 * b;
    float t16 = t3 * t15 * b + float(128) * t14 - float(128) * t7;
    F = (float(1) / float(1280)) * si.w[1] * t2 * t16 + (float(1) / float(3840)) * si.w[2] * (float(6) * t2 * t16 * b + float(10) * t3 * t13 - float(3) * c * t3 * t15) * t2 + (float(1) / float(1280)) * t3 * t15 * si.w[0];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-12/2) dt
// Operations: 65 +, 154 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i12_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  float ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
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
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (si.s * cross_cross + ab_ab) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = atan(t1, c_minus_b) * t2;
    float t3 = float(1) / D;
    float t4 = float(1) / q1;
    float t5 = t4 * t4;
    float t6 = t5 * t5;
    float t7 = t6 * t4;
    float t8 = float(1) / c;
    float t9 = t8 * t8;
    float t10 = t9 * t8;
    float t11 = t5 * t4;
    float t12 = t9 * t9;
    float t13 = float(48) * t6 * a_minus_b + float(7) * t3 * a * (float(5) * t3 * a * (float(2) * t5 * a_minus_b + float(2) * b * t9 + float(3) * (J2 * a + b * t8 + t4 * a_minus_b) * t3 * a) + float(8) * b * t10 + float(8) * t11 * a_minus_b) + float(48) * b * t12;
    float t14 = t12 * t8;
    float t15 = float(128) * t7 * a_minus_b + float(3) * t13 * t3 * a + float(128) * b * t14;
    float t16 = float(128) * t7 - float(128) * t14 - b * t3 * t15;
    float t17 = float(1) / a;
    F = (float(1) / float(1280)) * t3 * si.w[0] * t15 - (float(1) / float(1280)) * si.w[1] * t16 * t17 - (float(1) / float(3840)) * (float(3) * c * t3 * t15 + float(6) * b * t16 * t17 - float(10) * t13 * t3) * si.w[2] * t17;
    float t18 = t11 * t11;
    float t19 = t10 * t10;
    float t20 = float(1280) * t18 * a_minus_b + float(11) * t3 * a * t15 + float(1280) * b * t19;
    float t21 = float(1280) * t19 + b * t20 * t3 - float(1280) * t18;
    G_ap = (float(1) / float(15360)) * t20 * t3 * si.w[0] + (float(1) / float(15360)) * si.w[1] * t17 * t21 - (float(1) / float(15360)) * (c * t20 * t3 - float(2) * b * t17 * t21 - float(12) * t3 * t15) * si.w[2] * t17;
    G_E = (float(1) / float(15360)) * (float(1280) * t19 * si.w[0] + si.w[1] * t3 * t15 - float(1280) * t18 * (si.w[1] + si.w[2] + si.w[0]) - float(2) * t16 * si.w[2] * t17) * t17;
  }
  float g_factor = -float(12) * length * si.s;
  f = length * F;
  grad[0] = -g_factor * (G_E * ab0 - foot0 * G_ap);
  grad[1] = -(G_E * ab1 - G_ap * foot1) * g_factor;
  grad[2] = (G_ap * foot2 - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-12/2) dt
// Operations: 51 +, 112 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i12_w3_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
  float ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ab2 * ap0 - ap2 * ab0;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  float ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (cross_cross * si.s + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = ap_bp * si.s + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = atan(t0, c_minus_b) * t1;
    float t2 = float(1) / c;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = t4 * t2;
    float t6 = t3 * t2;
    float t7 = float(1) / q1;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = float(1) / D;
    float t11 = t8 * t8;
    float t12 = float(7) * (float(8) * b * t6 + float(8) * a_minus_b * t9 + float(5) * (float(2) * b * t3 + float(3) * (a_minus_b * t7 + J2 * a + b * t2) * t10 * a + float(2) * a_minus_b * t8) * t10 * a) * t10 * a + float(48) * b * t4 + float(48) * a_minus_b * t11;
    float t13 = t11 * t7;
    float t14 = float(3) * t12 * t10 * a + float(128) * b * t5 + float(128) * a_minus_b * t13;
    float t15 = float(128) * t5 + b * t14 * t10 - float(128) * t13;
    float t16 = float(1) / a;
    float t17 = float(6) * b * t15 * t16 + float(10) * t12 * t10 - float(3) * t14 * c * t10;
    F = (float(1) / float(3840)) * si.w[3] * (float(2) * b * t17 * t16 + float(10) * (b * t12 * t10 + float(48) * t4 - float(48) * t11) * t16 - float(3) * c * t15 * t16) * t16 + (float(1) / float(3840)) * t17 * si.w[2] * t16 + (float(1) / float(1280)) * si.w[1] * t15 * t16 + (float(1) / float(1280)) * si.w[0] * t14 * t10;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-12/2) dt
// Operations: 75 +, 181 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i12_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = ap_bp * si.s + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, c_minus_b);
    float t3 = float(1) / D;
    float t4 = float(1) / c;
    float t5 = t4 * t4;
    float t6 = t5 * t5;
    float t7 = float(1) / q1;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = t5 * t4;
    float t11 = t8 * t8;
    float t12 = float(48) * b * t6 + float(7) * t3 * a * (float(5) * t3 * a * (float(2) * a_minus_b * t8 + float(2) * b * t5 + float(3) * t3 * a * (b * t4 + a_minus_b * t7 + a * J2)) + float(8) * a_minus_b * t9 + float(8) * b * t10) + float(48) * a_minus_b * t11;
    float t13 = t11 * t7;
    float t14 = t6 * t4;
    float t15 = float(3) * t3 * a * t12 + float(128) * a_minus_b * t13 + float(128) * b * t14;
    float t16 = float(1) / a;
    float t17 = float(128) * t13 - float(128) * t14 - t3 * b * t15;
    float t18 = float(3) * t3 * t15 * c + float(6) * t16 * b * t17 - float(10) * t3 * t12;
    F = (float(1) / float(1280)) * t3 * si.w[0] * t15 - (float(1) / float(3840)) * t16 * (float(10) * t16 * (float(48) * t11 - float(48) * t6 - t3 * b * t12) + float(2) * t16 * t18 * b - float(3) * t16 * c * t17) * si.w[3] - (float(1) / float(1280)) * t16 * si.w[1] * t17 - (float(1) / float(3840)) * t16 * t18 * si.w[2];
    float t19 = t10 * t10;
    float t20 = t9 * t9;
    float t21 = float(11) * t3 * a * t15 + float(1280) * b * t19 + float(1280) * a_minus_b * t20;
    float t22 = float(1280) * t20 - float(1280) * t19 - t3 * t21 * b;
    float t23 = t3 * t21 * c + float(2) * t16 * b * t22 - float(12) * t3 * t15;
    G_ap = (float(1) / float(15360)) * t3 * t21 * si.w[0] - (float(1) / float(15360)) * t16 * si.w[1] * t22 - (float(1) / float(15360)) * t16 * (float(12) * t16 * t17 + float(2) * t16 * b * t23 - t16 * c * t22) * si.w[3] - (float(1) / float(15360)) * t16 * si.w[2] * t23;
    G_E = (float(1) / float(15360)) * t16 * (t3 * si.w[1] * t15 + float(1280) * si.w[0] * t19 - float(1280) * (si.w[0] + si.w[1] + si.w[2] + si.w[3]) * t20 - t16 * t18 * si.w[3] - float(2) * t16 * si.w[2] * t17);
  }
  float g_factor = -float(12) * length * si.s;
  f = F * length;
  grad[0] = (foot0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = -(ab1 * G_E - G_ap * foot1) * g_factor;
  grad[2] = -(ab2 * G_E - foot2 * G_ap) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-13/2) dt
// Operations: 38 +, 90 *, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i13_w0_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  float ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (ab_ab + cross_cross * si.s);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / D;
    float t1 = float(1) / r1;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = t4 * t2;
    float t6 = float(1) / r0;
    float t7 = t6 * t6;
    float t8 = t7 * t7;
    float t9 = t8 * t8;
    float t10 = t3 * t2;
    float t11 = t8 * t7;
    float t12 = t9 * t7;
    F = (float(1) / float(693)) * t0 * (float(63) * t1 * a_minus_b * t5 + float(2) * t0 * a * (float(35) * t1 * a_minus_b * t4 + float(35) * t6 * b * t9 + float(8) * t0 * a * (float(5) * t1 * a_minus_b * t10 + float(2) * t0 * (float(3) * t1 * a_minus_b * t3 + float(4) * t0 * a * (float(2) * t0 * a * (t6 * b + t1 * a_minus_b) + t6 * b * t7 + t1 * a_minus_b * t2) + float(3) * t6 * b * t8) * a + float(5) * t6 * b * t11)) + float(63) * t6 * b * t12) * si.w[0];
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-13/2) dt
// Operations: 47 +, 134 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i13_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (cross_cross * si.s + ab_ab) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / r0;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t2;
    float t5 = float(1) / r1;
    float t6 = t5 * t5;
    float t7 = t6 * t6;
    float t8 = t7 * t6;
    float t9 = float(1) / D;
    float t10 = t3 * t3;
    float t11 = t7 * t7;
    float t12 = t11 * t6;
    float t13 = t10 * t2;
    float t14 = float(2) * a * (float(8) * a * (float(5) * b * t4 * t1 + float(5) * t5 * a_minus_b * t8 + float(2) * a * (float(3) * b * t3 * t1 + float(3) * t5 * a_minus_b * t7 + float(4) * a * (t5 * a_minus_b * t6 + b * t2 * t1 + float(2) * a * (b * t1 + t5 * a_minus_b) * t9) * t9) * t9) * t9 + float(35) * b * t10 * t1 + float(35) * t5 * a_minus_b * t11) * t9 + float(63) * t5 * a_minus_b * t12 + float(63) * b * t13 * t1;
    F = (float(1) / float(693)) * t14 * si.w[0] * t9;
    float t15 = t4 * t4;
    float t16 = t8 * t8;
    G_ap = (float(1) / float(3003)) * (float(231) * b * t15 * t1 + float(4) * a * t14 * t9 + float(231) * t5 * a_minus_b * t16) * si.w[0] * t9;
    float t17 = t5 * t5;
    float t18 = t17 * t5;
    float t19 = t18 * t18;
    float t20 = t19 * t19;
    float t21 = t20 * t5;
    float t22 = t1 * t1;
    float t23 = t22 * t1;
    float t24 = t23 * t23;
    float t25 = t24 * t24;
    float t26 = t25 * t1;
    G_E = -(float(1) / float(13)) * (t21 * si.w[0] - t26 * si.w[0]) / a;
  }
  float g_factor = -float(13) * length * si.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = -(ab1 * G_E - G_ap * foot1) * g_factor;
  grad[2] = (foot2 * G_ap - ab2 * G_E) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-13/2) dt
// Operations: 41 +, 98 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i13_w1_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
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
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ab_bp = bp0 * ab0 + ab1 * bp1 + ab2 * bp2;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / D;
    float t1 = float(1) / r1;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = t4 * t2;
    float t6 = t3 * t2;
    float t7 = float(1) / r0;
    float t8 = t7 * t7;
    float t9 = t8 * t8;
    float t10 = t9 * t8;
    float t11 = t9 * t9;
    float t12 = t11 * t8;
    float t13 = float(63) * t5 * t1 * a_minus_b + float(2) * t0 * a * (float(8) * t0 * a * (float(5) * t6 * t1 * a_minus_b + float(2) * t0 * a * (float(3) * t3 * t1 * a_minus_b + float(4) * t0 * a * (float(2) * t0 * a * (t1 * a_minus_b + t7 * b) + t7 * b * t8 + t2 * t1 * a_minus_b) + float(3) * t7 * b * t9) + float(5) * t7 * b * t10) + float(35) * t4 * t1 * a_minus_b + float(35) * t7 * b * t11) + float(63) * t7 * b * t12;
    F = (float(1) / float(693)) * t0 * t13 * si.w[0] - (float(1) / float(693)) * si.w[1] * (float(63) * t5 * t1 - t0 * b * t13 - float(63) * t7 * t12) / a;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-13/2) dt
// Operations: 55 +, 157 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i13_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / D;
    float t2 = float(1) / r0;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = t4 * t4;
    float t6 = t5 * t3;
    float t7 = float(1) / r1;
    float t8 = t7 * t7;
    float t9 = t8 * t8;
    float t10 = t9 * t8;
    float t11 = t4 * t3;
    float t12 = t9 * t9;
    float t13 = t12 * t8;
    float t14 = float(63) * t2 * b * t6 + float(2) * a * t1 * (float(35) * t2 * b * t5 + float(8) * a * t1 * (float(5) * t7 * a_minus_b * t10 + float(5) * t2 * b * t11 + float(2) * a * t1 * (float(3) * t7 * a_minus_b * t9 + float(3) * t2 * b * t4 + float(4) * a * t1 * (float(2) * a * t1 * (t2 * b + t7 * a_minus_b) + t2 * b * t3 + t7 * a_minus_b * t8))) + float(35) * t7 * a_minus_b * t12) + float(63) * t7 * a_minus_b * t13;
    float t15 = float(1) / a;
    F = (float(1) / float(693)) * t1 * t14 * si.w[0] + (float(1) / float(693)) * t15 * (t1 * b * t14 + float(63) * t2 * t6 - float(63) * t7 * t13) * si.w[1];
    float t16 = t11 * t11;
    float t17 = t10 * t10;
    float t18 = float(231) * t2 * b * t16 + float(4) * a * t1 * t14 + float(231) * t7 * a_minus_b * t17;
    G_ap = (float(1) / float(3003)) * t1 * t18 * si.w[0] + (float(1) / float(3003)) * t15 * (t1 * b * t18 + float(231) * t2 * t16 - float(231) * t7 * t17) * si.w[1];
    float t19 = t2 * t2;
    float t20 = t19 * t2;
    float t21 = t20 * t20;
    float t22 = t21 * t21;
    float t23 = t22 * t2;
    float t24 = t7 * t7;
    float t25 = t24 * t7;
    float t26 = t25 * t25;
    float t27 = t26 * t26;
    float t28 = t27 * t7;
    G_E = (float(1) / float(9009)) * t15 * (float(693) * t23 * si.w[0] + t1 * t14 * si.w[1] - float(693) * t28 * (si.w[0] + si.w[1]));
  }
  float g_factor = -float(13) * length * si.s;
  f = length * F;
  grad[0] = -g_factor * (G_E * ab0 - foot0 * G_ap);
  grad[1] = -g_factor * (G_E * ab1 - G_ap * foot1);
  grad[2] = -g_factor * (G_E * ab2 - foot2 * G_ap);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-13/2) dt
// Operations: 44 +, 110 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i13_w2_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
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
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (cross_cross * si.s + ab_ab) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / r0;
    float t1 = t0 * t0;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t1;
    float t5 = float(1) / r1;
    float t6 = t5 * t5;
    float t7 = t6 * t6;
    float t8 = t7 * t7;
    float t9 = t8 * t6;
    float t10 = t7 * t6;
    float t11 = t2 * t1;
    float t12 = float(1) / D;
    float t13 = float(35) * t0 * b * t3 + float(35) * a_minus_b * t5 * t8 + float(8) * (float(5) * a_minus_b * t5 * t10 + float(5) * t0 * b * t11 + float(2) * (float(3) * a_minus_b * t5 * t7 + float(3) * t0 * b * t2 + float(4) * (t0 * b * t1 + float(2) * (a_minus_b * t5 + t0 * b) * t12 * a + a_minus_b * t5 * t6) * t12 * a) * t12 * a) * t12 * a;
    float t14 = float(63) * t0 * b * t4 + float(63) * a_minus_b * t5 * t9 + float(2) * t13 * t12 * a;
    float t15 = float(63) * t0 * t4 + b * t14 * t12 - float(63) * t5 * t9;
    float t16 = float(1) / a;
    F = (float(1) / float(693)) * si.w[0] * t14 * t12 + (float(1) / float(693)) * si.w[1] * t15 * t16 + (float(1) / float(3465)) * (float(10) * b * t15 * t16 + float(11) * t13 * t12 - float(5) * t14 * c * t12) * si.w[2] * t16;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-13/2) dt
// Operations: 63 +, 182 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i13_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
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
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (si.s * cross_cross + ab_ab) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / a;
    float t2 = float(1) / r0;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = t4 * t4;
    float t6 = t5 * t3;
    float t7 = float(1) / D;
    float t8 = float(1) / r1;
    float t9 = t8 * t8;
    float t10 = t9 * t9;
    float t11 = t10 * t10;
    float t12 = t11 * t9;
    float t13 = t10 * t9;
    float t14 = t4 * t3;
    float t15 = float(35) * t8 * a_minus_b * t11 + float(8) * a * t7 * (float(5) * t8 * a_minus_b * t13 + float(5) * t2 * b * t14 + float(2) * a * t7 * (float(4) * a * t7 * (t2 * b * t3 + t8 * a_minus_b * t9 + float(2) * a * t7 * (t2 * b + t8 * a_minus_b)) + float(3) * t8 * a_minus_b * t10 + float(3) * t2 * b * t4)) + float(35) * t2 * b * t5;
    float t16 = float(63) * t8 * a_minus_b * t12 + float(2) * a * t7 * t15 + float(63) * t2 * b * t6;
    float t17 = float(63) * t2 * t6 + t7 * b * t16 - float(63) * t8 * t12;
    F = (float(1) / float(693)) * t1 * si.w[1] * t17 + (float(1) / float(693)) * t7 * t16 * si.w[0] + (float(1) / float(3465)) * t1 * si.w[2] * (float(10) * t1 * b * t17 + float(11) * t7 * t15 - float(5) * t7 * c * t16);
    float t18 = t14 * t14;
    float t19 = t13 * t13;
    float t20 = float(231) * t8 * a_minus_b * t19 + float(4) * a * t7 * t16 + float(231) * t2 * b * t18;
    float t21 = float(231) * t2 * t18 + t7 * b * t20 - float(231) * t8 * t19;
    G_ap = (float(1) / float(3003)) * t21 * t1 * si.w[1] + (float(1) / float(3003)) * t7 * si.w[0] * t20 - (float(1) / float(9009)) * t1 * (float(3) * t7 * c * t20 - float(6) * t21 * t1 * b - float(13) * t7 * t16) * si.w[2];
    float t22 = t2 * t2;
    float t23 = t22 * t2;
    float t24 = t23 * t23;
    float t25 = t24 * t24;
    float t26 = t25 * t2;
    float t27 = t8 * t8;
    float t28 = t27 * t8;
    float t29 = t28 * t28;
    float t30 = t29 * t29;
    float t31 = t30 * t8;
    G_E = (float(1) / float(9009)) * t1 * (si.w[1] * t7 * t16 + float(693) * t26 * si.w[0] + float(2) * t1 * si.w[2] * t17 - float(693) * t31 * (si.w[1] + si.w[2] + si.w[0]));
  }
  float g_factor = -float(13) * length * si.s;
  f = F * length;
  grad[0] = -(G_E * ab0 - foot0 * G_ap) * g_factor;
  grad[1] = -g_factor * (G_E * ab1 - foot1 * G_ap);
  grad[2] = (foot2 * G_ap - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-13/2) dt
// Operations: 49 +, 127 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i13_w3_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ap0 * ab0 + ab1 * ap1 + ab2 * ap2;
  float ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ap0 * ab1;
  float plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / r0;
    float t1 = t0 * t0;
    float t2 = t1 * t1;
    float t3 = t2 * t1;
    float t4 = float(1) / D;
    float t5 = float(1) / r1;
    float t6 = t5 * t5;
    float t7 = t6 * t6;
    float t8 = t7 * t6;
    float t9 = t2 * t2;
    float t10 = t7 * t7;
    float t11 = float(8) * (float(5) * t3 * t0 * b + float(2) * (float(4) * (float(2) * a * t4 * (t5 * a_minus_b + t0 * b) + t1 * t0 * b + t5 * a_minus_b * t6) * a * t4 + float(3) * t5 * a_minus_b * t7 + float(3) * t2 * t0 * b) * a * t4 + float(5) * t5 * a_minus_b * t8) * a * t4 + float(35) * t9 * t0 * b + float(35) * t5 * a_minus_b * t10;
    float t12 = t10 * t6;
    float t13 = t9 * t1;
    float t14 = float(2) * a * t11 * t4 + float(63) * t5 * a_minus_b * t12 + float(63) * t13 * t0 * b;
    float t15 = float(1) / a;
    float t16 = float(63) * t13 * t0 + t14 * t4 * b - float(63) * t5 * t12;
    float t17 = float(10) * t15 * b * t16 + float(11) * t11 * t4 - float(5) * c * t14 * t4;
    F = (float(1) / float(693)) * t14 * si.w[0] * t4 + (float(1) / float(3465)) * t15 * si.w[2] * t17 + (float(1) / float(693)) * t15 * si.w[1] * t16 - (float(1) / float(3465)) * si.w[3] * t15 * (float(5) * c * t15 * t16 - float(2) * t15 * b * t17 - float(11) * (float(35) * t9 * t0 + t11 * t4 * b - float(35) * t5 * t10) * t15);
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-13/2) dt
// Operations: 73 +, 214 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i13_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  float ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / D;
    float t2 = float(1) / r1;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = t4 * t4;
    float t6 = t5 * t3;
    float t7 = float(1) / r0;
    float t8 = t7 * t7;
    float t9 = t8 * t8;
    float t10 = t9 * t9;
    float t11 = t10 * t8;
    float t12 = t9 * t8;
    float t13 = t4 * t3;
    float t14 = float(35) * t2 * a_minus_b * t5 + float(35) * t7 * b * t10 + float(8) * t1 * a * (float(2) * t1 * a * (float(3) * t7 * b * t9 + float(3) * t2 * a_minus_b * t4 + float(4) * t1 * a * (float(2) * t1 * a * (t2 * a_minus_b + t7 * b) + t2 * a_minus_b * t3 + t7 * b * t8)) + float(5) * t7 * b * t12 + float(5) * t2 * a_minus_b * t13);
    float t15 = float(63) * t2 * a_minus_b * t6 + float(63) * t7 * b * t11 + float(2) * t1 * a * t14;
    float t16 = float(1) / a;
    float t17 = float(63) * t2 * t6 - float(63) * t7 * t11 - t1 * t15 * b;
    float t18 = float(5) * t1 * t15 * c + float(10) * t17 * t16 * b - float(11) * t1 * t14;
    F = (float(1) / float(693)) * t1 * si.w[0] * t15 - (float(1) / float(3465)) * si.w[3] * (float(2) * t16 * t18 * b + float(11) * t16 * (float(35) * t2 * t5 - float(35) * t7 * t10 - t1 * t14 * b) - float(5) * t17 * t16 * c) * t16 - (float(1) / float(3465)) * t16 * t18 * si.w[2] - (float(1) / float(693)) * t17 * t16 * si.w[1];
    float t19 = t13 * t13;
    float t20 = t12 * t12;
    float t21 = float(231) * t2 * a_minus_b * t19 + float(231) * t7 * b * t20 + float(4) * t1 * a * t15;
    float t22 = float(231) * t2 * t19 - float(231) * t7 * t20 - t1 * t21 * b;
    float t23 = float(3) * t1 * t21 * c + float(6) * t22 * t16 * b - float(13) * t1 * t15;
    G_ap = (float(1) / float(3003)) * t1 * si.w[0] * t21 - (float(1) / float(9009)) * si.w[3] * t16 * (float(13) * t17 * t16 + float(2) * t16 * b * t23 - float(3) * t22 * t16 * c) - (float(1) / float(9009)) * t16 * t23 * si.w[2] - (float(1) / float(3003)) * t22 * t16 * si.w[1];
    float t24 = t7 * t7;
    float t25 = t24 * t7;
    float t26 = t25 * t25;
    float t27 = t26 * t26;
    float t28 = t27 * t7;
    float t29 = t2 * t2;
    float t30 = t29 * t2;
    float t31 = t30 * t30;
    float t32 = t31 * t31;
    float t33 = t32 * t2;
    G_E = (float(1) / float(45045)) * t16 * (float(3465) * t28 * si.w[0] + float(5) * t1 * t15 * si.w[1] - float(3465) * t33 * (si.w[3] + si.w[0] + si.w[1] + si.w[2]) - float(3) * si.w[3] * t16 * t18 - float(10) * t17 * t16 * si.w[2]);
  }
  float g_factor = -float(13) * si.s * length;
  f = F * length;
  grad[0] = (foot0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = -(G_E * ab1 - foot1 * G_ap) * g_factor;
  grad[2] = (foot2 * G_ap - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-14/2) dt
// Operations: 42 +, 88 *, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i14_w0_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
  float ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  float ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (cross_cross * si.s + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = ap_bp * si.s + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = atan(t0, c_minus_b) * t1;
    float t2 = float(1) / c;
    float t3 = t2 * t2;
    float t4 = t3 * t2;
    float t5 = t4 * t4;
    float t6 = t3 * t3;
    float t7 = t6 * t2;
    float t8 = float(1) / q1;
    float t9 = float(1) / D;
    float t10 = t8 * t8;
    float t11 = t10 * t8;
    float t12 = t10 * t10;
    float t13 = t12 * t8;
    float t14 = t11 * t11;
    F = (float(1) / float(15360)) * (float(1280) * b * t5 + float(11) * (float(128) * b * t7 + float(3) * (float(48) * b * t6 + float(7) * (float(8) * b * t4 + float(5) * (float(2) * b * t3 + float(3) * (a_minus_b * t8 + b * t2 + J2 * a) * t9 * a + float(2) * a_minus_b * t10) * t9 * a + float(8) * a_minus_b * t11) * t9 * a + float(48) * a_minus_b * t12) * t9 * a + float(128) * a_minus_b * t13) * t9 * a + float(1280) * a_minus_b * t14) * si.w[0] * t9;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-14/2) dt
// Operations: 51 +, 120 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i14_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
    foot2 = ap2 - ab2 * t0 * ab_ap;
  }
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = bp0 * ab0 + ab2 * bp2 + bp1 * ab1;
  float ap_bp = ap2 * bp2 + bp1 * ap1 + bp0 * ap0;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -ab_bp * si.s;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = ap_bp * si.s + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = atan(t1, c_minus_b) * t2;
    float t3 = float(1) / D;
    float t4 = float(1) / q1;
    float t5 = t4 * t4;
    float t6 = t5 * t4;
    float t7 = t6 * t6;
    float t8 = float(1) / c;
    float t9 = t8 * t8;
    float t10 = t9 * t8;
    float t11 = t10 * t10;
    float t12 = t5 * t5;
    float t13 = t12 * t4;
    float t14 = t9 * t9;
    float t15 = t14 * t8;
    float t16 = float(1280) * a_minus_b * t7 + float(1280) * b * t11 + float(11) * t3 * (float(128) * a_minus_b * t13 + float(3) * t3 * a * (float(48) * a_minus_b * t12 + float(7) * t3 * a * (float(5) * (float(3) * t3 * a * (b * t8 + a_minus_b * t4 + J2 * a) + float(2) * a_minus_b * t5 + float(2) * b * t9) * t3 * a + float(8) * a_minus_b * t6 + float(8) * b * t10) + float(48) * b * t14) + float(128) * b * t15) * a;
    F = (float(1) / float(15360)) * si.w[0] * t3 * t16;
    float t17 = t7 * t4;
    float t18 = t11 * t8;
    G_ap = (float(1) / float(215040)) * (float(13) * t3 * a * t16 + float(15360) * a_minus_b * t17 + float(15360) * b * t18) * si.w[0] * t3;
    G_E = (float(1) / float(14)) * (si.w[0] * t18 - si.w[0] * t17) / a;
  }
  float g_factor = -float(14) * length * si.s;
  f = F * length;
  grad[0] = -(G_E * ab0 - foot0 * G_ap) * g_factor;
  grad[1] = -g_factor * (G_E * ab1 - foot1 * G_ap);
  grad[2] = (foot2 * G_ap - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-14/2) dt
// Operations: 45 +, 94 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i14_w1_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ap1 * ab1 + ap0 * ab0 + ap2 * ab2;
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
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (ab_ab + si.s * cross_cross);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, c_minus_b);
    float t2 = float(1) / q1;
    float t3 = t2 * t2;
    float t4 = t3 * t2;
    float t5 = t4 * t4;
    float t6 = t3 * t3;
    float t7 = t6 * t2;
    float t8 = float(1) / c;
    float t9 = t8 * t8;
    float t10 = t9 * t9;
    float t11 = t10 * t8;
    float t12 = float(1) / D;
    float t13 = t9 * t8;
    float t14 = t13 * t13;
    float t15 = float(1280) * a_minus_b * t5 + float(11) * (float(128) * a_minus_b * t7 + float(128) * t11 * b + float(3) * (float(48) * a_minus_b * t6 + float(48) * t10 * b + float(7) * (float(5) * a * (float(3) * (t8 * b + a * J2 + a_minus_b * t2) * a * t12 + float(2) * a_minus_b * t3 + float(2) * t9 * b) * t12 + float(8) * a_minus_b * t4 + float(8) * t13 * b) * a * t12) * a * t12) * a * t12 + float(1280) * t14 * b;
    F = (float(1) / float(15360)) * si.w[0] * t15 * t12 + (float(1) / float(15360)) * (float(1280) * t14 + t15 * t12 * b - float(1280) * t5) * si.w[1] / a;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-14/2) dt
// Operations: 59 +, 139 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i14_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  float ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = ap_bp * si.s + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = atan(t1, c_minus_b) * t2;
    float t3 = float(1) / c;
    float t4 = t3 * t3;
    float t5 = t4 * t3;
    float t6 = t5 * t5;
    float t7 = float(1) / q1;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = t9 * t9;
    float t11 = t4 * t4;
    float t12 = t11 * t3;
    float t13 = t8 * t8;
    float t14 = t13 * t7;
    float t15 = float(1) / D;
    float t16 = float(1280) * b * t6 + float(1280) * a_minus_b * t10 + float(11) * a * (float(128) * b * t12 + float(128) * a_minus_b * t14 + float(3) * a * (float(48) * b * t11 + float(48) * a_minus_b * t13 + float(7) * a * (float(8) * b * t5 + float(5) * a * (float(2) * b * t4 + float(3) * a * (a_minus_b * t7 + a * J2 + b * t3) * t15 + float(2) * a_minus_b * t8) * t15 + float(8) * a_minus_b * t9) * t15) * t15) * t15;
    float t17 = float(1) / a;
    F = (float(1) / float(15360)) * si.w[0] * t16 * t15 - (float(1) / float(15360)) * t17 * (float(1280) * t10 - float(1280) * t6 - b * t16 * t15) * si.w[1];
    float t18 = t6 * t3;
    float t19 = t10 * t7;
    float t20 = float(13) * a * t16 * t15 + float(15360) * b * t18 + float(15360) * a_minus_b * t19;
    G_ap = (float(1) / float(215040)) * t20 * si.w[0] * t15 - (float(1) / float(215040)) * t17 * (float(15360) * t19 - float(15360) * t18 - t20 * b * t15) * si.w[1];
    G_E = (float(1) / float(215040)) * t17 * (float(15360) * si.w[0] * t18 + t16 * si.w[1] * t15 - float(15360) * (si.w[0] + si.w[1]) * t19);
  }
  float g_factor = -float(14) * length * si.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = -g_factor * (ab1 * G_E - G_ap * foot1);
  grad[2] = (foot2 * G_ap - ab2 * G_E) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-14/2) dt
// Operations: 48 +, 105 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i14_w2_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
  float ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
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
  float ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  float ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, c_minus_b);
    float t2 = float(1) / D;
    float t3 = float(1) / c;
    float t4 = t3 * t3;
    float t5 = t4 * t3;
    float t6 = t5 * t5;
    float t7 = float(1) / q1;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = t9 * t9;
    float t11 = t4 * t4;
    float t12 = t11 * t3;
    float t13 = t8 * t8;
    float t14 = t13 * t7;
    float t15 = float(128) * t12 * b + float(128) * a_minus_b * t14 + float(3) * (float(48) * t11 * b + float(48) * a_minus_b * t13 + float(7) * (float(8) * a_minus_b * t9 + float(5) * t2 * a * (float(2) * a_minus_b * t8 + float(2) * t4 * b + float(3) * t2 * a * (a * J2 + t3 * b + a_minus_b * t7)) + float(8) * t5 * b) * t2 * a) * t2 * a;
    float t16 = float(1280) * t6 * b + float(1280) * a_minus_b * t10 + float(11) * t15 * t2 * a;
    float t17 = float(1) / a;
    float t18 = float(1280) * t10 - float(1280) * t6 - t2 * t16 * b;
    F = (float(1) / float(15360)) * si.w[0] * t2 * t16 - (float(1) / float(15360)) * t17 * (c * t2 * t16 + float(2) * t17 * t18 * b - float(12) * t15 * t2) * si.w[2] - (float(1) / float(15360)) * si.w[1] * t17 * t18;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-14/2) dt
// Operations: 67 +, 162 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i14_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
  float ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (cross_cross * si.s + ab_ab) * si.s;
  float a_minus_b = -ab_bp * si.s;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = atan(t1, c_minus_b) * t2;
    float t3 = float(1) / D;
    float t4 = float(1) / c;
    float t5 = t4 * t4;
    float t6 = t5 * t4;
    float t7 = t6 * t6;
    float t8 = t5 * t5;
    float t9 = t8 * t4;
    float t10 = float(1) / q1;
    float t11 = t10 * t10;
    float t12 = t11 * t10;
    float t13 = t11 * t11;
    float t14 = t13 * t10;
    float t15 = float(128) * b * t9 + float(3) * (float(48) * b * t8 + float(7) * t3 * a * (float(8) * b * t6 + float(8) * a_minus_b * t12 + float(5) * (float(3) * (a_minus_b * t10 + b * t4 + J2 * a) * t3 * a + float(2) * b * t5 + float(2) * a_minus_b * t11) * t3 * a) + float(48) * a_minus_b * t13) * t3 * a + float(128) * a_minus_b * t14;
    float t16 = t12 * t12;
    float t17 = float(1280) * b * t7 + float(11) * t15 * t3 * a + float(1280) * a_minus_b * t16;
    float t18 = b * t3 * t17 + float(1280) * t7 - float(1280) * t16;
    float t19 = float(1) / a;
    F = (float(1) / float(15360)) * si.w[1] * t18 * t19 + (float(1) / float(15360)) * si.w[0] * t3 * t17 - (float(1) / float(15360)) * (c * t3 * t17 - float(12) * t15 * t3 - float(2) * b * t18 * t19) * si.w[2] * t19;
    float t20 = t7 * t4;
    float t21 = t16 * t10;
    float t22 = float(15360) * b * t20 + float(15360) * a_minus_b * t21 + float(13) * t3 * a * t17;
    float t23 = b * t3 * t22 + float(15360) * t20 - float(15360) * t21;
    G_ap = (float(1) / float(215040)) * si.w[1] * t23 * t19 + (float(1) / float(215040)) * si.w[0] * t3 * t22 + (float(1) / float(215040)) * (float(2) * b * t23 * t19 + float(14) * t3 * t17 - c * t3 * t22) * si.w[2] * t19;
    G_E = (float(1) / float(215040)) * (float(2) * t18 * si.w[2] * t19 + si.w[1] * t3 * t17 + float(15360) * si.w[0] * t20 - float(15360) * t21 * (si.w[0] + si.w[1] + si.w[2])) * t19;
  }
  float g_factor = -float(14) * length * si.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = -g_factor * (G_E * ab1 - G_ap * foot1);
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-14/2) dt
// Operations: 53 +, 119 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i14_w3_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  float ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (ab_ab + si.s * cross_cross);
  float a_minus_b = -ab_bp * si.s;
  float q1 = si.s * bp_bp + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, c_minus_b);
    float t2 = float(1) / D;
    float t3 = float(1) / c;
    float t4 = t3 * t3;
    float t5 = t4 * t3;
    float t6 = t5 * t5;
    float t7 = float(1) / q1;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = t9 * t9;
    float t11 = t8 * t8;
    float t12 = t4 * t4;
    float t13 = t12 * t3;
    float t14 = t11 * t7;
    float t15 = float(3) * (float(7) * (float(8) * t5 * b + float(5) * (float(2) * t4 * b + float(2) * a_minus_b * t8 + float(3) * t2 * a * (a * J2 + a_minus_b * t7 + t3 * b)) * t2 * a + float(8) * a_minus_b * t9) * t2 * a + float(48) * a_minus_b * t11 + float(48) * t12 * b) * t2 * a + float(128) * t13 * b + float(128) * a_minus_b * t14;
    float t16 = float(1280) * t6 * b + float(1280) * a_minus_b * t10 + float(11) * t2 * a * t15;
    float t17 = t2 * b * t16 + float(1280) * t6 - float(1280) * t10;
    float t18 = float(1) / a;
    float t19 = float(12) * t2 * t15 + float(2) * t17 * t18 * b - c * t2 * t16;
    F = (float(1) / float(15360)) * t17 * t18 * si.w[1] + (float(1) / float(15360)) * si.w[0] * t2 * t16 + (float(1) / float(15360)) * si.w[2] * t19 * t18 - (float(1) / float(15360)) * (c * t17 * t18 - float(2) * t19 * t18 * b - float(12) * (t2 * t15 * b + float(128) * t13 - float(128) * t14) * t18) * si.w[3] * t18;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-14/2) dt
// Operations: 77 +, 189 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i14_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
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
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, c_minus_b);
    float t3 = float(1) / D;
    float t4 = float(1) / c;
    float t5 = t4 * t4;
    float t6 = t5 * t4;
    float t7 = float(1) / q1;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = t8 * t8;
    float t11 = t5 * t5;
    float t12 = t11 * t4;
    float t13 = t10 * t7;
    float t14 = float(3) * t3 * a * (float(7) * t3 * a * (float(8) * t6 * b + float(8) * t9 * a_minus_b + float(5) * (float(3) * (J2 * a + t7 * a_minus_b + t4 * b) * t3 * a + float(2) * t5 * b + float(2) * t8 * a_minus_b) * t3 * a) + float(48) * t10 * a_minus_b + float(48) * t11 * b) + float(128) * t12 * b + float(128) * t13 * a_minus_b;
    float t15 = t9 * t9;
    float t16 = t6 * t6;
    float t17 = float(11) * t14 * t3 * a + float(1280) * t15 * a_minus_b + float(1280) * t16 * b;
    float t18 = float(1) / a;
    float t19 = t3 * b * t17 + float(1280) * t16 - float(1280) * t15;
    float t20 = float(12) * t14 * t3 + float(2) * t18 * t19 * b - c * t3 * t17;
    F = (float(1) / float(15360)) * t3 * si.w[0] * t17 + (float(1) / float(15360)) * t18 * t19 * si.w[1] + (float(1) / float(15360)) * t20 * si.w[2] * t18 - (float(1) / float(15360)) * si.w[3] * t18 * (c * t18 * t19 + float(12) * t18 * (float(128) * t13 - float(128) * t12 - t14 * t3 * b) - float(2) * t20 * t18 * b);
    float t21 = t16 * t4;
    float t22 = t15 * t7;
    float t23 = float(13) * t3 * a * t17 + float(15360) * t21 * b + float(15360) * t22 * a_minus_b;
    float t24 = t3 * t23 * b + float(15360) * t21 - float(15360) * t22;
    float t25 = float(2) * t24 * t18 * b + float(14) * t3 * t17 - c * t3 * t23;
    G_ap = (float(1) / float(215040)) * t24 * t18 * si.w[1] + (float(1) / float(215040)) * t3 * si.w[0] * t23 + (float(1) / float(215040)) * (float(14) * t18 * t19 + float(2) * t25 * t18 * b - c * t24 * t18) * si.w[3] * t18 + (float(1) / float(215040)) * si.w[2] * t25 * t18;
    G_E = (float(1) / float(215040)) * (t3 * si.w[1] * t17 + float(15360) * t21 * si.w[0] + float(3) * t20 * si.w[3] * t18 + float(2) * si.w[2] * t18 * t19 - float(15360) * t22 * (si.w[2] + si.w[3] + si.w[0] + si.w[1])) * t18;
  }
  float g_factor = -float(14) * si.s * length;
  f = F * length;
  grad[0] = -g_factor * (G_E * ab0 - foot0 * G_ap);
  grad[1] = (G_ap * foot1 - G_E * ab1) * g_factor;
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-15/2) dt
// Operations: 40 +, 101 *, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i15_w0_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  float ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  float plain_cross0 = ab1 * ap2 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
  float plain_cross2 = ap1 * ab0 - ap0 * ab1;
  float plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / r0;
    float t1 = t0 * t0;
    float t2 = t1 * t1;
    float t3 = t2 * t1;
    float t4 = t3 * t3;
    float t5 = float(1) / r1;
    float t6 = t5 * t5;
    float t7 = t6 * t6;
    float t8 = t7 * t6;
    float t9 = t8 * t8;
    float t10 = float(1) / D;
    float t11 = t2 * t2;
    float t12 = t7 * t7;
    float t13 = t11 * t1;
    float t14 = t12 * t6;
    F = (float(1) / float(3003)) * (float(231) * t4 * t0 * b + float(231) * t5 * a_minus_b * t9 + float(4) * (float(2) * a * t10 * (float(8) * a * t10 * (float(5) * t3 * t0 * b + float(2) * (float(4) * (t1 * t0 * b + t5 * a_minus_b * t6 + float(2) * (t0 * b + t5 * a_minus_b) * a * t10) * a * t10 + float(3) * t5 * a_minus_b * t7 + float(3) * t2 * t0 * b) * a * t10 + float(5) * t5 * a_minus_b * t8) + float(35) * t11 * t0 * b + float(35) * t5 * a_minus_b * t12) + float(63) * t13 * t0 * b + float(63) * t5 * a_minus_b * t14) * a * t10) * si.w[0] * t10;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-15/2) dt
// Operations: 49 +, 147 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i15_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ap1 * ab1 + ab0 * ap0 + ab2 * ap2;
  float ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
  float plain_cross0 = ab1 * ap2 - ap1 * ab2;
  float plain_cross1 = ab2 * ap0 - ab0 * ap2;
  float plain_cross2 = ap1 * ab0 - ab1 * ap0;
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
  float ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (ab_ab + si.s * cross_cross);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / r0;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t2;
    float t5 = t4 * t4;
    float t6 = float(1) / r1;
    float t7 = t6 * t6;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = t9 * t9;
    float t11 = float(1) / D;
    float t12 = t8 * t8;
    float t13 = t12 * t7;
    float t14 = t3 * t3;
    float t15 = t14 * t2;
    float t16 = float(231) * t5 * t1 * b + float(231) * t10 * t6 * a_minus_b + float(4) * a * t11 * (float(63) * t13 * t6 * a_minus_b + float(2) * (float(35) * t14 * t1 * b + float(35) * t12 * t6 * a_minus_b + float(8) * (float(5) * t9 * t6 * a_minus_b + float(5) * t4 * t1 * b + float(2) * a * t11 * (float(3) * t8 * t6 * a_minus_b + float(3) * t3 * t1 * b + float(4) * a * (t2 * t1 * b + t7 * t6 * a_minus_b + float(2) * (t6 * a_minus_b + t1 * b) * a * t11) * t11)) * a * t11) * a * t11 + float(63) * t15 * t1 * b);
    F = (float(1) / float(3003)) * si.w[0] * t16 * t11;
    float t17 = t10 * t7;
    float t18 = t5 * t2;
    G_ap = (float(1) / float(6435)) * (float(429) * t17 * t6 * a_minus_b + float(2) * a * t16 * t11 + float(429) * t18 * t1 * b) * si.w[0] * t11;
    float t19 = t1 * t1;
    float t20 = t19 * t1;
    float t21 = t20 * t20;
    float t22 = t21 * t1;
    float t23 = t22 * t22;
    float t24 = t23 * t1;
    float t25 = t6 * t6;
    float t26 = t25 * t6;
    float t27 = t26 * t26;
    float t28 = t27 * t6;
    float t29 = t28 * t28;
    float t30 = t29 * t6;
    G_E = (float(1) / float(15)) * (si.w[0] * t24 - si.w[0] * t30) / a;
  }
  float g_factor = -float(15) * si.s * length;
  f = length * F;
  grad[0] = -g_factor * (G_E * ab0 - foot0 * G_ap);
  grad[1] = g_factor * (G_ap * foot1 - G_E * ab1);
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-15/2) dt
// Operations: 43 +, 109 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i15_w1_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (si.s * cross_cross + ab_ab) * si.s;
  float a_minus_b = -ab_bp * si.s;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / D;
    float t1 = float(1) / r1;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t2;
    float t5 = t4 * t4;
    float t6 = float(1) / r0;
    float t7 = t6 * t6;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = t9 * t9;
    float t11 = t8 * t8;
    float t12 = t3 * t3;
    float t13 = t11 * t7;
    float t14 = t12 * t2;
    float t15 = float(231) * t1 * a_minus_b * t5 + float(231) * b * t10 * t6 + float(4) * t0 * a * (float(2) * (float(35) * b * t11 * t6 + float(8) * (float(2) * t0 * (float(3) * b * t8 * t6 + float(3) * t1 * a_minus_b * t3 + float(4) * (t1 * a_minus_b * t2 + b * t7 * t6 + float(2) * t0 * a * (b * t6 + t1 * a_minus_b)) * t0 * a) * a + float(5) * b * t9 * t6 + float(5) * t1 * a_minus_b * t4) * t0 * a + float(35) * t1 * a_minus_b * t12) * t0 * a + float(63) * b * t13 * t6 + float(63) * t1 * a_minus_b * t14);
    F = (float(1) / float(3003)) * si.w[0] * t0 * t15 - (float(1) / float(3003)) * (float(231) * t1 * t5 - float(231) * t10 * t6 - b * t0 * t15) * si.w[1] / a;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-15/2) dt
// Operations: 57 +, 170 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i15_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (ab_ab + si.s * cross_cross);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / r1;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t2;
    float t5 = t4 * t4;
    float t6 = float(1) / r0;
    float t7 = t6 * t6;
    float t8 = t7 * t7;
    float t9 = t8 * t8;
    float t10 = t9 * t7;
    float t11 = t3 * t3;
    float t12 = t11 * t2;
    float t13 = float(1) / D;
    float t14 = t8 * t7;
    float t15 = t14 * t14;
    float t16 = float(231) * t5 * t1 * a_minus_b + float(4) * (float(63) * t10 * t6 * b + float(63) * t12 * t1 * a_minus_b + float(2) * t13 * (float(35) * t9 * t6 * b + float(8) * (float(5) * t4 * t1 * a_minus_b + float(2) * t13 * (float(3) * t8 * t6 * b + float(3) * t3 * t1 * a_minus_b + float(4) * t13 * a * (t2 * t1 * a_minus_b + t7 * t6 * b + float(2) * (t1 * a_minus_b + t6 * b) * t13 * a)) * a + float(5) * t14 * t6 * b) * t13 * a + float(35) * t11 * t1 * a_minus_b) * a) * t13 * a + float(231) * t15 * t6 * b;
    float t17 = float(1) / a;
    F = (float(1) / float(3003)) * si.w[0] * t16 * t13 - (float(1) / float(3003)) * (float(231) * t5 * t1 - t16 * t13 * b - float(231) * t15 * t6) * si.w[1] * t17;
    float t18 = t5 * t2;
    float t19 = t15 * t7;
    float t20 = float(429) * t18 * t1 * a_minus_b + float(2) * t16 * t13 * a + float(429) * t19 * t6 * b;
    G_ap = (float(1) / float(6435)) * si.w[0] * t20 * t13 - (float(1) / float(6435)) * si.w[1] * t17 * (float(429) * t18 * t1 - float(429) * t19 * t6 - t20 * t13 * b);
    float t21 = t6 * t6;
    float t22 = t21 * t6;
    float t23 = t22 * t22;
    float t24 = t23 * t6;
    float t25 = t24 * t24;
    float t26 = t25 * t6;
    float t27 = t1 * t1;
    float t28 = t27 * t1;
    float t29 = t28 * t28;
    float t30 = t29 * t1;
    float t31 = t30 * t30;
    float t32 = t31 * t1;
    G_E = (float(1) / float(45045)) * (float(3003) * si.w[0] * t26 + t16 * si.w[1] * t13 - float(3003) * (si.w[0] + si.w[1]) * t32) * t17;
  }
  float g_factor = -float(15) * length * si.s;
  f = length * F;
  grad[0] = (foot0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = g_factor * (G_ap * foot1 - G_E * ab1);
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-15/2) dt
// Operations: 46 +, 121 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i15_w2_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab0 * ab0 + ab2 * ab2 + ab1 * ab1;
  float ab_ap = ab1 * ap1 + ab0 * ap0 + ab2 * ap2;
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
  float ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -ab_bp * si.s;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / D;
    float t1 = float(1) / r1;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t2;
    float t5 = t4 * t4;
    float t6 = float(1) / r0;
    float t7 = t6 * t6;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = t9 * t9;
    float t11 = t3 * t3;
    float t12 = t8 * t8;
    float t13 = t12 * t7;
    float t14 = t11 * t2;
    float t15 = float(2) * (float(8) * (float(2) * t0 * a * (float(3) * t8 * t6 * b + float(4) * (t2 * t1 * a_minus_b + t7 * t6 * b + float(2) * (t6 * b + t1 * a_minus_b) * t0 * a) * t0 * a + float(3) * t3 * t1 * a_minus_b) + float(5) * t9 * t6 * b + float(5) * t4 * t1 * a_minus_b) * t0 * a + float(35) * t11 * t1 * a_minus_b + float(35) * t12 * t6 * b) * t0 * a + float(63) * t13 * t6 * b + float(63) * t14 * t1 * a_minus_b;
    float t16 = float(231) * t5 * t1 * a_minus_b + float(231) * t10 * t6 * b + float(4) * t0 * a * t15;
    float t17 = float(231) * t10 * t6 + t0 * b * t16 - float(231) * t5 * t1;
    float t18 = float(1) / a;
    F = (float(1) / float(3003)) * t0 * si.w[0] * t16 + (float(1) / float(9009)) * si.w[2] * (float(6) * t17 * t18 * b + float(13) * t0 * t15 - float(3) * c * t0 * t16) * t18 + (float(1) / float(3003)) * t17 * t18 * si.w[1];
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-15/2) dt
// Operations: 65 +, 195 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i15_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -ab_bp * si.s;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / a;
    float t2 = float(1) / D;
    float t3 = float(1) / r0;
    float t4 = t3 * t3;
    float t5 = t4 * t4;
    float t6 = t5 * t5;
    float t7 = t6 * t4;
    float t8 = t5 * t4;
    float t9 = float(1) / r1;
    float t10 = t9 * t9;
    float t11 = t10 * t10;
    float t12 = t11 * t10;
    float t13 = t11 * t11;
    float t14 = t13 * t10;
    float t15 = float(63) * t3 * b * t7 + float(2) * t2 * a * (float(35) * t3 * b * t6 + float(8) * t2 * a * (float(5) * t3 * b * t8 + float(2) * t2 * a * (float(4) * t2 * a * (float(2) * t2 * a * (t9 * a_minus_b + t3 * b) + t9 * a_minus_b * t10 + t3 * b * t4) + float(3) * t3 * b * t5 + float(3) * t9 * a_minus_b * t11) + float(5) * t9 * a_minus_b * t12) + float(35) * t9 * a_minus_b * t13) + float(63) * t9 * a_minus_b * t14;
    float t16 = t8 * t8;
    float t17 = t12 * t12;
    float t18 = float(231) * t3 * b * t16 + float(4) * t2 * a * t15 + float(231) * t9 * a_minus_b * t17;
    float t19 = float(231) * t9 * t17 - t18 * t2 * b - float(231) * t3 * t16;
    F = (float(1) / float(9009)) * si.w[2] * t1 * (float(13) * t2 * t15 - float(3) * t18 * t2 * c - float(6) * t1 * b * t19) + (float(1) / float(3003)) * t18 * t2 * si.w[0] - (float(1) / float(3003)) * t1 * si.w[1] * t19;
    float t20 = t16 * t4;
    float t21 = t17 * t10;
    float t22 = float(429) * t3 * b * t20 + float(429) * t9 * a_minus_b * t21 + float(2) * t18 * t2 * a;
    float t23 = float(429) * t9 * t21 - float(429) * t3 * t20 - t22 * t2 * b;
    G_ap = (float(1) / float(6435)) * t22 * t2 * si.w[0] - (float(1) / float(6435)) * t23 * t1 * si.w[1] - (float(1) / float(45045)) * si.w[2] * t1 * (float(7) * t22 * t2 * c + float(14) * t23 * t1 * b - float(15) * t18 * t2);
    float t24 = t9 * t9;
    float t25 = t24 * t9;
    float t26 = t25 * t25;
    float t27 = t26 * t9;
    float t28 = t27 * t27;
    float t29 = t28 * t9;
    float t30 = t3 * t3;
    float t31 = t30 * t3;
    float t32 = t31 * t31;
    float t33 = t32 * t3;
    float t34 = t33 * t33;
    float t35 = t34 * t3;
    G_E = -(float(1) / float(45045)) * (float(3003) * (si.w[2] + si.w[0] + si.w[1]) * t29 + float(2) * si.w[2] * t1 * t19 - float(3003) * t35 * si.w[0] - t18 * t2 * si.w[1]) * t1;
  }
  float g_factor = -float(15) * length * si.s;
  f = F * length;
  grad[0] = -(G_E * ab0 - foot0 * G_ap) * g_factor;
  grad[1] = -(G_E * ab1 - foot1 * G_ap) * g_factor;
  grad[2] = g_factor * (foot2 * G_ap - G_E * ab2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-15/2) dt
// Operations: 51 +, 138 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i15_w3_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / D;
    float t1 = float(1) / r0;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = t4 * t2;
    float t6 = t3 * t2;
    float t7 = float(1) / r1;
    float t8 = t7 * t7;
    float t9 = t8 * t8;
    float t10 = t9 * t8;
    float t11 = t9 * t9;
    float t12 = t11 * t8;
    float t13 = float(63) * t5 * t1 * b + float(2) * (float(35) * t4 * t1 * b + float(8) * (float(5) * t6 * t1 * b + float(2) * (float(3) * t3 * t1 * b + float(4) * (t7 * a_minus_b * t8 + float(2) * t0 * a * (t7 * a_minus_b + t1 * b) + t2 * t1 * b) * t0 * a + float(3) * t7 * a_minus_b * t9) * t0 * a + float(5) * t7 * a_minus_b * t10) * t0 * a + float(35) * t7 * a_minus_b * t11) * t0 * a + float(63) * t7 * a_minus_b * t12;
    float t14 = t10 * t10;
    float t15 = t6 * t6;
    float t16 = float(4) * t13 * t0 * a + float(231) * t7 * a_minus_b * t14 + float(231) * t15 * t1 * b;
    float t17 = float(1) / a;
    float t18 = float(231) * t7 * t14 - t0 * b * t16 - float(231) * t15 * t1;
    float t19 = float(6) * t17 * b * t18 + float(3) * c * t0 * t16 - float(13) * t13 * t0;
    F = (float(1) / float(3003)) * si.w[0] * t0 * t16 - (float(1) / float(9009)) * si.w[2] * t17 * t19 - (float(1) / float(3003)) * t17 * si.w[1] * t18 - (float(1) / float(9009)) * si.w[3] * t17 * (float(2) * t17 * t19 * b + float(13) * (float(63) * t7 * t12 - float(63) * t5 * t1 - t13 * t0 * b) * t17 - float(3) * c * t17 * t18);
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-15/2) dt
// Operations: 75 +, 225 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_cauchy_i15_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ab1 * ap1 + ab2 * ap2 + ab0 * ap0;
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float r0 = sqrt(c);
  float r1 = sqrt(q1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / a;
    float t2 = float(1) / r0;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = t4 * t4;
    float t6 = t5 * t3;
    float t7 = float(1) / D;
    float t8 = t4 * t3;
    float t9 = float(1) / r1;
    float t10 = t9 * t9;
    float t11 = t10 * t10;
    float t12 = t11 * t10;
    float t13 = t11 * t11;
    float t14 = t13 * t10;
    float t15 = float(63) * t2 * b * t6 + float(2) * a * t7 * (float(8) * (float(5) * t2 * b * t8 + float(2) * a * (float(3) * t2 * b * t4 + float(3) * t9 * a_minus_b * t11 + float(4) * (float(2) * a * t7 * (t9 * a_minus_b + t2 * b) + t9 * a_minus_b * t10 + t2 * b * t3) * a * t7) * t7 + float(5) * t9 * a_minus_b * t12) * a * t7 + float(35) * t2 * b * t5 + float(35) * t9 * a_minus_b * t13) + float(63) * t9 * a_minus_b * t14;
    float t16 = t8 * t8;
    float t17 = t12 * t12;
    float t18 = float(231) * t2 * b * t16 + float(4) * t15 * a * t7 + float(231) * t9 * a_minus_b * t17;
    float t19 = float(231) * t2 * t16 + t7 * t18 * b - float(231) * t9 * t17;
    float t20 = float(13) * t15 * t7 + float(6) * t1 * b * t19 - float(3) * t7 * t18 * c;
    F = (float(1) / float(9009)) * t1 * t20 * si.w[2] + (float(1) / float(3003)) * t1 * si.w[1] * t19 + (float(1) / float(3003)) * si.w[0] * t7 * t18 + (float(1) / float(9009)) * (float(2) * t1 * t20 * b + float(13) * t1 * (float(63) * t2 * t6 + t15 * t7 * b - float(63) * t9 * t14) - float(3) * t1 * t19 * c) * si.w[3] * t1;
    float t21 = t16 * t3;
    float t22 = t17 * t10;
    float t23 = float(429) * t2 * b * t21 + float(2) * a * t7 * t18 + float(429) * t9 * a_minus_b * t22;
    float t24 = float(429) * t2 * t21 + t7 * t23 * b - float(429) * t9 * t22;
    float t25 = float(15) * t7 * t18 + float(14) * t1 * t24 * b - float(7) * t7 * t23 * c;
    G_ap = (float(1) / float(6435)) * t1 * t24 * si.w[1] + (float(1) / float(6435)) * si.w[0] * t7 * t23 + (float(1) / float(45045)) * si.w[3] * t1 * (float(15) * t1 * t19 + float(2) * t1 * t25 * b - float(7) * t1 * t24 * c) + (float(1) / float(45045)) * t1 * t25 * si.w[2];
    float t26 = t2 * t2;
    float t27 = t26 * t2;
    float t28 = t27 * t27;
    float t29 = t28 * t2;
    float t30 = t29 * t29;
    float t31 = t30 * t2;
    float t32 = t9 * t9;
    float t33 = t32 * t9;
    float t34 = t33 * t33;
    float t35 = t34 * t9;
    float t36 = t35 * t35;
    float t37 = t36 * t9;
    G_E = (float(1) / float(45045)) * t1 * (si.w[3] * t1 * t20 + float(2) * t1 * t19 * si.w[2] + t7 * t18 * si.w[1] + float(3003) * t31 * si.w[0] - float(3003) * t37 * (si.w[3] + si.w[0] + si.w[1] + si.w[2]));
  }
  float g_factor = -float(15) * si.s * length;
  f = F * length;
  grad[0] = -(G_E * ab0 - G_ap * foot0) * g_factor;
  grad[1] = -(G_E * ab1 - G_ap * foot1) * g_factor;
  grad[2] = (G_ap * foot2 - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-16/2) dt
// Operations: 44 +, 97 *, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i16_w0_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
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
  float ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  float ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (cross_cross * si.s + ab_ab) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = ap_bp * si.s + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, c_minus_b);
    float t2 = float(1) / D;
    float t3 = float(1) / q1;
    float t4 = t3 * t3;
    float t5 = t4 * t4;
    float t6 = t5 * t3;
    float t7 = t4 * t3;
    float t8 = float(1) / c;
    float t9 = t8 * t8;
    float t10 = t9 * t8;
    float t11 = t9 * t9;
    float t12 = t11 * t8;
    float t13 = t7 * t7;
    float t14 = t10 * t10;
    float t15 = t13 * t3;
    float t16 = t14 * t8;
    F = (float(1) / float(215040)) * t2 * (float(13) * t2 * (float(11) * t2 * (float(128) * t6 * a_minus_b + float(3) * t2 * (float(48) * t5 * a_minus_b + float(7) * t2 * a * (float(8) * t7 * a_minus_b + float(8) * b * t10 + float(5) * t2 * (float(2) * t4 * a_minus_b + float(2) * b * t9 + float(3) * t2 * (b * t8 + t3 * a_minus_b + J2 * a) * a) * a) + float(48) * b * t11) * a + float(128) * b * t12) * a + float(1280) * t13 * a_minus_b + float(1280) * b * t14) * a + float(15360) * t15 * a_minus_b + float(15360) * b * t16) * si.w[0];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 (1 + s |P - Gamma(t)|^2)^(-16/2) dt
// Operations: 53 +, 128 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i16_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab1 * ab1 + ab2 * ab2 + ab0 * ab0;
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  float ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  float length = sqrt(ab_ab);
  float a = ab_ab * si.s;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = (ab_ab + cross_cross * si.s) * si.s;
  float a_minus_b = -ab_bp * si.s;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = ap_bp * si.s + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, c_minus_b);
    float t3 = float(1) / D;
    float t4 = float(1) / c;
    float t5 = t4 * t4;
    float t6 = t5 * t4;
    float t7 = float(1) / q1;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = t5 * t5;
    float t11 = t8 * t8;
    float t12 = t11 * t7;
    float t13 = t10 * t4;
    float t14 = t6 * t6;
    float t15 = t9 * t9;
    float t16 = t14 * t4;
    float t17 = t15 * t7;
    float t18 = float(13) * a * t3 * (float(11) * a * t3 * (float(3) * a * t3 * (float(7) * (float(8) * t6 * b + float(5) * (float(3) * a * t3 * (a_minus_b * t7 + t4 * b + J2 * a) + float(2) * t5 * b + float(2) * a_minus_b * t8) * a * t3 + float(8) * a_minus_b * t9) * a * t3 + float(48) * t10 * b + float(48) * a_minus_b * t11) + float(128) * a_minus_b * t12 + float(128) * t13 * b) + float(1280) * t14 * b + float(1280) * a_minus_b * t15) + float(15360) * t16 * b + float(15360) * a_minus_b * t17;
    F = (float(1) / float(215040)) * si.w[0] * t3 * t18;
    float t19 = t11 * t11;
    float t20 = t10 * t10;
    G_ap = (float(1) / float(229376)) * si.w[0] * (float(14336) * a_minus_b * t19 + float(14336) * t20 * b + a * t3 * t18) * t3;
    G_E = (float(1) / float(16)) * (t20 * si.w[0] - si.w[0] * t19) / a;
  }
  float g_factor = -float(16) * length * si.s;
  f = F * length;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = (foot1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = -g_factor * (G_E * ab2 - foot2 * G_ap);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-16/2) dt
// Operations: 47 +, 103 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i16_w1_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
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
  float bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (si.s * cross_cross + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, c_minus_b);
    float t2 = float(1) / c;
    float t3 = t2 * t2;
    float t4 = t3 * t2;
    float t5 = t4 * t4;
    float t6 = t5 * t2;
    float t7 = float(1) / D;
    float t8 = t3 * t3;
    float t9 = t8 * t2;
    float t10 = float(1) / q1;
    float t11 = t10 * t10;
    float t12 = t11 * t10;
    float t13 = t11 * t11;
    float t14 = t13 * t10;
    float t15 = t12 * t12;
    float t16 = t15 * t10;
    float t17 = float(15360) * t6 * b + float(13) * t7 * (float(11) * t7 * a * (float(128) * t9 * b + float(3) * (float(48) * t8 * b + float(7) * (float(5) * (float(2) * a_minus_b * t11 + float(2) * t3 * b + float(3) * t7 * a * (a_minus_b * t10 + t2 * b + a * J2)) * t7 * a + float(8) * a_minus_b * t12 + float(8) * t4 * b) * t7 * a + float(48) * a_minus_b * t13) * t7 * a + float(128) * a_minus_b * t14) + float(1280) * t5 * b + float(1280) * a_minus_b * t15) * a + float(15360) * a_minus_b * t16;
    F = (float(1) / float(215040)) * si.w[1] * (float(15360) * t6 + t7 * b * t17 - float(15360) * t16) / a + (float(1) / float(215040)) * si.w[0] * t7 * t17;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) (1 + s |P - Gamma(t)|^2)^(-16/2) dt
// Operations: 61 +, 147 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i16_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ap2 * ab2 + ap1 * ab1 + ap0 * ab0;
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
    foot0 = ap0 - ab_ap * t0 * ab0;
    foot1 = ap1 - ab_ap * t0 * ab1;
    foot2 = ap2 - ab_ap * ab2 * t0;
  }
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (ab_ab + si.s * cross_cross);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = atan(t1, c_minus_b) * t2;
    float t3 = float(1) / D;
    float t4 = float(1) / q1;
    float t5 = t4 * t4;
    float t6 = t5 * t5;
    float t7 = t6 * t4;
    float t8 = float(1) / c;
    float t9 = t8 * t8;
    float t10 = t9 * t9;
    float t11 = t10 * t8;
    float t12 = t9 * t8;
    float t13 = t5 * t4;
    float t14 = t12 * t12;
    float t15 = t13 * t13;
    float t16 = t14 * t8;
    float t17 = t15 * t4;
    float t18 = float(13) * t3 * (float(11) * t3 * a * (float(128) * t7 * a_minus_b + float(128) * t11 * b + float(3) * (float(7) * (float(8) * t12 * b + float(8) * t13 * a_minus_b + float(5) * t3 * a * (float(2) * t5 * a_minus_b + float(2) * t9 * b + float(3) * t3 * a * (t8 * b + J2 * a + t4 * a_minus_b))) * t3 * a + float(48) * t6 * a_minus_b + float(48) * t10 * b) * t3 * a) + float(1280) * t14 * b + float(1280) * t15 * a_minus_b) * a + float(15360) * t16 * b + float(15360) * t17 * a_minus_b;
    float t19 = float(1) / a;
    F = (float(1) / float(215040)) * si.w[0] * t3 * t18 - (float(1) / float(215040)) * si.w[1] * t19 * (float(15360) * t17 - float(15360) * t16 - t3 * t18 * b);
    float t20 = t10 * t10;
    float t21 = t6 * t6;
    float t22 = t3 * a * t18 + float(14336) * t20 * b + float(14336) * t21 * a_minus_b;
    G_ap = (float(1) / float(229376)) * si.w[0] * t3 * t22 - (float(1) / float(229376)) * (float(14336) * t21 - float(14336) * t20 - t3 * t22 * b) * si.w[1] * t19;
    G_E = (float(1) / float(3440640)) * (float(215040) * si.w[0] * t20 + si.w[1] * t3 * t18 - float(215040) * t21 * (si.w[0] + si.w[1])) * t19;
  }
  float g_factor = -float(16) * si.s * length;
  f = F * length;
  grad[0] = (foot0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = (G_ap * foot1 - G_E * ab1) * g_factor;
  grad[2] = -(G_E * ab2 - G_ap * foot2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-16/2) dt
// Operations: 50 +, 114 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i16_w2_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ap1 * ab1 + ab2 * ap2 + ap0 * ab0;
  float ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  float plain_cross0 = ab1 * ap2 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
  float plain_cross2 = ap1 * ab0 - ap0 * ab1;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  float ap_bp = bp2 * ap2 + ap1 * bp1 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = ap_ap * si.s + float(1);
  float D = (si.s * cross_cross + ab_ab) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = atan(t0, c_minus_b) * t1;
    float t2 = float(1) / a;
    float t3 = float(1) / q1;
    float t4 = t3 * t3;
    float t5 = t4 * t3;
    float t6 = t5 * t5;
    float t7 = t4 * t4;
    float t8 = t7 * t3;
    float t9 = float(1) / c;
    float t10 = t9 * t9;
    float t11 = float(1) / D;
    float t12 = t10 * t9;
    float t13 = t10 * t10;
    float t14 = t13 * t9;
    float t15 = t12 * t12;
    float t16 = float(1280) * a_minus_b * t6 + float(11) * (float(128) * a_minus_b * t8 + float(3) * (float(48) * a_minus_b * t7 + float(7) * (float(5) * (float(2) * a_minus_b * t4 + float(2) * b * t10 + float(3) * (b * t9 + a * J2 + a_minus_b * t3) * t11 * a) * t11 * a + float(8) * a_minus_b * t5 + float(8) * b * t12) * t11 * a + float(48) * b * t13) * t11 * a + float(128) * b * t14) * t11 * a + float(1280) * b * t15;
    float t17 = t6 * t3;
    float t18 = t15 * t9;
    float t19 = float(13) * t16 * t11 * a + float(15360) * a_minus_b * t17 + float(15360) * b * t18;
    float t20 = float(15360) * t17 - b * t11 * t19 - float(15360) * t18;
    F = (float(1) / float(215040)) * si.w[2] * t2 * (float(14) * t16 * t11 - c * t11 * t19 - float(2) * b * t2 * t20) + (float(1) / float(215040)) * t11 * si.w[0] * t19 - (float(1) / float(215040)) * si.w[1] * t2 * t20;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) (1 + s |P - Gamma(t)|^2)^(-16/2) dt
// Operations: 69 +, 171 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i16_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  float ab_ap = ab0 * ap0 + ap1 * ab1 + ap2 * ab2;
  float ap_ap = ap1 * ap1 + ap2 * ap2 + ap0 * ap0;
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
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = bp1 * ab1 + ab0 * bp0 + bp2 * ab2;
  float ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = ab_ap * si.s;
  float c = si.s * ap_ap + float(1);
  float D = si.s * (cross_cross * si.s + ab_ab);
  float a_minus_b = -si.s * ab_bp;
  float q1 = bp_bp * si.s + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = atan(t1, c_minus_b) * t2;
    float t3 = float(1) / c;
    float t4 = t3 * t3;
    float t5 = t4 * t3;
    float t6 = t5 * t5;
    float t7 = t6 * t3;
    float t8 = t4 * t4;
    float t9 = t8 * t3;
    float t10 = float(1) / D;
    float t11 = float(1) / q1;
    float t12 = t11 * t11;
    float t13 = t12 * t11;
    float t14 = t12 * t12;
    float t15 = t14 * t11;
    float t16 = t13 * t13;
    float t17 = float(1280) * b * t6 + float(11) * (float(128) * b * t9 + float(3) * t10 * (float(48) * b * t8 + float(7) * (float(8) * b * t5 + float(8) * a_minus_b * t13 + float(5) * t10 * a * (float(2) * b * t4 + float(3) * (J2 * a + a_minus_b * t11 + b * t3) * t10 * a + float(2) * a_minus_b * t12)) * t10 * a + float(48) * a_minus_b * t14) * a + float(128) * a_minus_b * t15) * t10 * a + float(1280) * a_minus_b * t16;
    float t18 = t16 * t11;
    float t19 = float(15360) * b * t7 + float(13) * t17 * t10 * a + float(15360) * a_minus_b * t18;
    float t20 = float(15360) * t7 + b * t19 * t10 - float(15360) * t18;
    float t21 = float(1) / a;
    F = (float(1) / float(215040)) * si.w[0] * t19 * t10 + (float(1) / float(215040)) * t20 * si.w[1] * t21 + (float(1) / float(215040)) * si.w[2] * (float(14) * t17 * t10 + float(2) * t20 * b * t21 - t19 * c * t10) * t21;
    float t22 = t14 * t14;
    float t23 = t8 * t8;
    float t24 = float(14336) * a_minus_b * t22 + float(14336) * b * t23 + t19 * t10 * a;
    float t25 = t24 * b * t10 + float(14336) * t23 - float(14336) * t22;
    G_ap = (float(1) / float(229376)) * t25 * si.w[1] * t21 + (float(1) / float(229376)) * t24 * si.w[0] * t10 - (float(1) / float(3440640)) * (float(15) * t24 * c * t10 - float(16) * t19 * t10 - float(30) * t25 * b * t21) * si.w[2] * t21;
    G_E = (float(1) / float(3440640)) * (float(2) * t20 * si.w[2] * t21 + t19 * si.w[1] * t10 + float(215040) * si.w[0] * t23 - float(215040) * t22 * (si.w[0] + si.w[1] + si.w[2])) * t21;
  }
  float g_factor = -float(16) * length * si.s;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = g_factor * (G_ap * foot1 - G_E * ab1);
  grad[2] = g_factor * (foot2 * G_ap - G_E * ab2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-16/2) dt
// Operations: 55 +, 128 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i16_w3_f(SegmentInput si) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab0 * ab0 + ab1 * ab1;
  float ab_ap = ap0 * ab0 + ap1 * ab1 + ab2 * ap2;
  float ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  float plain_cross0 = ab1 * ap2 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
  float plain_cross2 = ap1 * ab0 - ap0 * ab1;
  float plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  float ap_bp = bp2 * ap2 + ap1 * bp1 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = ap_ap * si.s + float(1);
  float D = si.s * (ab_ab + si.s * cross_cross);
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(D);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, c_minus_b);
    float t2 = float(1) / D;
    float t3 = float(1) / q1;
    float t4 = t3 * t3;
    float t5 = t4 * t3;
    float t6 = t5 * t5;
    float t7 = float(1) / c;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = t9 * t9;
    float t11 = t4 * t4;
    float t12 = t8 * t8;
    float t13 = t11 * t3;
    float t14 = t12 * t7;
    float t15 = float(1280) * a_minus_b * t6 + float(1280) * t10 * b + float(11) * t2 * a * (float(3) * t2 * a * (float(48) * a_minus_b * t11 + float(7) * (float(8) * a_minus_b * t5 + float(8) * t9 * b + float(5) * (float(2) * a_minus_b * t4 + float(2) * t8 * b + float(3) * t2 * a * (a * J2 + t7 * b + a_minus_b * t3)) * t2 * a) * t2 * a + float(48) * t12 * b) + float(128) * a_minus_b * t13 + float(128) * t14 * b);
    float t16 = t10 * t7;
    float t17 = t6 * t3;
    float t18 = float(13) * t2 * t15 * a + float(15360) * a_minus_b * t17 + float(15360) * t16 * b;
    float t19 = float(15360) * t16 + t18 * t2 * b - float(15360) * t17;
    float t20 = float(1) / a;
    float t21 = float(14) * t2 * t15 + float(2) * t19 * t20 * b - t18 * c * t2;
    F = (float(1) / float(215040)) * si.w[2] * t21 * t20 + (float(1) / float(215040)) * t19 * t20 * si.w[1] + (float(1) / float(215040)) * t18 * si.w[0] * t2 - (float(1) / float(215040)) * si.w[3] * t20 * (c * t19 * t20 - float(14) * (float(1280) * t10 + t2 * t15 * b - float(1280) * t6) * t20 - float(2) * t21 * t20 * b);
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 + s |P - Gamma(t)|^2)^(-16/2) dt
// Operations: 79 +, 199 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_cauchy_i16_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  float f;
  float ab0 = si.b[0] - si.a[0];
  float ap0 = si.p[0] - si.a[0];
  float bp0 = si.p[0] - si.b[0];
  float ab1 = si.b[1] - si.a[1];
  float ap1 = si.p[1] - si.a[1];
  float bp1 = si.p[1] - si.b[1];
  float ab2 = si.b[2] - si.a[2];
  float ap2 = si.p[2] - si.a[2];
  float bp2 = si.p[2] - si.b[2];
  float ab_ab = ab2 * ab2 + ab1 * ab1 + ab0 * ab0;
  float ab_ap = ap0 * ab0 + ap2 * ab2 + ap1 * ab1;
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
    foot0 = ap0 - t0 * ab0 * ab_ap;
    foot1 = ap1 - t0 * ab1 * ab_ap;
    foot2 = ap2 - t0 * ab2 * ab_ap;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  float length = sqrt(ab_ab);
  float a = si.s * ab_ab;
  float b = si.s * ab_ap;
  float c = si.s * ap_ap + float(1);
  float D = (ab_ab + si.s * cross_cross) * si.s;
  float a_minus_b = -si.s * ab_bp;
  float q1 = si.s * bp_bp + float(1);
  float c_minus_b = si.s * ap_bp + float(1);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(D);
    float t2 = float(1) / t1;
    float J2 = atan(t1, c_minus_b) * t2;
    float t3 = float(1) / D;
    float t4 = float(1) / q1;
    float t5 = t4 * t4;
    float t6 = t5 * t5;
    float t7 = t6 * t4;
    float t8 = float(1) / c;
    float t9 = t8 * t8;
    float t10 = t9 * t9;
    float t11 = t10 * t8;
    float t12 = t5 * t4;
    float t13 = t9 * t8;
    float t14 = t12 * t12;
    float t15 = t13 * t13;
    float t16 = float(11) * (float(128) * t7 * a_minus_b + float(128) * t11 * b + float(3) * (float(48) * t10 * b + float(48) * t6 * a_minus_b + float(7) * (float(5) * (float(3) * (J2 * a + t8 * b + t4 * a_minus_b) * t3 * a + float(2) * t9 * b + float(2) * t5 * a_minus_b) * t3 * a + float(8) * t12 * a_minus_b + float(8) * t13 * b) * t3 * a) * t3 * a) * t3 * a + float(1280) * t14 * a_minus_b + float(1280) * t15 * b;
    float t17 = t15 * t8;
    float t18 = t14 * t4;
    float t19 = float(13) * t16 * t3 * a + float(15360) * t17 * b + float(15360) * t18 * a_minus_b;
    float t20 = float(1) / a;
    float t21 = float(15360) * t18 - float(15360) * t17 - t3 * b * t19;
    float t22 = float(2) * t21 * t20 * b + c * t3 * t19 - float(14) * t16 * t3;
    F = (float(1) / float(215040)) * t3 * si.w[0] * t19 + (float(1) / float(215040)) * si.w[3] * t20 * (t21 * c * t20 - float(14) * t20 * (float(1280) * t14 - float(1280) * t15 - t16 * t3 * b) - float(2) * t22 * t20 * b) - (float(1) / float(215040)) * t22 * si.w[2] * t20 - (float(1) / float(215040)) * t21 * t20 * si.w[1];
    float t23 = t10 * t10;
    float t24 = t6 * t6;
    float t25 = float(14336) * t23 * b + float(14336) * t24 * a_minus_b + t3 * a * t19;
    float t26 = float(14336) * t23 + t3 * t25 * b - float(14336) * t24;
    float t27 = float(16) * t3 * t19 + float(30) * t20 * b * t26 - float(15) * c * t3 * t25;
    G_ap = (float(1) / float(229376)) * t20 * si.w[1] * t26 + (float(1) / float(3440640)) * si.w[2] * t20 * t27 + (float(1) / float(229376)) * t3 * si.w[0] * t25 + (float(1) / float(3440640)) * (float(2) * t20 * t27 * b - float(15) * c * t20 * t26 - float(16) * t21 * t20) * si.w[3] * t20;
    G_E = -(float(1) / float(3440640)) * t20 * (float(215040) * t24 * (si.w[2] + si.w[3] + si.w[0] + si.w[1]) + float(3) * t22 * si.w[3] * t20 + float(2) * t21 * si.w[2] * t20 - t3 * si.w[1] * t19 - float(215040) * t23 * si.w[0]);
  }
  float g_factor = -float(16) * length * si.s;
  f = length * F;
  grad[0] = -g_factor * (G_E * ab0 - foot0 * G_ap);
  grad[1] = (G_ap * foot1 - G_E * ab1) * g_factor;
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return f;
}

