// generated/glsl/segment_inverse.glsl - segment kernels of the inverse family in GLSL (float; ES 3.00 and 4.50), generic forms only.
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
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-1) dt
// Operations: 25 +, 29 *, 2 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
float segment_inverse_i1_w0_f(SegmentInput si) {
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
  float plain_cross1 = ab2 * ap0 - ap2 * ab0;
  float plain_cross2 = ap1 * ab0 - ab1 * ap0;
  float plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    X = length * (r1 * ab_ap + a_minus_b * r0) / cross_cross;
  }
  float J1 = skelconv_asinh(X) / length;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    F = si.w[0] * J1;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-1) dt
// Operations: 33 +, 53 *, 7 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
float segment_inverse_i1_w0_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t1 = float(1) / cross_cross;
    X = length * t1 * (r1 * ab_ap + r0 * a_minus_b);
  }
  float t2 = float(1) / length;
  float J1 = skelconv_asinh(X) * t2;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    F = J1 * si.w[0];
    float t3 = float(1) / r1;
    float t4 = float(1) / r0;
    float t5 = float(1) / cross_cross;
    G_ap = (t3 * a_minus_b + t4 * ab_ap) * si.w[0] * t5;
    float t6 = float(1) / ab_ab;
    G_E = -t6 * (si.w[0] * t3 - si.w[0] * t4);
  }
  float g_factor = -length;
  f = F * length;
  grad[0] = -(ab0 * G_E - G_ap * foot0) * g_factor;
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = (G_ap * foot2 - ab2 * G_E) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-1) dt
// Operations: 28 +, 33 *, 3 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
float segment_inverse_i1_w1_f(SegmentInput si) {
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
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    X = length * (r1 * ab_ap + a_minus_b * r0) / cross_cross;
  }
  float t0 = float(1) / length;
  float J1 = t0 * skelconv_asinh(X);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / ab_ab;
    F = J1 * si.w[0] + (r1 + ab_ap * J1 - r0) * si.w[1] * t1;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-1) dt
// Operations: 41 +, 61 *, 7 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
float segment_inverse_i1_w1_f_and_grad(SegmentInput si, out vec3 grad) {
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
    foot2 = ap2 - ab_ap * ab2 * t0;
  }
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
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
  float J1 = skelconv_asinh(X) * t2;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t3 = float(1) / ab_ab;
    F = si.w[0] * J1 + (ab_ap * J1 + r1 - r0) * si.w[1] * t3;
    float t4 = float(1) / r1;
    float t5 = float(1) / r0;
    float t6 = a_minus_b * t4 + ab_ap * t5;
    float t7 = float(1) / cross_cross;
    G_ap = si.w[0] * t6 * t7 - (t4 - t5 - ab_ap * t6 * t7) * si.w[1] * t3;
    G_E = (J1 * si.w[1] + si.w[0] * t5 - t4 * (si.w[0] + si.w[1])) * t3;
  }
  float g_factor = -length;
  f = length * F;
  grad[0] = -(ab0 * G_E - foot0 * G_ap) * g_factor;
  grad[1] = g_factor * (foot1 * G_ap - ab1 * G_E);
  grad[2] = (G_ap * foot2 - ab2 * G_E) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-1) dt
// Operations: 33 +, 45 *, 3 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
float segment_inverse_i1_w2_f(SegmentInput si) {
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
  float ab_ap = ab1 * ap1 + ap0 * ab0 + ab2 * ap2;
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
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    X = length * (r0 * a_minus_b + r1 * ab_ap) / cross_cross;
  }
  float t0 = float(1) / length;
  float J1 = skelconv_asinh(X) * t0;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = r0 - ab_ap * J1 - r1;
    float t2 = float(1) / ab_ab;
    F = si.w[0] * J1 - si.w[1] * t1 * t2 - (float(1) / float(2)) * si.w[2] * t2 * (float(2) * ap_ap * J1 + float(4) * t1 * t2 * ab_ap - (r1 * a_minus_b + r0 * ab_ap + cross_cross * J1) * t2);
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-1) dt
// Operations: 51 +, 83 *, 7 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
float segment_inverse_i1_w2_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t1 = float(1) / cross_cross;
    X = length * (a_minus_b * r0 + r1 * ab_ap) * t1;
  }
  float t2 = float(1) / length;
  float J1 = skelconv_asinh(X) * t2;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t3 = r0 - J1 * ab_ap - r1;
    float t4 = float(1) / ab_ab;
    F = J1 * si.w[0] - si.w[1] * t3 * t4 - (float(1) / float(2)) * si.w[2] * t4 * (float(2) * ap_ap * J1 + float(4) * t3 * t4 * ab_ap - t4 * (r0 * ab_ap + a_minus_b * r1 + J1 * cross_cross));
    float t5 = float(1) / r1;
    float t6 = float(1) / r0;
    float t7 = a_minus_b * t5 + t6 * ab_ap;
    float t8 = float(1) / cross_cross;
    float t9 = t5 - t7 * t8 * ab_ap - t6;
    G_ap = t7 * t8 * si.w[0] - si.w[2] * t4 * (ap_ap * t7 * t8 + float(2) * t4 * t9 * ab_ap - J1) - si.w[1] * t4 * t9;
    G_E = (t6 * si.w[0] + si.w[1] * J1 - (si.w[1] + si.w[2] + si.w[0]) * t5 - float(2) * t3 * si.w[2] * t4) * t4;
  }
  float g_factor = -length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = g_factor * (foot1 * G_ap - ab1 * G_E);
  grad[2] = (G_ap * foot2 - ab2 * G_E) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-1) dt
// Operations: 38 +, 62 *, 3 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
float segment_inverse_i1_w3_f(SegmentInput si) {
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
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    X = length * (a_minus_b * r0 + r1 * ab_ap) / cross_cross;
  }
  float t0 = float(1) / length;
  float J1 = skelconv_asinh(X) * t0;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / ab_ab;
    float t2 = cross_cross * J1 + r1 * a_minus_b + ab_ap * r0;
    float t3 = r1 + ab_ap * J1 - r0;
    float t4 = float(2) * ap_ap * J1 - float(4) * t3 * t1 * ab_ap - t2 * t1;
    F = si.w[0] * J1 + (float(1) / float(6)) * si.w[3] * t1 * (t1 * (float(3) * t2 * t1 * ab_ap + float(2) * bp_bp * r1 - float(2) * ap_ap * r0) - float(6) * t3 * ap_ap * t1 - float(6) * t4 * t1 * ab_ap) + t3 * t1 * si.w[1] - (float(1) / float(2)) * si.w[2] * t4 * t1;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-1) dt
// Operations: 61 +, 115 *, 7 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
float segment_inverse_i1_w3_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float J1 = t2 * skelconv_asinh(X);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t3 = float(1) / ab_ab;
    float t4 = r1 * a_minus_b + r0 * ab_ap + J1 * cross_cross;
    float t5 = r0 - J1 * ab_ap - r1;
    float t6 = t3 * t4 - float(4) * t3 * ab_ap * t5 - float(2) * J1 * ap_ap;
    F = J1 * si.w[0] + (float(1) / float(2)) * t3 * t6 * si.w[2] + (float(1) / float(6)) * si.w[3] * t3 * (float(6) * t3 * ap_ap * t5 + float(6) * t3 * t6 * ab_ap - t3 * (float(2) * r0 * ap_ap - float(3) * t3 * ab_ap * t4 - float(2) * r1 * bp_bp)) - t3 * si.w[1] * t5;
    float t7 = float(1) / r0;
    float t8 = float(1) / r1;
    float t9 = t7 * ab_ap + t8 * a_minus_b;
    float t10 = float(1) / cross_cross;
    float t11 = t8 - t9 * t10 * ab_ap - t7;
    float t12 = J1 - t9 * t10 * ap_ap - float(2) * t11 * t3 * ab_ap;
    G_ap = t12 * t3 * si.w[2] + si.w[0] * t9 * t10 + si.w[3] * t3 * (t11 * t3 * ap_ap + float(2) * t12 * t3 * ab_ap - t3 * t5) - t11 * t3 * si.w[1];
    G_E = -(float(1) / float(2)) * t3 * (float(4) * t3 * si.w[2] * t5 + float(2) * (si.w[3] + si.w[0] + si.w[1] + si.w[2]) * t8 - float(2) * J1 * si.w[1] - float(2) * t7 * si.w[0] - float(3) * si.w[3] * t3 * t6);
  }
  float g_factor = -length;
  f = length * F;
  grad[0] = -(ab0 * G_E - G_ap * foot0) * g_factor;
  grad[1] = -(ab1 * G_E - foot1 * G_ap) * g_factor;
  grad[2] = -g_factor * (ab2 * G_E - G_ap * foot2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-2) dt
// Operations: 18 +, 17 *, 1 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i2_w0_f(SegmentInput si) {
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
  float plain_cross0 = ap2 * ab1 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ap2 * ab0;
  float plain_cross2 = ap1 * ab0 - ap0 * ab1;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float J2 = atan(t0, ap_bp) / t0;
    F = si.w[0] * J2;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-2) dt
// Operations: 35 +, 56 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i2_w0_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  float ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
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
  float ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  float ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, ap_bp);
    F = J2 * si.w[0];
    float t3 = float(1) / cross_cross;
    float t4 = float(1) / ap_ap;
    float t5 = float(1) / bp_bp;
    G_ap = (float(1) / float(2)) * t3 * (ab_ap * t4 + J2 * ab_ab + t5 * a_minus_b) * si.w[0];
    float t6 = float(1) / ab_ab;
    G_E = -(float(1) / float(2)) * (t5 * si.w[0] - t4 * si.w[0]) * t6;
  }
  float g_factor = -float(2) * length;
  f = length * F;
  grad[0] = (foot0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = -(ab1 * G_E - foot1 * G_ap) * g_factor;
  grad[2] = -g_factor * (G_E * ab2 - foot2 * G_ap);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-2) dt
// Operations: 26 +, 30 *, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float segment_inverse_i2_w1_f(SegmentInput si) {
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
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float log_ratio = log(bp_bp / ap_ap);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float J2 = atan(t0, ap_bp) / t0;
    F = si.w[0] * J2 + (float(1) / float(2)) * (log_ratio + float(2) * ab_ap * J2) * si.w[1] / ab_ab;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-2) dt
// Operations: 42 +, 68 *, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float segment_inverse_i2_w1_f_and_grad(SegmentInput si, out vec3 grad) {
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
    F = J2 * si.w[0] + (float(1) / float(2)) * si.w[1] * (float(2) * ab_ap * J2 + log_ratio) * t4;
    float t5 = float(1) / cross_cross;
    float t6 = float(1) / bp_bp;
    float t7 = J2 * ab_ab + ab_ap * t1 + t6 * a_minus_b;
    G_ap = (float(1) / float(2)) * t5 * si.w[0] * t7 + (float(1) / float(2)) * (t1 + t5 * ab_ap * t7 - t6) * si.w[1] * t4;
    G_E = -(float(1) / float(2)) * (t6 * (si.w[0] + si.w[1]) - si.w[0] * t1 - J2 * si.w[1]) * t4;
  }
  float g_factor = -float(2) * length;
  f = length * F;
  grad[0] = -(ab0 * G_E - foot0 * G_ap) * g_factor;
  grad[1] = (foot1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = -(G_E * ab2 - G_ap * foot2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-2) dt
// Operations: 29 +, 36 *, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float segment_inverse_i2_w2_f(SegmentInput si) {
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
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float log_ratio = log(bp_bp / ap_ap);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float J2 = atan(t0, ap_bp) / t0;
    float t1 = float(1) / ab_ab;
    float t2 = log_ratio + float(2) * ab_ap * J2;
    F = J2 * si.w[0] + (ab_ap * t1 * t2 + float(1) - ap_ap * J2) * si.w[2] * t1 + (float(1) / float(2)) * si.w[1] * t1 * t2;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-2) dt
// Operations: 50 +, 84 *, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float segment_inverse_i2_w2_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
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
    float t4 = float(2) * ab_ap * J2 + log_ratio;
    float t5 = float(1) / ab_ab;
    F = (ab_ap * t4 * t5 + float(1) - J2 * ap_ap) * si.w[2] * t5 + (float(1) / float(2)) * si.w[1] * t4 * t5 + si.w[0] * J2;
    float t6 = float(1) / cross_cross;
    float t7 = float(1) / bp_bp;
    float t8 = J2 * ab_ab + ab_ap * t1 + t7 * a_minus_b;
    float t9 = t6 * ab_ap * t8 + t1 - t7;
    G_ap = (float(1) / float(2)) * si.w[1] * t5 * t9 + (float(1) / float(2)) * t6 * si.w[0] * t8 - (float(1) / float(2)) * si.w[2] * (t6 * ap_ap * t8 - float(2) * ab_ap * t5 * t9 - float(2) * J2) * t5;
    G_E = (float(1) / float(2)) * (si.w[0] * t1 + t4 * si.w[2] * t5 + si.w[1] * J2 - t7 * (si.w[0] + si.w[1] + si.w[2])) * t5;
  }
  float g_factor = -float(2) * length;
  f = length * F;
  grad[0] = -g_factor * (G_E * ab0 - foot0 * G_ap);
  grad[1] = (foot1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = -(G_E * ab2 - G_ap * foot2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-2) dt
// Operations: 34 +, 46 *, 3 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float segment_inverse_i2_w3_f(SegmentInput si) {
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
  float ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  float length = sqrt(ab_ab);
  float log_ratio = log(bp_bp / ap_ap);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float J2 = atan(t0, ap_bp) / t0;
    float t1 = float(2) * J2 * ab_ap + log_ratio;
    float t2 = float(1) / ab_ab;
    float t3 = ap_ap * J2 - t1 * t2 * ab_ap - float(1);
    F = si.w[0] * J2 + (float(1) / float(2)) * t1 * t2 * si.w[1] + (float(1) / float(2)) * ((bp_bp + float(2) * ab_ap - ap_ap) * t2 - ap_ap * t1 * t2 - float(4) * t2 * t3 * ab_ap) * si.w[3] * t2 - si.w[2] * t2 * t3;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-2) dt
// Operations: 60 +, 106 *, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float segment_inverse_i2_w3_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  float ap_bp = bp0 * ap0 + bp1 * ap1 + bp2 * ap2;
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
    float t4 = float(1) / ab_ab;
    float t5 = float(2) * ab_ap * J2 + log_ratio;
    float t6 = ap_ap * J2 - t4 * ab_ap * t5 - float(1);
    F = (float(1) / float(2)) * t4 * si.w[1] * t5 + si.w[0] * J2 - t6 * t4 * si.w[2] - (float(1) / float(2)) * si.w[3] * (ap_ap * t4 * t5 + (ap_ap - float(2) * ab_ap - bp_bp) * t4 + float(4) * t6 * t4 * ab_ap) * t4;
    float t7 = float(1) / bp_bp;
    float t8 = ab_ab * J2 + a_minus_b * t7 + t1 * ab_ap;
    float t9 = float(1) / cross_cross;
    float t10 = t8 * t9 * ab_ap + t1 - t7;
    float t11 = float(2) * t4 * ab_ap * t10 + float(2) * J2 - ap_ap * t8 * t9;
    G_ap = (float(1) / float(2)) * si.w[3] * t4 * (float(2) * t4 * ab_ap * t11 + t4 * t5 - ap_ap * t4 * t10) + (float(1) / float(2)) * t8 * si.w[0] * t9 + (float(1) / float(2)) * t4 * t11 * si.w[2] + (float(1) / float(2)) * t4 * si.w[1] * t10;
    G_E = -(float(1) / float(2)) * t4 * ((si.w[3] + si.w[0] + si.w[1] + si.w[2]) * t7 + float(3) * si.w[3] * t6 * t4 - t1 * si.w[0] - t4 * t5 * si.w[2] - si.w[1] * J2);
  }
  float g_factor = -float(2) * length;
  f = F * length;
  grad[0] = -(ab0 * G_E - G_ap * foot0) * g_factor;
  grad[1] = -(ab1 * G_E - foot1 * G_ap) * g_factor;
  grad[2] = g_factor * (G_ap * foot2 - ab2 * G_E);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-3) dt
// Operations: 25 +, 26 *, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i3_w0_f(SegmentInput si) {
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
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    F = (a_minus_b / r1 + ab_ap / r0) * si.w[0] / cross_cross;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-3) dt
// Operations: 34 +, 61 *, 7 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i3_w0_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / cross_cross;
    float t2 = float(1) / r1;
    float t3 = float(1) / r0;
    float t4 = t2 * a_minus_b + ab_ap * t3;
    F = t1 * t4 * si.w[0];
    G_ap = (float(1) / float(3)) * (ab_ap * t3 / ap_ap + float(2) * ab_ab * t1 * t4 + t2 * a_minus_b / bp_bp) * t1 * si.w[0];
    float t5 = float(1) / ab_ab;
    float t6 = t2 * t2;
    float t7 = t6 * t2;
    float t8 = t3 * t3;
    float t9 = t8 * t3;
    G_E = -(float(1) / float(3)) * t5 * (t7 * si.w[0] - si.w[0] * t9);
  }
  float g_factor = -float(3) * length;
  f = length * F;
  grad[0] = -(ab0 * G_E - G_ap * foot0) * g_factor;
  grad[1] = -(ab1 * G_E - G_ap * foot1) * g_factor;
  grad[2] = (G_ap * foot2 - ab2 * G_E) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-3) dt
// Operations: 28 +, 32 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i3_w1_f(SegmentInput si) {
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
  float ab_bp = ab2 * bp2 + ab0 * bp0 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / cross_cross;
    float t1 = float(1) / r0;
    float t2 = float(1) / r1;
    float t3 = t1 * ab_ap + a_minus_b * t2;
    F = t0 * t3 * si.w[0] - si.w[1] * (t2 - t0 * ab_ap * t3 - t1) / ab_ab;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-3) dt
// Operations: 42 +, 78 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i3_w1_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / cross_cross;
    float t2 = float(1) / r1;
    float t3 = float(1) / r0;
    float t4 = a_minus_b * t2 + ab_ap * t3;
    float t5 = float(1) / ab_ab;
    F = t1 * si.w[0] * t4 - si.w[1] * t5 * (t2 - t1 * ab_ap * t4 - t3);
    float t6 = t2 * t2;
    float t7 = t3 * t3;
    float t8 = float(2) * t1 * t4 * ab_ab + t6 * a_minus_b * t2 + ab_ap * t7 * t3;
    G_ap = (float(1) / float(3)) * (t1 * ab_ap * t8 + t7 * t3 - t6 * t2) * si.w[1] * t5 + (float(1) / float(3)) * t1 * si.w[0] * t8;
    float t9 = t3 * t3;
    float t10 = t9 * t3;
    float t11 = t2 * t2;
    float t12 = t11 * t2;
    G_E = (float(1) / float(3)) * t5 * (t1 * t4 * si.w[1] + si.w[0] * t10 - (si.w[0] + si.w[1]) * t12);
  }
  float g_factor = -float(3) * length;
  f = length * F;
  grad[0] = -(G_E * ab0 - foot0 * G_ap) * g_factor;
  grad[1] = (foot1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = (G_ap * foot2 - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-3) dt
// Operations: 32 +, 45 *, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
float segment_inverse_i3_w2_f(SegmentInput si) {
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
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
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
  float J1 = skelconv_asinh(X) * t1;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t2 = float(1) / r0;
    float t3 = float(1) / r1;
    float t4 = ab_ap * t2 + t3 * a_minus_b;
    float t5 = float(1) / cross_cross;
    float t6 = ab_ap * t4 * t5 + t2 - t3;
    float t7 = float(1) / ab_ab;
    F = si.w[1] * t6 * t7 + (float(2) * ab_ap * t6 * t7 + J1 - t4 * ap_ap * t5) * si.w[2] * t7 + t4 * t5 * si.w[0];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-3) dt
// Operations: 51 +, 103 *, 7 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
float segment_inverse_i3_w2_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t1 = float(1) / cross_cross;
    X = t1 * length * (r1 * ab_ap + a_minus_b * r0);
  }
  float t2 = float(1) / length;
  float J1 = t2 * skelconv_asinh(X);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t3 = float(1) / cross_cross;
    float t4 = float(1) / r1;
    float t5 = float(1) / r0;
    float t6 = t4 * a_minus_b + ab_ap * t5;
    float t7 = t3 * ab_ap * t6 + t5 - t4;
    float t8 = float(1) / ab_ab;
    F = t3 * t6 * si.w[0] + (J1 + float(2) * ab_ap * t7 * t8 - t3 * ap_ap * t6) * si.w[2] * t8 + t7 * si.w[1] * t8;
    float t9 = t4 * t4;
    float t10 = t5 * t5;
    float t11 = t4 * t9 * a_minus_b + ab_ap * t10 * t5 + float(2) * t3 * t6 * ab_ab;
    float t12 = t3 * ab_ap * t11 + t10 * t5 - t4 * t9;
    G_ap = (float(1) / float(3)) * t3 * t11 * si.w[0] + (float(1) / float(3)) * si.w[2] * t8 * (float(3) * t3 * t6 + float(2) * ab_ap * t8 * t12 - t3 * ap_ap * t11) + (float(1) / float(3)) * si.w[1] * t8 * t12;
    float t13 = t5 * t5;
    float t14 = t13 * t5;
    float t15 = t4 * t4;
    float t16 = t15 * t4;
    G_E = (float(1) / float(3)) * (t3 * si.w[1] * t6 + t14 * si.w[0] + float(2) * t7 * si.w[2] * t8 - t16 * (si.w[1] + si.w[2] + si.w[0])) * t8;
  }
  float g_factor = -float(3) * length;
  f = length * F;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = g_factor * (foot1 * G_ap - G_E * ab1);
  grad[2] = g_factor * (G_ap * foot2 - G_E * ab2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-3) dt
// Operations: 37 +, 54 *, 6 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
float segment_inverse_i3_w3_f(SegmentInput si) {
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
  float plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
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
  float J1 = skelconv_asinh(X) * t1;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t2 = float(1) / ab_ab;
    float t3 = float(1) / r0;
    float t4 = float(1) / r1;
    float t5 = ab_ap * t3 + t4 * a_minus_b;
    float t6 = float(1) / cross_cross;
    float t7 = t5 * t6 * ab_ap + t3 - t4;
    float t8 = float(2) * t7 * t2 * ab_ap + J1 - ap_ap * t5 * t6;
    F = si.w[2] * t2 * t8 + si.w[0] * t5 * t6 + t7 * t2 * si.w[1] + si.w[3] * t2 * (float(2) * t2 * t8 * ab_ap + (r1 + ab_ap * J1 - r0) * t2 - ap_ap * t7 * t2);
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-3) dt
// Operations: 61 +, 125 *, 7 /, 3 sqrt, 0 atan, 1 log/asinh (generic form).
float segment_inverse_i3_w3_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float ab_bp = ab2 * bp2 + bp1 * ab1 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float X;
  {
    // P projects onto [A,B]: X = sqrta((a-b)r0 + b r1)/D
    float t1 = float(1) / cross_cross;
    X = length * t1 * (r1 * ab_ap + r0 * a_minus_b);
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
    float t5 = t3 * a_minus_b + t4 * ab_ap;
    float t6 = float(1) / cross_cross;
    float t7 = float(1) / ab_ab;
    float t8 = t4 + t5 * t6 * ab_ap - t3;
    float t9 = t5 * t6 * ap_ap - J1 - float(2) * t7 * ab_ap * t8;
    F = si.w[0] * t5 * t6 + t7 * si.w[1] * t8 - t7 * t9 * si.w[2] - t7 * (float(2) * t7 * t9 * ab_ap + t7 * t8 * ap_ap + t7 * (r0 - r1 - J1 * ab_ap)) * si.w[3];
    float t10 = t3 * t3;
    float t11 = t4 * t4;
    float t12 = t4 * ab_ap * t11 + float(2) * t5 * ab_ab * t6 + t3 * t10 * a_minus_b;
    float t13 = t3 * t10 - t12 * t6 * ab_ap - t4 * t11;
    float t14 = float(2) * t7 * t13 * ab_ap + t12 * t6 * ap_ap - float(3) * t5 * t6;
    G_ap = (float(1) / float(3)) * t7 * (float(3) * t7 * t8 + t7 * t13 * ap_ap - float(2) * t7 * ab_ap * t14) * si.w[3] + (float(1) / float(3)) * si.w[0] * t12 * t6 - (float(1) / float(3)) * t7 * si.w[2] * t14 - (float(1) / float(3)) * t7 * si.w[1] * t13;
    float t15 = t3 * t3;
    float t16 = t15 * t3;
    float t17 = t4 * t4;
    float t18 = t17 * t4;
    G_E = -(float(1) / float(3)) * t7 * ((si.w[0] + si.w[1] + si.w[2] + si.w[3]) * t16 + float(3) * t7 * t9 * si.w[3] - float(2) * t7 * si.w[2] * t8 - t5 * si.w[1] * t6 - si.w[0] * t18);
  }
  float g_factor = -float(3) * length;
  f = length * F;
  grad[0] = g_factor * (G_ap * foot0 - ab0 * G_E);
  grad[1] = g_factor * (foot1 * G_ap - ab1 * G_E);
  grad[2] = (G_ap * foot2 - ab2 * G_E) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-4) dt
// Operations: 28 +, 33 *, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i4_w0_f(SegmentInput si) {
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
  float ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, ap_bp);
    float t2 = float(1) / cross_cross;
    F = (float(1) / float(2)) * t2 * (ab_ap / ap_ap + ab_ab * J2 + a_minus_b / bp_bp) * si.w[0];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-4) dt
// Operations: 37 +, 67 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i4_w0_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float ab_ap = ap1 * ab1 + ab0 * ap0 + ab2 * ap2;
  float ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
  float plain_cross0 = ap2 * ab1 - ab2 * ap1;
  float plain_cross1 = ab2 * ap0 - ab0 * ap2;
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
    foot0 = ap0 - ab0 * t0 * ab_ap;
    foot1 = ap1 - t0 * ab_ap * ab1;
    foot2 = ap2 - t0 * ab2 * ab_ap;
  }
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = ab0 * bp0 + ab2 * bp2 + bp1 * ab1;
  float ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, ap_bp);
    float t3 = float(1) / cross_cross;
    float t4 = float(1) / ap_ap;
    float t5 = float(1) / bp_bp;
    float t6 = ab_ap * t4 + ab_ab * J2 + t5 * a_minus_b;
    F = (float(1) / float(2)) * t3 * t6 * si.w[0];
    float t7 = t5 * t5;
    float t8 = t4 * t4;
    G_ap = (float(1) / float(8)) * t3 * si.w[0] * (float(2) * t7 * a_minus_b + float(2) * ab_ap * t8 + float(3) * ab_ab * t3 * t6);
    float t9 = float(1) / ab_ab;
    G_E = -(float(1) / float(4)) * t9 * (t7 * si.w[0] - t8 * si.w[0]);
  }
  float g_factor = -float(4) * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = -(G_E * ab1 - foot1 * G_ap) * g_factor;
  grad[2] = -g_factor * (ab2 * G_E - foot2 * G_ap);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-4) dt
// Operations: 31 +, 39 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i4_w1_f(SegmentInput si) {
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
  float plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  float ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = atan(t0, ap_bp) * t1;
    float t2 = float(1) / bp_bp;
    float t3 = float(1) / ap_ap;
    float t4 = J2 * ab_ab + a_minus_b * t2 + ab_ap * t3;
    float t5 = float(1) / cross_cross;
    F = (float(1) / float(2)) * t4 * t5 * si.w[0] + (float(1) / float(2)) * (t3 + t4 * t5 * ab_ap - t2) * si.w[1] / ab_ab;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-4) dt
// Operations: 45 +, 83 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i4_w1_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  float foot0;
  float foot1;
  float foot2;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
    float t0 = float(1) / ab_ab;
    foot0 = ap0 - t0 * ab_ap * ab0;
    foot1 = ap1 - t0 * ab_ap * ab1;
    foot2 = ap2 - t0 * ab2 * ab_ap;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  float ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, ap_bp);
    float t3 = float(1) / cross_cross;
    float t4 = float(1) / ap_ap;
    float t5 = float(1) / bp_bp;
    float t6 = ab_ap * t4 + t5 * a_minus_b + ab_ab * J2;
    float t7 = float(1) / ab_ab;
    F = (float(1) / float(2)) * t3 * t6 * si.w[0] - (float(1) / float(2)) * (t5 - t3 * ab_ap * t6 - t4) * si.w[1] * t7;
    float t8 = t5 * t5;
    float t9 = t4 * t4;
    float t10 = float(2) * t8 * a_minus_b + float(2) * ab_ap * t9 + float(3) * t3 * ab_ab * t6;
    G_ap = (float(1) / float(8)) * t3 * t10 * si.w[0] + (float(1) / float(8)) * si.w[1] * t7 * (float(2) * t9 + t3 * ab_ap * t10 - float(2) * t8);
    G_E = -(float(1) / float(8)) * t7 * (float(2) * t8 * (si.w[1] + si.w[0]) - float(2) * t9 * si.w[0] - si.w[1] * t3 * t6);
  }
  float g_factor = -float(4) * length;
  f = length * F;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = -(G_E * ab1 - foot1 * G_ap) * g_factor;
  grad[2] = -(G_E * ab2 - G_ap * foot2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-4) dt
// Operations: 34 +, 49 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i4_w2_f(SegmentInput si) {
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
  float ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
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
  float ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  float ap_bp = ap1 * bp1 + bp2 * ap2 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = atan(t0, ap_bp) * t1;
    float t2 = float(1) / cross_cross;
    float t3 = float(1) / bp_bp;
    float t4 = float(1) / ap_ap;
    float t5 = t3 * a_minus_b + t4 * ab_ap + J2 * ab_ab;
    float t6 = float(1) / ab_ab;
    float t7 = t3 - t4 - t2 * t5 * ab_ap;
    F = (float(1) / float(2)) * t2 * si.w[0] * t5 - (float(1) / float(2)) * si.w[2] * (ap_ap * t2 * t5 + float(2) * t6 * t7 * ab_ap - float(2) * J2) * t6 - (float(1) / float(2)) * si.w[1] * t6 * t7;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-4) dt
// Operations: 53 +, 105 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i4_w2_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float plain_cross0 = ap2 * ab1 - ab2 * ap1;
  float plain_cross1 = ab2 * ap0 - ap2 * ab0;
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
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  float ap_bp = bp1 * ap1 + ap2 * bp2 + bp0 * ap0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = atan(t1, ap_bp) * t2;
    float t3 = float(1) / ap_ap;
    float t4 = float(1) / bp_bp;
    float t5 = t3 * ab_ap + J2 * ab_ab + t4 * a_minus_b;
    float t6 = float(1) / cross_cross;
    float t7 = t3 + t5 * t6 * ab_ap - t4;
    float t8 = float(1) / ab_ab;
    F = (float(1) / float(2)) * si.w[1] * t7 * t8 + (float(1) / float(2)) * (float(2) * J2 + float(2) * t7 * t8 * ab_ap - ap_ap * t5 * t6) * si.w[2] * t8 + (float(1) / float(2)) * t5 * si.w[0] * t6;
    float t9 = t4 * t4;
    float t10 = t3 * t3;
    float t11 = float(3) * t5 * ab_ab * t6 + float(2) * t9 * a_minus_b + float(2) * t10 * ab_ap;
    float t12 = t11 * t6 * ab_ap + float(2) * t10 - float(2) * t9;
    G_ap = (float(1) / float(8)) * t11 * si.w[0] * t6 + (float(1) / float(8)) * (float(2) * t12 * t8 * ab_ap + float(4) * t5 * t6 - t11 * ap_ap * t6) * si.w[2] * t8 + (float(1) / float(8)) * si.w[1] * t12 * t8;
    G_E = (float(1) / float(8)) * (float(2) * t7 * si.w[2] * t8 + si.w[1] * t5 * t6 + float(2) * t10 * si.w[0] - float(2) * t9 * (si.w[1] + si.w[2] + si.w[0])) * t8;
  }
  float g_factor = -float(4) * length;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = -(ab1 * G_E - foot1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_E - G_ap * foot2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-4) dt
// Operations: 38 +, 61 *, 5 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float segment_inverse_i4_w3_f(SegmentInput si) {
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
  float ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float t0 = float(1) / ap_ap;
  float log_ratio = log(t0 * bp_bp);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, ap_bp);
    float t3 = float(1) / bp_bp;
    float t4 = t0 * ab_ap + a_minus_b * t3 + J2 * ab_ab;
    float t5 = float(1) / cross_cross;
    float t6 = float(1) / ab_ab;
    float t7 = t3 - t0 - t4 * t5 * ab_ap;
    float t8 = float(2) * J2 - ap_ap * t4 * t5 - float(2) * t7 * t6 * ab_ap;
    F = (float(1) / float(2)) * t4 * si.w[0] * t5 + (float(1) / float(2)) * t6 * t8 * si.w[2] + (float(1) / float(2)) * (float(2) * t6 * ab_ap * t8 + t6 * (log_ratio + float(2) * J2 * ab_ap) + t7 * ap_ap * t6) * si.w[3] * t6 - (float(1) / float(2)) * t7 * t6 * si.w[1];
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-4) dt
// Operations: 62 +, 130 *, 6 /, 2 sqrt, 1 atan, 1 log/asinh (generic form).
float segment_inverse_i4_w3_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
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
    foot2 = ap2 - t0 * ab2 * ab_ap;
  }
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  float ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
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
    float t6 = float(1) / bp_bp;
    float t7 = t6 * a_minus_b + ab_ap * t1 + ab_ab * J2;
    float t8 = t1 + t5 * ab_ap * t7 - t6;
    float t9 = float(2) * t4 * t8 * ab_ap + float(2) * J2 - t5 * t7 * ap_ap;
    F = (float(1) / float(2)) * t4 * si.w[2] * t9 + (float(1) / float(2)) * t4 * si.w[1] * t8 + (float(1) / float(2)) * t4 * (float(2) * t4 * ab_ap * t9 + (float(2) * ab_ap * J2 + log_ratio) * t4 - t4 * t8 * ap_ap) * si.w[3] + (float(1) / float(2)) * t5 * t7 * si.w[0];
    float t10 = t1 * t1;
    float t11 = t6 * t6;
    float t12 = float(3) * ab_ab * t5 * t7 + float(2) * ab_ap * t10 + float(2) * t11 * a_minus_b;
    float t13 = t12 * t5 * ab_ap + float(2) * t10 - float(2) * t11;
    float t14 = float(4) * t5 * t7 + float(2) * t13 * t4 * ab_ap - t12 * t5 * ap_ap;
    G_ap = (float(1) / float(8)) * t14 * t4 * si.w[2] + (float(1) / float(8)) * t13 * t4 * si.w[1] + (float(1) / float(8)) * (float(2) * t14 * t4 * ab_ap + float(4) * t4 * t8 - t13 * t4 * ap_ap) * t4 * si.w[3] + (float(1) / float(8)) * t12 * t5 * si.w[0];
    G_E = -(float(1) / float(8)) * t4 * (float(2) * (si.w[1] + si.w[2] + si.w[3] + si.w[0]) * t11 - si.w[1] * t5 * t7 - float(3) * t4 * t9 * si.w[3] - float(2) * t4 * t8 * si.w[2] - float(2) * t10 * si.w[0]);
  }
  float g_factor = -float(4) * length;
  f = length * F;
  grad[0] = -(ab0 * G_E - G_ap * foot0) * g_factor;
  grad[1] = g_factor * (G_ap * foot1 - ab1 * G_E);
  grad[2] = g_factor * (G_ap * foot2 - ab2 * G_E);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-5) dt
// Operations: 27 +, 35 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i5_w0_f(SegmentInput si) {
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
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / cross_cross;
    float t1 = float(1) / r0;
    float t2 = float(1) / r1;
    F = (float(1) / float(3)) * si.w[0] * t0 * (float(2) * (ab_ap * t1 + t2 * a_minus_b) * ab_ab * t0 + t2 * a_minus_b / bp_bp + ab_ap * t1 / ap_ap);
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-5) dt
// Operations: 36 +, 79 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i5_w0_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / cross_cross;
    float t2 = float(1) / r1;
    float t3 = t2 * t2;
    float t4 = float(1) / r0;
    float t5 = t4 * t4;
    float t6 = t2 * t3 * a_minus_b + ab_ap * t5 * t4 + float(2) * (t2 * a_minus_b + ab_ap * t4) * t1 * ab_ab;
    F = (float(1) / float(3)) * t1 * t6 * si.w[0];
    float t7 = t5 * t5;
    float t8 = t3 * t3;
    G_ap = (float(1) / float(15)) * (float(3) * ab_ap * t7 * t4 + float(3) * t2 * t8 * a_minus_b + float(4) * t1 * t6 * ab_ab) * t1 * si.w[0];
    float t9 = t2 * t2;
    float t10 = t9 * t9;
    float t11 = t10 * t2;
    float t12 = t4 * t4;
    float t13 = t12 * t12;
    float t14 = t13 * t4;
    float t15 = float(1) / ab_ab;
    G_E = -(float(1) / float(5)) * (t11 * si.w[0] - si.w[0] * t14) * t15;
  }
  float g_factor = -float(5) * length;
  f = length * F;
  grad[0] = -(G_E * ab0 - foot0 * G_ap) * g_factor;
  grad[1] = (foot1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-5) dt
// Operations: 30 +, 45 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i5_w1_f(SegmentInput si) {
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
  float ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / cross_cross;
    float t1 = float(1) / r0;
    float t2 = t1 * t1;
    float t3 = float(1) / r1;
    float t4 = t3 * t3;
    float t5 = t1 * ab_ap * t2 + a_minus_b * t4 * t3 + float(2) * ab_ab * t0 * (a_minus_b * t3 + t1 * ab_ap);
    F = (float(1) / float(3)) * t0 * si.w[0] * t5 - (float(1) / float(3)) * (t4 * t3 - t1 * t2 - t0 * ab_ap * t5) * si.w[1] / ab_ab;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-5) dt
// Operations: 44 +, 99 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i5_w1_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / r1;
    float t2 = t1 * t1;
    float t3 = float(1) / r0;
    float t4 = t3 * t3;
    float t5 = float(1) / cross_cross;
    float t6 = a_minus_b * t1 * t2 + ab_ap * t3 * t4 + float(2) * ab_ab * (a_minus_b * t1 + ab_ap * t3) * t5;
    float t7 = float(1) / ab_ab;
    F = (float(1) / float(3)) * t6 * si.w[0] * t5 + (float(1) / float(3)) * t7 * (t3 * t4 + t6 * ab_ap * t5 - t1 * t2) * si.w[1];
    float t8 = t4 * t4;
    float t9 = t2 * t2;
    float t10 = float(3) * ab_ap * t3 * t8 + float(4) * ab_ab * t6 * t5 + float(3) * a_minus_b * t1 * t9;
    G_ap = (float(1) / float(15)) * si.w[0] * t10 * t5 - (float(1) / float(15)) * t7 * (float(3) * t1 * t9 - ab_ap * t10 * t5 - float(3) * t3 * t8) * si.w[1];
    float t11 = t1 * t1;
    float t12 = t11 * t11;
    float t13 = t12 * t1;
    float t14 = t3 * t3;
    float t15 = t14 * t14;
    float t16 = t15 * t3;
    G_E = -(float(1) / float(15)) * t7 * (float(3) * (si.w[0] + si.w[1]) * t13 - float(3) * si.w[0] * t16 - t6 * si.w[1] * t5);
  }
  float g_factor = -float(5) * length;
  f = F * length;
  grad[0] = (foot0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = -g_factor * (ab1 * G_E - foot1 * G_ap);
  grad[2] = -(ab2 * G_E - G_ap * foot2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-5) dt
// Operations: 33 +, 56 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i5_w2_f(SegmentInput si) {
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / cross_cross;
    float t1 = float(1) / r0;
    float t2 = float(1) / r1;
    float t3 = t1 * ab_ap + a_minus_b * t2;
    float t4 = t2 * t2;
    float t5 = t1 * t1;
    float t6 = float(2) * ab_ab * t0 * t3 + a_minus_b * t4 * t2 + t1 * ab_ap * t5;
    float t7 = float(1) / ab_ab;
    float t8 = t0 * t6 * ab_ap + t1 * t5 - t4 * t2;
    F = (float(1) / float(3)) * t0 * si.w[0] * t6 + (float(1) / float(3)) * t7 * t8 * si.w[1] + (float(1) / float(3)) * si.w[2] * t7 * (float(3) * t0 * t3 + float(2) * t7 * t8 * ab_ap - t0 * t6 * ap_ap);
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-5) dt
// Operations: 52 +, 122 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i5_w2_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = ab2 * bp2 + bp0 * ab0 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / r0;
    float t2 = t1 * t1;
    float t3 = float(1) / r1;
    float t4 = t3 * t3;
    float t5 = float(1) / cross_cross;
    float t6 = t1 * ab_ap + a_minus_b * t3;
    float t7 = t1 * ab_ap * t2 + a_minus_b * t3 * t4 + float(2) * ab_ab * t5 * t6;
    float t8 = ab_ap * t7 * t5 + t1 * t2 - t3 * t4;
    float t9 = float(1) / ab_ab;
    F = (float(1) / float(3)) * t8 * t9 * si.w[1] + (float(1) / float(3)) * si.w[0] * t7 * t5 - (float(1) / float(3)) * si.w[2] * t9 * (t7 * t5 * ap_ap - float(3) * t5 * t6 - float(2) * t8 * t9 * ab_ap);
    float t10 = t2 * t2;
    float t11 = t4 * t4;
    float t12 = float(4) * ab_ab * t7 * t5 + float(3) * t1 * ab_ap * t10 + float(3) * a_minus_b * t3 * t11;
    float t13 = float(3) * t1 * t10 + ab_ap * t5 * t12 - float(3) * t3 * t11;
    G_ap = (float(1) / float(15)) * si.w[2] * t9 * (float(2) * t9 * ab_ap * t13 + float(5) * t7 * t5 - t5 * t12 * ap_ap) + (float(1) / float(15)) * t9 * t13 * si.w[1] + (float(1) / float(15)) * si.w[0] * t5 * t12;
    float t14 = t1 * t1;
    float t15 = t14 * t14;
    float t16 = t15 * t1;
    float t17 = t3 * t3;
    float t18 = t17 * t17;
    float t19 = t18 * t3;
    G_E = (float(1) / float(15)) * t9 * (t7 * t5 * si.w[1] + float(2) * t8 * si.w[2] * t9 + float(3) * t16 * si.w[0] - float(3) * (si.w[2] + si.w[0] + si.w[1]) * t19);
  }
  float g_factor = -float(5) * length;
  f = F * length;
  grad[0] = (G_ap * foot0 - ab0 * G_E) * g_factor;
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = -g_factor * (ab2 * G_E - G_ap * foot2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-5) dt
// Operations: 38 +, 68 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i5_w3_f(SegmentInput si) {
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
  float plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / r0;
    float t1 = t0 * t0;
    float t2 = float(1) / r1;
    float t3 = t2 * a_minus_b + t0 * ab_ap;
    float t4 = float(1) / cross_cross;
    float t5 = t2 * t2;
    float t6 = t0 * ab_ap * t1 + float(2) * ab_ab * t3 * t4 + t5 * t2 * a_minus_b;
    float t7 = t5 * t2 - ab_ap * t6 * t4 - t0 * t1;
    float t8 = float(1) / ab_ab;
    float t9 = float(3) * t3 * t4 - ap_ap * t6 * t4 - float(2) * ab_ap * t7 * t8;
    F = (float(1) / float(3)) * si.w[0] * t6 * t4 + (float(1) / float(3)) * si.w[2] * t9 * t8 - (float(1) / float(3)) * (float(3) * (t2 - ab_ap * t3 * t4 - t0) * t8 - ap_ap * t7 * t8 - float(2) * ab_ap * t9 * t8) * si.w[3] * t8 - (float(1) / float(3)) * t7 * t8 * si.w[1];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-5) dt
// Operations: 62 +, 147 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i5_w3_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / ab_ab;
    float t2 = float(1) / cross_cross;
    float t3 = float(1) / r1;
    float t4 = float(1) / r0;
    float t5 = a_minus_b * t3 + ab_ap * t4;
    float t6 = t4 * t4;
    float t7 = t3 * t3;
    float t8 = float(2) * t2 * ab_ab * t5 + t7 * a_minus_b * t3 + ab_ap * t6 * t4;
    float t9 = t6 * t4 + t2 * ab_ap * t8 - t7 * t3;
    float t10 = float(3) * t2 * t5 + float(2) * ab_ap * t9 * t1 - t2 * t8 * ap_ap;
    F = (float(1) / float(3)) * si.w[2] * t1 * t10 + (float(1) / float(3)) * t9 * t1 * si.w[1] + (float(1) / float(3)) * t2 * t8 * si.w[0] - (float(1) / float(3)) * (float(3) * (t3 - t2 * ab_ap * t5 - t4) * t1 + ap_ap * t9 * t1 - float(2) * ab_ap * t1 * t10) * si.w[3] * t1;
    float t11 = t6 * t6;
    float t12 = t7 * t7;
    float t13 = float(4) * t2 * t8 * ab_ab + float(3) * ab_ap * t11 * t4 + float(3) * t12 * a_minus_b * t3;
    float t14 = float(3) * t12 * t3 - t2 * ab_ap * t13 - float(3) * t11 * t4;
    float t15 = float(2) * ab_ap * t14 * t1 + t2 * t13 * ap_ap - float(5) * t2 * t8;
    G_ap = (float(1) / float(15)) * t2 * t13 * si.w[0] - (float(1) / float(15)) * t14 * t1 * si.w[1] - (float(1) / float(15)) * si.w[2] * t15 * t1 - (float(1) / float(15)) * si.w[3] * t1 * (float(2) * ab_ap * t15 * t1 - t14 * ap_ap * t1 - float(5) * t9 * t1);
    float t16 = t4 * t4;
    float t17 = t16 * t16;
    float t18 = t17 * t4;
    float t19 = t3 * t3;
    float t20 = t19 * t19;
    float t21 = t20 * t3;
    G_E = (float(1) / float(15)) * (float(3) * si.w[0] * t18 + float(2) * si.w[2] * t9 * t1 + float(3) * si.w[3] * t1 * t10 + t2 * t8 * si.w[1] - float(3) * (si.w[2] + si.w[3] + si.w[0] + si.w[1]) * t21) * t1;
  }
  float g_factor = -float(5) * length;
  f = length * F;
  grad[0] = (foot0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = g_factor * (foot1 * G_ap - G_E * ab1);
  grad[2] = g_factor * (G_ap * foot2 - G_E * ab2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-6) dt
// Operations: 30 +, 44 *, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i6_w0_f(SegmentInput si) {
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
  float ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
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
  float ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  float ap_bp = ap1 * bp1 + bp0 * ap0 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, ap_bp);
    float t2 = float(1) / bp_bp;
    float t3 = t2 * t2;
    float t4 = float(1) / ap_ap;
    float t5 = t4 * t4;
    float t6 = float(1) / cross_cross;
    F = (float(1) / float(8)) * (float(2) * a_minus_b * t3 + float(2) * ab_ap * t5 + float(3) * (ab_ap * t4 + a_minus_b * t2 + ab_ab * J2) * ab_ab * t6) * si.w[0] * t6;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-6) dt
// Operations: 39 +, 76 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i6_w0_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
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
    foot0 = ap0 - ab0 * t0 * ab_ap;
    foot1 = ap1 - ab1 * t0 * ab_ap;
    foot2 = ap2 - t0 * ab2 * ab_ap;
  }
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ab_bp = bp2 * ab2 + ab1 * bp1 + bp0 * ab0;
  float ap_bp = bp2 * ap2 + bp0 * ap0 + ap1 * bp1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = atan(t1, ap_bp) * t2;
    float t3 = float(1) / ap_ap;
    float t4 = t3 * t3;
    float t5 = float(1) / bp_bp;
    float t6 = t5 * t5;
    float t7 = float(1) / cross_cross;
    float t8 = float(2) * t4 * ab_ap + float(2) * t6 * a_minus_b + float(3) * (ab_ab * J2 + t5 * a_minus_b + t3 * ab_ap) * ab_ab * t7;
    F = (float(1) / float(8)) * si.w[0] * t8 * t7;
    float t9 = t4 * t3;
    float t10 = t6 * t5;
    G_ap = (float(1) / float(48)) * si.w[0] * t7 * (float(8) * t9 * ab_ap + float(5) * t8 * ab_ab * t7 + float(8) * t10 * a_minus_b);
    float t11 = float(1) / ab_ab;
    G_E = -(float(1) / float(6)) * (si.w[0] * t10 - t9 * si.w[0]) * t11;
  }
  float g_factor = -float(6) * length;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_E - G_ap * foot0);
  grad[1] = g_factor * (foot1 * G_ap - ab1 * G_E);
  grad[2] = -g_factor * (ab2 * G_E - G_ap * foot2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-6) dt
// Operations: 33 +, 50 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i6_w1_f(SegmentInput si) {
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
  float ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  float plain_cross0 = ab1 * ap2 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
  float plain_cross2 = ap1 * ab0 - ap0 * ab1;
  float plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float ap_bp = ap0 * bp0 + ap1 * bp1 + bp2 * ap2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = atan(t0, ap_bp) * t1;
    float t2 = float(1) / ap_ap;
    float t3 = t2 * t2;
    float t4 = float(1) / cross_cross;
    float t5 = float(1) / bp_bp;
    float t6 = t5 * t5;
    float t7 = float(2) * t3 * ab_ap + float(2) * t6 * a_minus_b + float(3) * ab_ab * t4 * (t5 * a_minus_b + t2 * ab_ap + J2 * ab_ab);
    F = (float(1) / float(8)) * si.w[1] * (float(2) * t3 + t4 * ab_ap * t7 - float(2) * t6) / ab_ab + (float(1) / float(8)) * si.w[0] * t4 * t7;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-6) dt
// Operations: 47 +, 94 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i6_w1_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float ab_ap = ab1 * ap1 + ab2 * ap2 + ap0 * ab0;
  float ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  float plain_cross0 = ab1 * ap2 - ab2 * ap1;
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
    foot0 = ap0 - t0 * ab_ap * ab0;
    foot1 = ap1 - t0 * ab_ap * ab1;
    foot2 = ap2 - t0 * ab2 * ab_ap;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  float ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, ap_bp);
    float t3 = float(1) / cross_cross;
    float t4 = float(1) / bp_bp;
    float t5 = t4 * t4;
    float t6 = float(1) / ap_ap;
    float t7 = t6 * t6;
    float t8 = float(2) * t5 * a_minus_b + float(2) * ab_ap * t7 + float(3) * (ab_ab * J2 + ab_ap * t6 + t4 * a_minus_b) * t3 * ab_ab;
    float t9 = float(1) / ab_ab;
    F = (float(1) / float(8)) * si.w[0] * t3 * t8 - (float(1) / float(8)) * (float(2) * t5 - t3 * ab_ap * t8 - float(2) * t7) * si.w[1] * t9;
    float t10 = t5 * t4;
    float t11 = t7 * t6;
    float t12 = float(8) * t10 * a_minus_b + float(8) * ab_ap * t11 + float(5) * t3 * ab_ab * t8;
    G_ap = (float(1) / float(48)) * si.w[0] * t3 * t12 - (float(1) / float(48)) * (float(8) * t10 - float(8) * t11 - t3 * ab_ap * t12) * si.w[1] * t9;
    G_E = (float(1) / float(48)) * t9 * (float(8) * si.w[0] * t11 + si.w[1] * t3 * t8 - float(8) * (si.w[0] + si.w[1]) * t10);
  }
  float g_factor = -float(6) * length;
  f = length * F;
  grad[0] = -(G_E * ab0 - G_ap * foot0) * g_factor;
  grad[1] = -g_factor * (G_E * ab1 - foot1 * G_ap);
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-6) dt
// Operations: 36 +, 61 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i6_w2_f(SegmentInput si) {
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
  float plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  float ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, ap_bp);
    float t2 = float(1) / ab_ab;
    float t3 = float(1) / bp_bp;
    float t4 = float(1) / ap_ap;
    float t5 = a_minus_b * t3 + ab_ap * t4 + ab_ab * J2;
    float t6 = float(1) / cross_cross;
    float t7 = t4 * t4;
    float t8 = t3 * t3;
    float t9 = float(2) * ab_ap * t7 + float(3) * t5 * ab_ab * t6 + float(2) * a_minus_b * t8;
    float t10 = float(2) * t7 + t6 * t9 * ab_ap - float(2) * t8;
    F = (float(1) / float(8)) * t2 * (float(4) * t5 * t6 + float(2) * t2 * ab_ap * t10 - t6 * t9 * ap_ap) * si.w[2] + (float(1) / float(8)) * t6 * si.w[0] * t9 + (float(1) / float(8)) * t2 * t10 * si.w[1];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-6) dt
// Operations: 55 +, 117 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i6_w2_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  float ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = atan(t1, ap_bp) * t2;
    float t3 = float(1) / ab_ab;
    float t4 = float(1) / ap_ap;
    float t5 = t4 * t4;
    float t6 = float(1) / bp_bp;
    float t7 = t6 * a_minus_b + ab_ap * t4 + ab_ab * J2;
    float t8 = float(1) / cross_cross;
    float t9 = t6 * t6;
    float t10 = float(2) * ab_ap * t5 + float(3) * ab_ab * t7 * t8 + float(2) * t9 * a_minus_b;
    float t11 = float(2) * t5 + t10 * t8 * ab_ap - float(2) * t9;
    F = (float(1) / float(8)) * t3 * si.w[1] * t11 + (float(1) / float(8)) * t3 * (float(2) * t3 * ab_ap * t11 + float(4) * t7 * t8 - t10 * t8 * ap_ap) * si.w[2] + (float(1) / float(8)) * t10 * si.w[0] * t8;
    float t12 = t5 * t4;
    float t13 = t9 * t6;
    float t14 = float(5) * t10 * ab_ab * t8 + float(8) * t13 * a_minus_b + float(8) * ab_ap * t12;
    float t15 = float(8) * t12 + t8 * ab_ap * t14 - float(8) * t13;
    G_ap = (float(1) / float(48)) * t15 * t3 * si.w[1] + (float(1) / float(48)) * t3 * si.w[2] * (float(2) * t15 * t3 * ab_ap + float(6) * t10 * t8 - t8 * t14 * ap_ap) + (float(1) / float(48)) * si.w[0] * t8 * t14;
    G_E = (float(1) / float(48)) * t3 * (t10 * t8 * si.w[1] + float(2) * t3 * t11 * si.w[2] + float(8) * si.w[0] * t12 - float(8) * t13 * (si.w[0] + si.w[1] + si.w[2]));
  }
  float g_factor = -float(6) * length;
  f = length * F;
  grad[0] = g_factor * (G_ap * foot0 - ab0 * G_E);
  grad[1] = g_factor * (G_ap * foot1 - ab1 * G_E);
  grad[2] = -(ab2 * G_E - G_ap * foot2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-6) dt
// Operations: 41 +, 73 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i6_w3_f(SegmentInput si) {
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
  float ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  float ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = atan(t0, ap_bp) * t1;
    float t2 = float(1) / ab_ab;
    float t3 = float(1) / ap_ap;
    float t4 = t3 * t3;
    float t5 = float(1) / bp_bp;
    float t6 = t5 * t5;
    float t7 = t3 * ab_ap + a_minus_b * t5 + J2 * ab_ab;
    float t8 = float(1) / cross_cross;
    float t9 = float(2) * a_minus_b * t6 + float(3) * t7 * ab_ab * t8 + float(2) * t4 * ab_ap;
    float t10 = float(2) * t4 + t9 * t8 * ab_ap - float(2) * t6;
    float t11 = float(2) * t2 * ab_ap * t10 + float(4) * t7 * t8 - t9 * ap_ap * t8;
    F = (float(1) / float(8)) * t2 * t11 * si.w[2] + (float(1) / float(8)) * t9 * si.w[0] * t8 + (float(1) / float(8)) * t2 * si.w[1] * t10 - (float(1) / float(8)) * (ap_ap * t2 * t10 + float(4) * t2 * (t5 - t7 * t8 * ab_ap - t3) - float(2) * t2 * t11 * ab_ap) * si.w[3] * t2;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-6) dt
// Operations: 65 +, 142 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i6_w3_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
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
  float ap_bp = bp1 * ap1 + bp0 * ap0 + bp2 * ap2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, ap_bp);
    float t3 = float(1) / cross_cross;
    float t4 = float(1) / ap_ap;
    float t5 = float(1) / bp_bp;
    float t6 = t4 * ab_ap + a_minus_b * t5 + ab_ab * J2;
    float t7 = t4 * t4;
    float t8 = t5 * t5;
    float t9 = float(3) * ab_ab * t3 * t6 + float(2) * t7 * ab_ap + float(2) * a_minus_b * t8;
    float t10 = float(1) / ab_ab;
    float t11 = float(2) * t7 + t9 * t3 * ab_ap - float(2) * t8;
    float t12 = ap_ap * t9 * t3 - float(4) * t3 * t6 - float(2) * t10 * t11 * ab_ap;
    F = (float(1) / float(8)) * si.w[0] * t9 * t3 + (float(1) / float(8)) * t10 * t11 * si.w[1] - (float(1) / float(8)) * si.w[3] * (ap_ap * t10 * t11 + float(2) * t10 * t12 * ab_ap + float(4) * (t5 - t4 - t3 * ab_ap * t6) * t10) * t10 - (float(1) / float(8)) * t10 * t12 * si.w[2];
    float t13 = t7 * t4;
    float t14 = t8 * t5;
    float t15 = float(5) * ab_ab * t9 * t3 + float(8) * a_minus_b * t14 + float(8) * t13 * ab_ap;
    float t16 = float(8) * t13 + t15 * t3 * ab_ap - float(8) * t14;
    float t17 = ap_ap * t15 * t3 - float(2) * t10 * ab_ap * t16 - float(6) * t9 * t3;
    G_ap = (float(1) / float(48)) * t10 * si.w[1] * t16 + (float(1) / float(48)) * t15 * si.w[0] * t3 - (float(1) / float(48)) * si.w[3] * t10 * (float(2) * t10 * t17 * ab_ap + ap_ap * t10 * t16 - float(6) * t10 * t11) - (float(1) / float(48)) * t10 * t17 * si.w[2];
    G_E = (float(1) / float(48)) * t10 * (t9 * t3 * si.w[1] + float(2) * t10 * t11 * si.w[2] + float(8) * t13 * si.w[0] - float(8) * (si.w[3] + si.w[0] + si.w[1] + si.w[2]) * t14 - float(3) * si.w[3] * t10 * t12);
  }
  float g_factor = -float(6) * length;
  f = F * length;
  grad[0] = -(ab0 * G_E - G_ap * foot0) * g_factor;
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = -(ab2 * G_E - G_ap * foot2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-7) dt
// Operations: 29 +, 50 *, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i7_w0_f(SegmentInput si) {
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
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / cross_cross;
    float t1 = float(1) / r1;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = float(1) / r0;
    float t5 = t4 * t4;
    float t6 = t5 * t5;
    F = (float(1) / float(15)) * t0 * (float(3) * a_minus_b * t3 * t1 + float(4) * ab_ab * t0 * (ab_ap * t4 * t5 + a_minus_b * t2 * t1 + float(2) * ab_ab * (a_minus_b * t1 + ab_ap * t4) * t0) + float(3) * ab_ap * t4 * t6) * si.w[0];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-7) dt
// Operations: 38 +, 92 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i7_w0_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
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
    foot2 = ap2 - t0 * ab2 * ab_ap;
  }
  float bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  float ab_bp = ab2 * bp2 + ab1 * bp1 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / cross_cross;
    float t2 = float(1) / r0;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = float(1) / r1;
    float t6 = t5 * t5;
    float t7 = t6 * t6;
    float t8 = float(3) * t2 * ab_ap * t4 + float(3) * t5 * t7 * a_minus_b + float(4) * ab_ab * (float(2) * ab_ab * (t5 * a_minus_b + t2 * ab_ap) * t1 + t5 * t6 * a_minus_b + t2 * ab_ap * t3) * t1;
    F = (float(1) / float(15)) * si.w[0] * t1 * t8;
    float t9 = t7 * t6;
    float t10 = t4 * t3;
    G_ap = (float(1) / float(35)) * si.w[0] * t1 * (float(5) * t5 * t9 * a_minus_b + float(2) * ab_ab * t1 * t8 + float(5) * t2 * ab_ap * t10);
    float t11 = float(1) / ab_ab;
    float t12 = t2 * t2;
    float t13 = t12 * t2;
    float t14 = t13 * t13;
    float t15 = t14 * t2;
    float t16 = t5 * t5;
    float t17 = t16 * t5;
    float t18 = t17 * t17;
    float t19 = t18 * t5;
    G_E = (float(1) / float(7)) * t11 * (si.w[0] * t15 - si.w[0] * t19);
  }
  float g_factor = -float(7) * length;
  f = length * F;
  grad[0] = -(ab0 * G_E - G_ap * foot0) * g_factor;
  grad[1] = (G_ap * foot1 - ab1 * G_E) * g_factor;
  grad[2] = (G_ap * foot2 - ab2 * G_E) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-7) dt
// Operations: 32 +, 58 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i7_w1_f(SegmentInput si) {
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
  float ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
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
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / cross_cross;
    float t1 = float(1) / r1;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = float(1) / r0;
    float t5 = t4 * t4;
    float t6 = t5 * t5;
    float t7 = float(3) * t1 * a_minus_b * t3 + float(4) * ab_ab * t0 * (t5 * t4 * ab_ap + float(2) * (t4 * ab_ap + t1 * a_minus_b) * ab_ab * t0 + t1 * a_minus_b * t2) + float(3) * t6 * t4 * ab_ap;
    F = (float(1) / float(15)) * t0 * t7 * si.w[0] - (float(1) / float(15)) * (float(3) * t1 * t3 - t0 * ab_ap * t7 - float(3) * t6 * t4) * si.w[1] / ab_ab;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-7) dt
// Operations: 46 +, 114 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i7_w1_f_and_grad(SegmentInput si, out vec3 grad) {
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
    foot0 = ap0 - ab0 * ab_ap * t0;
    foot1 = ap1 - ab1 * ab_ap * t0;
    foot2 = ap2 - ab_ap * t0 * ab2;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / cross_cross;
    float t2 = float(1) / r0;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = float(1) / r1;
    float t6 = t5 * t5;
    float t7 = t6 * t6;
    float t8 = float(3) * ab_ap * t4 * t2 + float(4) * t1 * (t5 * t6 * a_minus_b + ab_ap * t3 * t2 + float(2) * t1 * (t5 * a_minus_b + ab_ap * t2) * ab_ab) * ab_ab + float(3) * t5 * t7 * a_minus_b;
    float t9 = float(1) / ab_ab;
    F = (float(1) / float(15)) * t1 * t8 * si.w[0] + (float(1) / float(15)) * (t1 * ab_ap * t8 + float(3) * t4 * t2 - float(3) * t5 * t7) * si.w[1] * t9;
    float t10 = t4 * t3;
    float t11 = t7 * t6;
    float t12 = float(5) * ab_ap * t10 * t2 + float(5) * t5 * t11 * a_minus_b + float(2) * t1 * t8 * ab_ab;
    G_ap = (float(1) / float(35)) * t1 * t12 * si.w[0] + (float(1) / float(35)) * (t1 * ab_ap * t12 + float(5) * t10 * t2 - float(5) * t5 * t11) * si.w[1] * t9;
    float t13 = t2 * t2;
    float t14 = t13 * t2;
    float t15 = t14 * t14;
    float t16 = t15 * t2;
    float t17 = t5 * t5;
    float t18 = t17 * t5;
    float t19 = t18 * t18;
    float t20 = t19 * t5;
    G_E = (float(1) / float(105)) * (t1 * t8 * si.w[1] + float(15) * si.w[0] * t16 - float(15) * t20 * (si.w[0] + si.w[1])) * t9;
  }
  float g_factor = -float(7) * length;
  f = length * F;
  grad[0] = (foot0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = -(ab1 * G_E - foot1 * G_ap) * g_factor;
  grad[2] = -(G_E * ab2 - foot2 * G_ap) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-7) dt
// Operations: 35 +, 69 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i7_w2_f(SegmentInput si) {
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
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / r1;
    float t1 = t0 * t0;
    float t2 = t1 * t1;
    float t3 = float(1) / r0;
    float t4 = t3 * t3;
    float t5 = float(1) / cross_cross;
    float t6 = t3 * ab_ap * t4 + float(2) * ab_ab * t5 * (t0 * a_minus_b + t3 * ab_ap) + t1 * t0 * a_minus_b;
    float t7 = t4 * t4;
    float t8 = float(3) * t2 * t0 * a_minus_b + float(4) * t6 * ab_ab * t5 + float(3) * t3 * ab_ap * t7;
    float t9 = float(3) * t3 * t7 + ab_ap * t8 * t5 - float(3) * t2 * t0;
    float t10 = float(1) / ab_ab;
    F = (float(1) / float(15)) * t8 * t5 * si.w[0] + (float(1) / float(15)) * si.w[2] * (float(2) * ab_ap * t9 * t10 + float(5) * t6 * t5 - t8 * ap_ap * t5) * t10 + (float(1) / float(15)) * si.w[1] * t9 * t10;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-7) dt
// Operations: 54 +, 138 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i7_w2_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
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
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / r0;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = float(1) / r1;
    float t5 = t4 * t4;
    float t6 = float(1) / cross_cross;
    float t7 = t5 * a_minus_b * t4 + float(2) * ab_ab * (ab_ap * t1 + a_minus_b * t4) * t6 + ab_ap * t2 * t1;
    float t8 = t5 * t5;
    float t9 = float(3) * ab_ap * t3 * t1 + float(4) * t7 * ab_ab * t6 + float(3) * t8 * a_minus_b * t4;
    float t10 = float(3) * t3 * t1 + ab_ap * t9 * t6 - float(3) * t8 * t4;
    float t11 = float(1) / ab_ab;
    F = (float(1) / float(15)) * t10 * si.w[1] * t11 + (float(1) / float(15)) * (float(5) * t7 * t6 + float(2) * t10 * ab_ap * t11 - ap_ap * t9 * t6) * si.w[2] * t11 + (float(1) / float(15)) * t9 * t6 * si.w[0];
    float t12 = t3 * t2;
    float t13 = t8 * t5;
    float t14 = float(5) * t13 * a_minus_b * t4 + float(2) * t9 * ab_ab * t6 + float(5) * ab_ap * t12 * t1;
    float t15 = float(5) * t12 * t1 + ab_ap * t14 * t6 - float(5) * t13 * t4;
    G_ap = (float(1) / float(35)) * si.w[1] * t11 * t15 + (float(1) / float(105)) * si.w[2] * t11 * (float(6) * ab_ap * t11 * t15 + float(7) * t9 * t6 - float(3) * ap_ap * t14 * t6) + (float(1) / float(35)) * t14 * t6 * si.w[0];
    float t16 = t1 * t1;
    float t17 = t16 * t1;
    float t18 = t17 * t17;
    float t19 = t18 * t1;
    float t20 = t4 * t4;
    float t21 = t20 * t4;
    float t22 = t21 * t21;
    float t23 = t22 * t4;
    G_E = (float(1) / float(105)) * (float(2) * t10 * si.w[2] * t11 + si.w[1] * t9 * t6 + float(15) * t19 * si.w[0] - float(15) * (si.w[1] + si.w[2] + si.w[0]) * t23) * t11;
  }
  float g_factor = -float(7) * length;
  f = length * F;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = g_factor * (foot1 * G_ap - G_E * ab1);
  grad[2] = g_factor * (G_ap * foot2 - G_E * ab2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-7) dt
// Operations: 40 +, 83 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i7_w3_f(SegmentInput si) {
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
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / cross_cross;
    float t1 = float(1) / r0;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = float(1) / r1;
    float t5 = t4 * t4;
    float t6 = t5 * t5;
    float t7 = float(2) * ab_ab * (t1 * ab_ap + a_minus_b * t4) * t0 + t1 * ab_ap * t2 + a_minus_b * t5 * t4;
    float t8 = float(3) * t1 * ab_ap * t3 + float(3) * a_minus_b * t6 * t4 + float(4) * ab_ab * t0 * t7;
    float t9 = float(1) / ab_ab;
    float t10 = t0 * ab_ap * t8 + float(3) * t1 * t3 - float(3) * t6 * t4;
    float t11 = t0 * ap_ap * t8 - float(2) * t9 * ab_ap * t10 - float(5) * t0 * t7;
    F = (float(1) / float(15)) * si.w[0] * t0 * t8 + (float(1) / float(15)) * t9 * si.w[1] * t10 - (float(1) / float(15)) * t9 * si.w[2] * t11 - (float(1) / float(15)) * t9 * (float(2) * t9 * ab_ap * t11 + t9 * t10 * ap_ap - float(5) * t9 * (t0 * ab_ap * t7 + t1 * t2 - t5 * t4)) * si.w[3];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-7) dt
// Operations: 64 +, 166 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i7_w3_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / ab_ab;
    float t2 = float(1) / r0;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = float(1) / r1;
    float t6 = t5 * t5;
    float t7 = float(1) / cross_cross;
    float t8 = t5 * t6 * a_minus_b + t2 * ab_ap * t3 + float(2) * ab_ab * t7 * (t5 * a_minus_b + t2 * ab_ap);
    float t9 = t6 * t6;
    float t10 = float(4) * t8 * ab_ab * t7 + float(3) * t2 * ab_ap * t4 + float(3) * t5 * t9 * a_minus_b;
    float t11 = float(3) * t2 * t4 + t10 * t7 * ab_ap - float(3) * t5 * t9;
    float t12 = float(2) * t1 * ab_ap * t11 + float(5) * t8 * t7 - t10 * t7 * ap_ap;
    F = (float(1) / float(15)) * t1 * t12 * si.w[2] + (float(1) / float(15)) * t10 * si.w[0] * t7 + (float(1) / float(15)) * t1 * si.w[1] * t11 - (float(1) / float(15)) * t1 * (float(5) * t1 * (t5 * t6 - t8 * t7 * ab_ap - t2 * t3) + t1 * ap_ap * t11 - float(2) * t1 * t12 * ab_ap) * si.w[3];
    float t13 = t9 * t6;
    float t14 = t4 * t3;
    float t15 = float(2) * t10 * ab_ab * t7 + float(5) * t5 * t13 * a_minus_b + float(5) * t2 * ab_ap * t14;
    float t16 = float(5) * t2 * t14 + t7 * ab_ap * t15 - float(5) * t5 * t13;
    float t17 = float(3) * t7 * t15 * ap_ap - float(7) * t10 * t7 - float(6) * t1 * ab_ap * t16;
    G_ap = (float(1) / float(35)) * si.w[0] * t7 * t15 + (float(1) / float(105)) * t1 * (float(7) * t1 * t11 - float(2) * t1 * ab_ap * t17 - float(3) * t1 * t16 * ap_ap) * si.w[3] + (float(1) / float(35)) * t1 * si.w[1] * t16 - (float(1) / float(105)) * t1 * si.w[2] * t17;
    float t18 = t2 * t2;
    float t19 = t18 * t2;
    float t20 = t19 * t19;
    float t21 = t20 * t2;
    float t22 = t5 * t5;
    float t23 = t22 * t5;
    float t24 = t23 * t23;
    float t25 = t24 * t5;
    G_E = (float(1) / float(105)) * t1 * (t10 * t7 * si.w[1] + float(2) * t1 * si.w[2] * t11 + float(15) * t21 * si.w[0] + float(3) * t1 * t12 * si.w[3] - float(15) * t25 * (si.w[0] + si.w[1] + si.w[2] + si.w[3]));
  }
  float g_factor = -float(7) * length;
  f = length * F;
  grad[0] = (G_ap * foot0 - ab0 * G_E) * g_factor;
  grad[1] = -(ab1 * G_E - G_ap * foot1) * g_factor;
  grad[2] = (G_ap * foot2 - ab2 * G_E) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-8) dt
// Operations: 32 +, 53 *, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i8_w0_f(SegmentInput si) {
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
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  float ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, ap_bp);
    float t2 = float(1) / cross_cross;
    float t3 = float(1) / bp_bp;
    float t4 = t3 * t3;
    float t5 = t4 * t3;
    float t6 = float(1) / ap_ap;
    float t7 = t6 * t6;
    float t8 = t7 * t6;
    F = (float(1) / float(48)) * t2 * si.w[0] * (float(8) * t5 * a_minus_b + float(5) * t2 * ab_ab * (float(2) * t4 * a_minus_b + float(2) * ab_ap * t7 + float(3) * t2 * (ab_ab * J2 + ab_ap * t6 + t3 * a_minus_b) * ab_ab) + float(8) * ab_ap * t8);
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-8) dt
// Operations: 41 +, 85 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i8_w0_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = ab0 * bp0 + ab2 * bp2 + ab1 * bp1;
  float ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, ap_bp);
    float t3 = float(1) / cross_cross;
    float t4 = float(1) / ap_ap;
    float t5 = t4 * t4;
    float t6 = float(1) / bp_bp;
    float t7 = t6 * t6;
    float t8 = t5 * t4;
    float t9 = t7 * t6;
    float t10 = float(5) * t3 * (float(2) * ab_ap * t5 + float(2) * t7 * a_minus_b + float(3) * t3 * (J2 * ab_ab + t6 * a_minus_b + ab_ap * t4) * ab_ab) * ab_ab + float(8) * ab_ap * t8 + float(8) * t9 * a_minus_b;
    F = (float(1) / float(48)) * t3 * t10 * si.w[0];
    float t11 = t5 * t5;
    float t12 = t7 * t7;
    G_ap = (float(1) / float(384)) * t3 * (float(7) * t3 * t10 * ab_ab + float(48) * ab_ap * t11 + float(48) * t12 * a_minus_b) * si.w[0];
    float t13 = float(1) / ab_ab;
    G_E = (float(1) / float(8)) * (t11 * si.w[0] - t12 * si.w[0]) * t13;
  }
  float g_factor = -float(8) * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = -(ab2 * G_E - foot2 * G_ap) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-8) dt
// Operations: 35 +, 59 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i8_w1_f(SegmentInput si) {
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
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  float ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = atan(t0, ap_bp) * t1;
    float t2 = float(1) / cross_cross;
    float t3 = float(1) / bp_bp;
    float t4 = float(1) / ap_ap;
    float t5 = t4 * t4;
    float t6 = t3 * t3;
    float t7 = t5 * t4;
    float t8 = t6 * t3;
    float t9 = float(5) * ab_ab * t2 * (float(3) * ab_ab * t2 * (J2 * ab_ab + a_minus_b * t3 + ab_ap * t4) + float(2) * ab_ap * t5 + float(2) * a_minus_b * t6) + float(8) * ab_ap * t7 + float(8) * a_minus_b * t8;
    F = (float(1) / float(48)) * t9 * t2 * si.w[0] - (float(1) / float(48)) * (float(8) * t8 - t9 * t2 * ab_ap - float(8) * t7) * si.w[1] / ab_ab;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-8) dt
// Operations: 49 +, 103 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i8_w1_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  float ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, ap_bp);
    float t3 = float(1) / cross_cross;
    float t4 = float(1) / bp_bp;
    float t5 = t4 * t4;
    float t6 = t5 * t4;
    float t7 = float(1) / ap_ap;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = float(8) * t6 * a_minus_b + float(8) * ab_ap * t9 + float(5) * t3 * ab_ab * (float(2) * ab_ap * t8 + float(3) * t3 * (t4 * a_minus_b + ab_ap * t7 + J2 * ab_ab) * ab_ab + float(2) * t5 * a_minus_b);
    float t11 = float(1) / ab_ab;
    F = (float(1) / float(48)) * t3 * t10 * si.w[0] - (float(1) / float(48)) * (float(8) * t6 - t3 * ab_ap * t10 - float(8) * t9) * si.w[1] * t11;
    float t12 = t8 * t8;
    float t13 = t5 * t5;
    float t14 = float(48) * ab_ap * t12 + float(7) * t3 * t10 * ab_ab + float(48) * t13 * a_minus_b;
    G_ap = (float(1) / float(384)) * (t3 * ab_ap * t14 + float(48) * t12 - float(48) * t13) * si.w[1] * t11 + (float(1) / float(384)) * t3 * si.w[0] * t14;
    G_E = (float(1) / float(384)) * t11 * (t3 * t10 * si.w[1] + float(48) * si.w[0] * t12 - float(48) * t13 * (si.w[0] + si.w[1]));
  }
  float g_factor = -float(8) * length;
  f = length * F;
  grad[0] = -(G_E * ab0 - foot0 * G_ap) * g_factor;
  grad[1] = -(G_E * ab1 - foot1 * G_ap) * g_factor;
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-8) dt
// Operations: 38 +, 70 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i8_w2_f(SegmentInput si) {
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  float ap_bp = bp0 * ap0 + ap1 * bp1 + bp2 * ap2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = atan(t0, ap_bp) * t1;
    float t2 = float(1) / ab_ab;
    float t3 = float(1) / ap_ap;
    float t4 = t3 * t3;
    float t5 = t4 * t3;
    float t6 = float(1) / cross_cross;
    float t7 = float(1) / bp_bp;
    float t8 = t7 * t7;
    float t9 = float(2) * t4 * ab_ap + float(3) * ab_ab * (a_minus_b * t7 + t3 * ab_ap + J2 * ab_ab) * t6 + float(2) * a_minus_b * t8;
    float t10 = t8 * t7;
    float t11 = float(8) * t5 * ab_ap + float(5) * ab_ab * t9 * t6 + float(8) * a_minus_b * t10;
    float t12 = float(8) * t5 + t6 * t11 * ab_ap - float(8) * t10;
    F = (float(1) / float(48)) * si.w[2] * t2 * (float(2) * t2 * t12 * ab_ap + float(6) * t9 * t6 - ap_ap * t6 * t11) + (float(1) / float(48)) * t6 * si.w[0] * t11 + (float(1) / float(48)) * si.w[1] * t2 * t12;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-8) dt
// Operations: 57 +, 126 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i8_w2_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  float ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, ap_bp);
    float t3 = float(1) / bp_bp;
    float t4 = t3 * t3;
    float t5 = t4 * t3;
    float t6 = float(1) / ap_ap;
    float t7 = t6 * t6;
    float t8 = t7 * t6;
    float t9 = float(1) / cross_cross;
    float t10 = float(2) * t4 * a_minus_b + float(2) * t7 * ab_ap + float(3) * ab_ab * (J2 * ab_ab + t6 * ab_ap + t3 * a_minus_b) * t9;
    float t11 = float(8) * t5 * a_minus_b + float(8) * t8 * ab_ap + float(5) * t10 * ab_ab * t9;
    float t12 = t11 * t9 * ab_ap + float(8) * t8 - float(8) * t5;
    float t13 = float(1) / ab_ab;
    F = (float(1) / float(48)) * si.w[1] * t12 * t13 + (float(1) / float(48)) * t11 * t9 * si.w[0] + (float(1) / float(48)) * (float(2) * t12 * t13 * ab_ap + float(6) * t10 * t9 - t11 * ap_ap * t9) * si.w[2] * t13;
    float t14 = t7 * t7;
    float t15 = t4 * t4;
    float t16 = float(48) * t14 * ab_ap + float(48) * t15 * a_minus_b + float(7) * t11 * ab_ab * t9;
    float t17 = float(48) * t15 - float(48) * t14 - t16 * t9 * ab_ap;
    G_ap = (float(1) / float(384)) * t16 * t9 * si.w[0] - (float(1) / float(384)) * si.w[1] * t17 * t13 - (float(1) / float(384)) * (float(2) * t17 * t13 * ab_ap + t16 * ap_ap * t9 - float(8) * t11 * t9) * si.w[2] * t13;
    G_E = (float(1) / float(384)) * (float(48) * t14 * si.w[0] + float(2) * t12 * si.w[2] * t13 + si.w[1] * t11 * t9 - float(48) * t15 * (si.w[1] + si.w[2] + si.w[0])) * t13;
  }
  float g_factor = -float(8) * length;
  f = F * length;
  grad[0] = (foot0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = -(ab1 * G_E - foot1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_E - G_ap * foot2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-8) dt
// Operations: 43 +, 84 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i8_w3_f(SegmentInput si) {
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
  float ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, ap_bp);
    float t2 = float(1) / ab_ab;
    float t3 = float(1) / ap_ap;
    float t4 = t3 * t3;
    float t5 = float(1) / cross_cross;
    float t6 = float(1) / bp_bp;
    float t7 = t6 * t6;
    float t8 = float(2) * ab_ap * t4 + float(2) * a_minus_b * t7 + float(3) * ab_ab * (a_minus_b * t6 + ab_ab * J2 + ab_ap * t3) * t5;
    float t9 = t4 * t3;
    float t10 = t7 * t6;
    float t11 = float(8) * ab_ap * t9 + float(5) * ab_ab * t5 * t8 + float(8) * a_minus_b * t10;
    float t12 = float(8) * t9 + t5 * t11 * ab_ap - float(8) * t10;
    float t13 = float(2) * t2 * ab_ap * t12 + float(6) * t5 * t8 - t5 * t11 * ap_ap;
    F = (float(1) / float(48)) * t2 * (float(6) * t2 * (float(2) * t4 + t5 * ab_ap * t8 - float(2) * t7) + float(2) * t2 * ab_ap * t13 - t2 * t12 * ap_ap) * si.w[3] + (float(1) / float(48)) * t5 * t11 * si.w[0] + (float(1) / float(48)) * t2 * si.w[1] * t12 + (float(1) / float(48)) * t2 * si.w[2] * t13;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-8) dt
// Operations: 67 +, 153 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i8_w3_f_and_grad(SegmentInput si, out vec3 grad) {
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
    foot0 = ap0 - ab0 * ab_ap * t0;
    foot1 = ap1 - ab1 * ab_ap * t0;
    foot2 = ap2 - ab_ap * t0 * ab2;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  float ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, ap_bp);
    float t3 = float(1) / cross_cross;
    float t4 = float(1) / ap_ap;
    float t5 = t4 * t4;
    float t6 = float(1) / bp_bp;
    float t7 = t6 * t6;
    float t8 = float(2) * ab_ap * t5 + float(3) * t3 * (J2 * ab_ab + t6 * a_minus_b + ab_ap * t4) * ab_ab + float(2) * t7 * a_minus_b;
    float t9 = t5 * t4;
    float t10 = t7 * t6;
    float t11 = float(8) * ab_ap * t9 + float(8) * t10 * a_minus_b + float(5) * t3 * t8 * ab_ab;
    float t12 = float(8) * t9 + t3 * ab_ap * t11 - float(8) * t10;
    float t13 = float(1) / ab_ab;
    float t14 = float(6) * t3 * t8 + float(2) * ab_ap * t12 * t13 - t3 * t11 * ap_ap;
    F = (float(1) / float(48)) * t14 * si.w[2] * t13 + (float(1) / float(48)) * t3 * t11 * si.w[0] + (float(1) / float(48)) * si.w[1] * t12 * t13 + (float(1) / float(48)) * (float(2) * t14 * ab_ap * t13 + float(6) * (float(2) * t5 + t3 * ab_ap * t8 - float(2) * t7) * t13 - ap_ap * t12 * t13) * si.w[3] * t13;
    float t15 = t5 * t5;
    float t16 = t7 * t7;
    float t17 = float(7) * t3 * t11 * ab_ab + float(48) * ab_ap * t15 + float(48) * t16 * a_minus_b;
    float t18 = t3 * ab_ap * t17 + float(48) * t15 - float(48) * t16;
    float t19 = float(2) * ab_ap * t18 * t13 + float(8) * t3 * t11 - t3 * ap_ap * t17;
    G_ap = (float(1) / float(384)) * si.w[2] * t19 * t13 + (float(1) / float(384)) * si.w[1] * t18 * t13 + (float(1) / float(384)) * (float(8) * t12 * t13 + float(2) * ab_ap * t19 * t13 - ap_ap * t18 * t13) * si.w[3] * t13 + (float(1) / float(384)) * t3 * t17 * si.w[0];
    G_E = (float(1) / float(384)) * (float(3) * t14 * si.w[3] * t13 + t3 * si.w[1] * t11 + float(2) * si.w[2] * t12 * t13 + float(48) * t15 * si.w[0] - float(48) * t16 * (si.w[1] + si.w[2] + si.w[3] + si.w[0])) * t13;
  }
  float g_factor = -float(8) * length;
  f = length * F;
  grad[0] = -(ab0 * G_E - foot0 * G_ap) * g_factor;
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = -g_factor * (G_E * ab2 - foot2 * G_ap);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-9) dt
// Operations: 31 +, 61 *, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i9_w0_f(SegmentInput si) {
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
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / r1;
    float t1 = t0 * t0;
    float t2 = t1 * t1;
    float t3 = float(1) / r0;
    float t4 = t3 * t3;
    float t5 = float(1) / cross_cross;
    float t6 = t4 * t4;
    float t7 = t2 * t1;
    float t8 = t6 * t4;
    F = (float(1) / float(35)) * si.w[0] * (float(2) * ab_ab * (float(3) * t2 * t0 * a_minus_b + float(4) * (t3 * t4 * ab_ap + t1 * t0 * a_minus_b + float(2) * (t3 * ab_ap + t0 * a_minus_b) * ab_ab * t5) * ab_ab * t5 + float(3) * t3 * t6 * ab_ap) * t5 + float(5) * t7 * t0 * a_minus_b + float(5) * t3 * t8 * ab_ap) * t5;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-9) dt
// Operations: 40 +, 103 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i9_w0_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float ab_ap = ap0 * ab0 + ap1 * ab1 + ap2 * ab2;
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
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / r1;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t2;
    float t5 = float(1) / r0;
    float t6 = t5 * t5;
    float t7 = t6 * t6;
    float t8 = t7 * t6;
    float t9 = float(1) / cross_cross;
    float t10 = float(5) * t4 * a_minus_b * t1 + float(5) * ab_ap * t8 * t5 + float(2) * (float(4) * ab_ab * (float(2) * (ab_ap * t5 + a_minus_b * t1) * ab_ab * t9 + t2 * a_minus_b * t1 + ab_ap * t6 * t5) * t9 + float(3) * ab_ap * t7 * t5 + float(3) * t3 * a_minus_b * t1) * ab_ab * t9;
    F = (float(1) / float(35)) * si.w[0] * t10 * t9;
    float t11 = t7 * t7;
    float t12 = t3 * t3;
    G_ap = (float(1) / float(315)) * (float(8) * ab_ab * t10 * t9 + float(35) * ab_ap * t11 * t5 + float(35) * t12 * a_minus_b * t1) * si.w[0] * t9;
    float t13 = float(1) / ab_ab;
    float t14 = t5 * t5;
    float t15 = t14 * t14;
    float t16 = t15 * t15;
    float t17 = t16 * t5;
    float t18 = t1 * t1;
    float t19 = t18 * t18;
    float t20 = t19 * t19;
    float t21 = t20 * t1;
    G_E = (float(1) / float(9)) * t13 * (si.w[0] * t17 - si.w[0] * t21);
  }
  float g_factor = -float(9) * length;
  f = length * F;
  grad[0] = (foot0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = (foot1 * G_ap - G_E * ab1) * g_factor;
  grad[2] = (G_ap * foot2 - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-9) dt
// Operations: 34 +, 69 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i9_w1_f(SegmentInput si) {
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
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = ab0 * bp0 + ab1 * bp1 + ab2 * bp2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / cross_cross;
    float t1 = float(1) / r1;
    float t2 = t1 * t1;
    float t3 = float(1) / r0;
    float t4 = t3 * t3;
    float t5 = t4 * t4;
    float t6 = t2 * t2;
    float t7 = t6 * t2;
    float t8 = t5 * t4;
    float t9 = float(2) * t0 * (float(4) * (t2 * t1 * a_minus_b + t3 * ab_ap * t4 + float(2) * t0 * (t1 * a_minus_b + t3 * ab_ap) * ab_ab) * t0 * ab_ab + float(3) * t3 * ab_ap * t5 + float(3) * t6 * t1 * a_minus_b) * ab_ab + float(5) * t7 * t1 * a_minus_b + float(5) * t3 * ab_ap * t8;
    F = (float(1) / float(35)) * t0 * t9 * si.w[0] - (float(1) / float(35)) * (float(5) * t7 * t1 - t0 * ab_ap * t9 - float(5) * t3 * t8) * si.w[1] / ab_ab;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-9) dt
// Operations: 48 +, 125 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i9_w1_f_and_grad(SegmentInput si, out vec3 grad) {
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
    foot0 = ap0 - ab0 * ab_ap * t0;
    foot1 = ap1 - ab1 * ab_ap * t0;
    foot2 = ap2 - ab2 * ab_ap * t0;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / cross_cross;
    float t2 = float(1) / r0;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = t4 * t3;
    float t6 = float(1) / r1;
    float t7 = t6 * t6;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = float(5) * ab_ap * t5 * t2 + float(2) * t1 * (float(4) * (t6 * t7 * a_minus_b + float(2) * t1 * ab_ab * (t6 * a_minus_b + ab_ap * t2) + ab_ap * t3 * t2) * t1 * ab_ab + float(3) * ab_ap * t4 * t2 + float(3) * t6 * t8 * a_minus_b) * ab_ab + float(5) * t6 * t9 * a_minus_b;
    float t11 = float(1) / ab_ab;
    F = (float(1) / float(35)) * t1 * t10 * si.w[0] + (float(1) / float(35)) * (t1 * ab_ap * t10 + float(5) * t5 * t2 - float(5) * t6 * t9) * si.w[1] * t11;
    float t12 = t8 * t8;
    float t13 = t4 * t4;
    float t14 = float(35) * t6 * t12 * a_minus_b + float(8) * t1 * t10 * ab_ab + float(35) * ab_ap * t13 * t2;
    G_ap = (float(1) / float(315)) * t1 * si.w[0] * t14 + (float(1) / float(315)) * (t1 * ab_ap * t14 + float(35) * t13 * t2 - float(35) * t6 * t12) * si.w[1] * t11;
    float t15 = t6 * t6;
    float t16 = t15 * t15;
    float t17 = t16 * t16;
    float t18 = t17 * t6;
    float t19 = t2 * t2;
    float t20 = t19 * t19;
    float t21 = t20 * t20;
    float t22 = t21 * t2;
    G_E = -(float(1) / float(315)) * (float(35) * t18 * (si.w[0] + si.w[1]) - t1 * t10 * si.w[1] - float(35) * si.w[0] * t22) * t11;
  }
  float g_factor = -float(9) * length;
  f = length * F;
  grad[0] = (foot0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = -(ab2 * G_E - foot2 * G_ap) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-9) dt
// Operations: 37 +, 81 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i9_w2_f(SegmentInput si) {
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
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / r0;
    float t1 = t0 * t0;
    float t2 = float(1) / r1;
    float t3 = float(1) / cross_cross;
    float t4 = t2 * t2;
    float t5 = t4 * t4;
    float t6 = t1 * t1;
    float t7 = float(4) * ab_ab * (ab_ap * t0 * t1 + float(2) * (ab_ap * t0 + t2 * a_minus_b) * ab_ab * t3 + t4 * t2 * a_minus_b) * t3 + float(3) * t5 * t2 * a_minus_b + float(3) * ab_ap * t0 * t6;
    float t8 = t5 * t4;
    float t9 = t6 * t1;
    float t10 = float(2) * t7 * ab_ab * t3 + float(5) * t8 * t2 * a_minus_b + float(5) * ab_ap * t0 * t9;
    float t11 = float(1) / ab_ab;
    float t12 = float(5) * t8 * t2 - ab_ap * t10 * t3 - float(5) * t0 * t9;
    F = (float(1) / float(35)) * t10 * t3 * si.w[0] - (float(1) / float(105)) * si.w[2] * (float(6) * ab_ap * t11 * t12 + float(3) * ap_ap * t10 * t3 - float(7) * t7 * t3) * t11 - (float(1) / float(35)) * si.w[1] * t11 * t12;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-9) dt
// Operations: 56 +, 149 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i9_w2_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
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
    float t8 = float(1) / cross_cross;
    float t9 = float(3) * t7 * a_minus_b * t5 + float(3) * ab_ap * t3 * t1 + float(4) * (t6 * a_minus_b * t5 + ab_ap * t2 * t1 + float(2) * (ab_ap * t1 + a_minus_b * t5) * ab_ab * t8) * ab_ab * t8;
    float t10 = t7 * t6;
    float t11 = float(5) * ab_ap * t4 * t1 + float(2) * ab_ab * t9 * t8 + float(5) * t10 * a_minus_b * t5;
    float t12 = float(1) / ab_ab;
    float t13 = float(5) * t4 * t1 + ab_ap * t11 * t8 - float(5) * t10 * t5;
    F = (float(1) / float(35)) * si.w[0] * t11 * t8 + (float(1) / float(35)) * si.w[1] * t12 * t13 - (float(1) / float(105)) * (float(3) * t11 * ap_ap * t8 - float(6) * ab_ap * t12 * t13 - float(7) * t9 * t8) * si.w[2] * t12;
    float t14 = t7 * t7;
    float t15 = t3 * t3;
    float t16 = float(35) * t14 * a_minus_b * t5 + float(8) * t11 * ab_ab * t8 + float(35) * ab_ap * t15 * t1;
    float t17 = float(35) * t14 * t5 - ab_ap * t16 * t8 - float(35) * t15 * t1;
    G_ap = (float(1) / float(315)) * si.w[0] * t16 * t8 - (float(1) / float(315)) * (ap_ap * t16 * t8 + float(2) * ab_ap * t17 * t12 - float(9) * t11 * t8) * si.w[2] * t12 - (float(1) / float(315)) * si.w[1] * t17 * t12;
    float t18 = t1 * t1;
    float t19 = t18 * t18;
    float t20 = t19 * t19;
    float t21 = t20 * t1;
    float t22 = t5 * t5;
    float t23 = t22 * t22;
    float t24 = t23 * t23;
    float t25 = t24 * t5;
    G_E = (float(1) / float(315)) * t12 * (si.w[1] * t11 * t8 + float(35) * si.w[0] * t21 + float(2) * si.w[2] * t12 * t13 - float(35) * (si.w[0] + si.w[1] + si.w[2]) * t25);
  }
  float g_factor = -float(9) * length;
  f = length * F;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = g_factor * (foot1 * G_ap - G_E * ab1);
  grad[2] = (G_ap * foot2 - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-9) dt
// Operations: 42 +, 98 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i9_w3_f(SegmentInput si) {
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
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
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
    float t8 = float(1) / cross_cross;
    float t9 = float(4) * ab_ab * t8 * (a_minus_b * t1 * t0 + t4 * ab_ap * t5 + float(2) * ab_ab * t8 * (a_minus_b * t0 + t4 * ab_ap)) + float(3) * a_minus_b * t2 * t0 + float(3) * t4 * ab_ap * t6;
    float t10 = float(5) * a_minus_b * t3 * t0 + float(5) * t4 * ab_ap * t7 + float(2) * ab_ab * t9 * t8;
    float t11 = t10 * t8 * ab_ap + float(5) * t4 * t7 - float(5) * t3 * t0;
    float t12 = float(1) / ab_ab;
    float t13 = float(6) * t11 * t12 * ab_ap + float(7) * t9 * t8 - float(3) * t10 * t8 * ap_ap;
    F = (float(1) / float(35)) * si.w[0] * t10 * t8 + (float(1) / float(35)) * t11 * t12 * si.w[1] + (float(1) / float(105)) * t12 * (float(7) * t12 * (float(3) * t4 * t6 + t9 * t8 * ab_ap - float(3) * t2 * t0) + float(2) * t12 * t13 * ab_ap - float(3) * t11 * t12 * ap_ap) * si.w[3] + (float(1) / float(105)) * t12 * t13 * si.w[2];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-9) dt
// Operations: 66 +, 178 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i9_w3_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / r0;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t2;
    float t5 = float(1) / cross_cross;
    float t6 = float(1) / r1;
    float t7 = t6 * t6;
    float t8 = t7 * t7;
    float t9 = float(3) * t1 * ab_ap * t3 + float(3) * t6 * t8 * a_minus_b + float(4) * ab_ab * t5 * (t6 * t7 * a_minus_b + t1 * ab_ap * t2 + float(2) * ab_ab * t5 * (t1 * ab_ap + t6 * a_minus_b));
    float t10 = t8 * t7;
    float t11 = float(2) * ab_ab * t5 * t9 + float(5) * t6 * t10 * a_minus_b + float(5) * t1 * ab_ap * t4;
    float t12 = float(5) * t1 * t4 + t5 * ab_ap * t11 - float(5) * t6 * t10;
    float t13 = float(1) / ab_ab;
    float t14 = float(3) * t5 * t11 * ap_ap - float(6) * t12 * t13 * ab_ap - float(7) * t5 * t9;
    F = (float(1) / float(35)) * t12 * t13 * si.w[1] + (float(1) / float(35)) * si.w[0] * t5 * t11 - (float(1) / float(105)) * si.w[3] * t13 * (float(3) * t12 * t13 * ap_ap + float(2) * t13 * ab_ap * t14 - float(7) * (float(3) * t1 * t3 + t5 * ab_ap * t9 - float(3) * t6 * t8) * t13) - (float(1) / float(105)) * t13 * t14 * si.w[2];
    float t15 = t8 * t8;
    float t16 = t3 * t3;
    float t17 = float(8) * ab_ab * t5 * t11 + float(35) * t6 * t15 * a_minus_b + float(35) * t1 * ab_ap * t16;
    float t18 = float(35) * t1 * t16 + t5 * ab_ap * t17 - float(35) * t6 * t15;
    float t19 = float(2) * t13 * ab_ap * t18 + float(9) * t5 * t11 - t5 * t17 * ap_ap;
    G_ap = (float(1) / float(315)) * si.w[0] * t5 * t17 + (float(1) / float(315)) * t13 * si.w[1] * t18 + (float(1) / float(315)) * t13 * t19 * si.w[2] - (float(1) / float(315)) * si.w[3] * t13 * (t13 * ap_ap * t18 - float(2) * t13 * t19 * ab_ap - float(9) * t12 * t13);
    float t20 = t1 * t1;
    float t21 = t20 * t20;
    float t22 = t21 * t21;
    float t23 = t22 * t1;
    float t24 = t6 * t6;
    float t25 = t24 * t24;
    float t26 = t25 * t25;
    float t27 = t26 * t6;
    G_E = (float(1) / float(315)) * t13 * (t5 * si.w[1] * t11 + float(35) * t23 * si.w[0] + float(2) * t12 * t13 * si.w[2] - si.w[3] * t13 * t14 - float(35) * t27 * (si.w[3] + si.w[0] + si.w[1] + si.w[2]));
  }
  float g_factor = -float(9) * length;
  f = length * F;
  grad[0] = (G_ap * foot0 - ab0 * G_E) * g_factor;
  grad[1] = -(ab1 * G_E - G_ap * foot1) * g_factor;
  grad[2] = (G_ap * foot2 - ab2 * G_E) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-10) dt
// Operations: 34 +, 62 *, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i10_w0_f(SegmentInput si) {
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
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab0 * bp0 + ab1 * bp1 + bp2 * ab2;
  float ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, ap_bp);
    float t2 = float(1) / cross_cross;
    float t3 = float(1) / ap_ap;
    float t4 = t3 * t3;
    float t5 = t4 * t4;
    float t6 = float(1) / bp_bp;
    float t7 = t6 * t6;
    float t8 = t7 * t7;
    float t9 = t4 * t3;
    float t10 = t7 * t6;
    F = (float(1) / float(384)) * t2 * (float(48) * ab_ap * t5 + float(48) * t8 * a_minus_b + float(7) * t2 * (float(8) * ab_ap * t9 + float(5) * t2 * (float(2) * ab_ap * t4 + float(2) * t7 * a_minus_b + float(3) * t2 * (t6 * a_minus_b + ab_ab * J2 + ab_ap * t3) * ab_ab) * ab_ab + float(8) * t10 * a_minus_b) * ab_ab) * si.w[0];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-10) dt
// Operations: 43 +, 94 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i10_w0_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  float ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, ap_bp);
    float t3 = float(1) / cross_cross;
    float t4 = float(1) / ap_ap;
    float t5 = t4 * t4;
    float t6 = t5 * t5;
    float t7 = float(1) / bp_bp;
    float t8 = t7 * t7;
    float t9 = t8 * t8;
    float t10 = t5 * t4;
    float t11 = t8 * t7;
    float t12 = float(48) * ab_ap * t6 + float(48) * t9 * a_minus_b + float(7) * t3 * (float(8) * ab_ap * t10 + float(8) * t11 * a_minus_b + float(5) * t3 * (float(2) * ab_ap * t5 + float(3) * t3 * (J2 * ab_ab + t7 * a_minus_b + ab_ap * t4) * ab_ab + float(2) * t8 * a_minus_b) * ab_ab) * ab_ab;
    F = (float(1) / float(384)) * t3 * si.w[0] * t12;
    float t13 = t6 * t4;
    float t14 = t9 * t7;
    G_ap = (float(1) / float(1280)) * (float(3) * t3 * t12 * ab_ab + float(128) * ab_ap * t13 + float(128) * t14 * a_minus_b) * t3 * si.w[0];
    float t15 = float(1) / ab_ab;
    G_E = -(float(1) / float(10)) * t15 * (t14 * si.w[0] - t13 * si.w[0]);
  }
  float g_factor = -float(10) * length;
  f = length * F;
  grad[0] = -(ab0 * G_E - foot0 * G_ap) * g_factor;
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = -(ab2 * G_E - foot2 * G_ap) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-10) dt
// Operations: 37 +, 68 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i10_w1_f(SegmentInput si) {
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
  float ab_ap = ab0 * ap0 + ap2 * ab2 + ap1 * ab1;
  float ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  float plain_cross0 = ap2 * ab1 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ap2 * ab0;
  float plain_cross2 = ab0 * ap1 - ap0 * ab1;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
  float ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = atan(t0, ap_bp) * t1;
    float t2 = float(1) / ap_ap;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = float(1) / bp_bp;
    float t6 = float(1) / cross_cross;
    float t7 = t5 * t5;
    float t8 = t3 * t2;
    float t9 = t7 * t5;
    float t10 = t7 * t7;
    float t11 = float(48) * ab_ap * t4 + float(7) * (float(5) * ab_ab * (float(2) * ab_ap * t3 + float(3) * (t5 * a_minus_b + J2 * ab_ab + ab_ap * t2) * ab_ab * t6 + float(2) * t7 * a_minus_b) * t6 + float(8) * ab_ap * t8 + float(8) * t9 * a_minus_b) * ab_ab * t6 + float(48) * t10 * a_minus_b;
    F = (float(1) / float(384)) * (ab_ap * t11 * t6 + float(48) * t4 - float(48) * t10) * si.w[1] / ab_ab + (float(1) / float(384)) * si.w[0] * t11 * t6;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-10) dt
// Operations: 51 +, 112 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i10_w1_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  float ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, ap_bp);
    float t3 = float(1) / cross_cross;
    float t4 = float(1) / ap_ap;
    float t5 = t4 * t4;
    float t6 = t5 * t4;
    float t7 = float(1) / bp_bp;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = t5 * t5;
    float t11 = t8 * t8;
    float t12 = float(7) * t3 * (float(8) * ab_ap * t6 + float(8) * t9 * a_minus_b + float(5) * t3 * (float(2) * ab_ap * t5 + float(2) * t8 * a_minus_b + float(3) * t3 * ab_ab * (t7 * a_minus_b + ab_ap * t4 + J2 * ab_ab)) * ab_ab) * ab_ab + float(48) * ab_ap * t10 + float(48) * t11 * a_minus_b;
    float t13 = float(1) / ab_ab;
    F = (float(1) / float(384)) * t3 * si.w[0] * t12 - (float(1) / float(384)) * (float(48) * t11 - t3 * ab_ap * t12 - float(48) * t10) * si.w[1] * t13;
    float t14 = t10 * t4;
    float t15 = t11 * t7;
    float t16 = float(3) * t3 * t12 * ab_ab + float(128) * ab_ap * t14 + float(128) * t15 * a_minus_b;
    G_ap = (float(1) / float(1280)) * t3 * t16 * si.w[0] - (float(1) / float(1280)) * si.w[1] * t13 * (float(128) * t15 - t3 * t16 * ab_ap - float(128) * t14);
    G_E = (float(1) / float(3840)) * (float(384) * si.w[0] * t14 + t3 * si.w[1] * t12 - float(384) * t15 * (si.w[0] + si.w[1])) * t13;
  }
  float g_factor = -float(10) * length;
  f = length * F;
  grad[0] = -g_factor * (G_E * ab0 - foot0 * G_ap);
  grad[1] = -(G_E * ab1 - foot1 * G_ap) * g_factor;
  grad[2] = (G_ap * foot2 - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-10) dt
// Operations: 40 +, 79 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i10_w2_f(SegmentInput si) {
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
  float ab_ap = ap1 * ab1 + ab0 * ap0 + ap2 * ab2;
  float ap_ap = ap2 * ap2 + ap1 * ap1 + ap0 * ap0;
  float plain_cross0 = ap2 * ab1 - ap1 * ab2;
  float plain_cross1 = ab2 * ap0 - ap2 * ab0;
  float plain_cross2 = ap1 * ab0 - ab1 * ap0;
  float plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  float ap_bp = ap1 * bp1 + ap2 * bp2 + bp0 * ap0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, ap_bp);
    float t2 = float(1) / ap_ap;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = float(1) / bp_bp;
    float t6 = t5 * t5;
    float t7 = t6 * t5;
    float t8 = float(1) / cross_cross;
    float t9 = t3 * t2;
    float t10 = float(8) * t7 * a_minus_b + float(5) * (float(3) * (J2 * ab_ab + t2 * ab_ap + t5 * a_minus_b) * ab_ab * t8 + float(2) * t6 * a_minus_b + float(2) * t3 * ab_ap) * ab_ab * t8 + float(8) * t9 * ab_ap;
    float t11 = t6 * t6;
    float t12 = float(48) * t4 * ab_ap + float(7) * t10 * ab_ab * t8 + float(48) * t11 * a_minus_b;
    float t13 = float(48) * t11 - float(48) * t4 - t12 * t8 * ab_ap;
    float t14 = float(1) / ab_ab;
    F = (float(1) / float(384)) * t12 * si.w[0] * t8 - (float(1) / float(384)) * si.w[2] * (ap_ap * t12 * t8 + float(2) * t13 * t14 * ab_ap - float(8) * t10 * t8) * t14 - (float(1) / float(384)) * si.w[1] * t13 * t14;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-10) dt
// Operations: 59 +, 136 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i10_w2_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  float ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = atan(t1, ap_bp) * t2;
    float t3 = float(1) / bp_bp;
    float t4 = t3 * t3;
    float t5 = t4 * t3;
    float t6 = float(1) / ap_ap;
    float t7 = float(1) / cross_cross;
    float t8 = t6 * t6;
    float t9 = t8 * t6;
    float t10 = float(8) * t5 * a_minus_b + float(5) * ab_ab * (float(2) * t4 * a_minus_b + float(3) * (J2 * ab_ab + t6 * ab_ap + t3 * a_minus_b) * ab_ab * t7 + float(2) * t8 * ab_ap) * t7 + float(8) * t9 * ab_ap;
    float t11 = t8 * t8;
    float t12 = t4 * t4;
    float t13 = float(7) * ab_ab * t10 * t7 + float(48) * t11 * ab_ap + float(48) * t12 * a_minus_b;
    float t14 = float(48) * t12 - float(48) * t11 - t13 * t7 * ab_ap;
    float t15 = float(1) / ab_ab;
    F = (float(1) / float(384)) * (float(8) * t10 * t7 - ap_ap * t13 * t7 - float(2) * t14 * t15 * ab_ap) * si.w[2] * t15 + (float(1) / float(384)) * t13 * t7 * si.w[0] - (float(1) / float(384)) * t14 * si.w[1] * t15;
    float t16 = t11 * t6;
    float t17 = t12 * t3;
    float t18 = float(128) * t16 * ab_ap + float(3) * t13 * ab_ab * t7 + float(128) * t17 * a_minus_b;
    float t19 = float(128) * t17 - t18 * t7 * ab_ap - float(128) * t16;
    G_ap = (float(1) / float(3840)) * si.w[2] * t15 * (float(10) * t13 * t7 - float(3) * t18 * ap_ap * t7 - float(6) * t19 * t15 * ab_ap) + (float(1) / float(1280)) * t18 * t7 * si.w[0] - (float(1) / float(1280)) * t19 * si.w[1] * t15;
    G_E = -(float(1) / float(3840)) * (float(2) * t14 * si.w[2] * t15 + float(384) * t17 * (si.w[1] + si.w[2] + si.w[0]) - si.w[1] * t13 * t7 - float(384) * t16 * si.w[0]) * t15;
  }
  float g_factor = -float(10) * length;
  f = F * length;
  grad[0] = (foot0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = -(ab1 * G_E - foot1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_E - G_ap * foot2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-10) dt
// Operations: 45 +, 93 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i10_w3_f(SegmentInput si) {
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
  float ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  float ap_bp = ap1 * bp1 + ap0 * bp0 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = atan(t0, ap_bp) * t1;
    float t2 = float(1) / ap_ap;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = float(1) / cross_cross;
    float t6 = t3 * t2;
    float t7 = float(1) / bp_bp;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = float(8) * ab_ap * t6 + float(5) * (float(3) * (ab_ap * t2 + J2 * ab_ab + a_minus_b * t7) * ab_ab * t5 + float(2) * a_minus_b * t8 + float(2) * ab_ap * t3) * ab_ab * t5 + float(8) * a_minus_b * t9;
    float t11 = t8 * t8;
    float t12 = float(7) * ab_ab * t5 * t10 + float(48) * a_minus_b * t11 + float(48) * ab_ap * t4;
    float t13 = float(48) * t4 + t5 * ab_ap * t12 - float(48) * t11;
    float t14 = float(1) / ab_ab;
    float t15 = t5 * t12 * ap_ap - float(8) * t5 * t10 - float(2) * t13 * t14 * ab_ap;
    F = (float(1) / float(384)) * t13 * t14 * si.w[1] + (float(1) / float(384)) * si.w[0] * t5 * t12 - (float(1) / float(384)) * t14 * (float(2) * t15 * t14 * ab_ap + t13 * t14 * ap_ap - float(8) * t14 * (float(8) * t6 + t5 * ab_ap * t10 - float(8) * t9)) * si.w[3] - (float(1) / float(384)) * t15 * t14 * si.w[2];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-10) dt
// Operations: 69 +, 164 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i10_w3_f_and_grad(SegmentInput si, out vec3 grad) {
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
    foot0 = ap0 - ab0 * ab_ap * t0;
    foot1 = ap1 - ab1 * ab_ap * t0;
    foot2 = ap2 - ab2 * ab_ap * t0;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  float ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, ap_bp);
    float t3 = float(1) / cross_cross;
    float t4 = float(1) / ap_ap;
    float t5 = t4 * t4;
    float t6 = t5 * t4;
    float t7 = float(1) / bp_bp;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = float(8) * ab_ap * t6 + float(8) * t9 * a_minus_b + float(5) * t3 * (float(2) * ab_ap * t5 + float(2) * t8 * a_minus_b + float(3) * (J2 * ab_ab + t7 * a_minus_b + ab_ap * t4) * t3 * ab_ab) * ab_ab;
    float t11 = float(1) / ab_ab;
    float t12 = t5 * t5;
    float t13 = t8 * t8;
    float t14 = float(7) * t3 * t10 * ab_ab + float(48) * ab_ap * t12 + float(48) * t13 * a_minus_b;
    float t15 = t14 * t3 * ab_ap + float(48) * t12 - float(48) * t13;
    float t16 = float(2) * ab_ap * t15 * t11 + float(8) * t3 * t10 - t14 * t3 * ap_ap;
    F = (float(1) / float(384)) * (float(8) * (t3 * ab_ap * t10 + float(8) * t6 - float(8) * t9) * t11 + float(2) * t16 * ab_ap * t11 - ap_ap * t15 * t11) * si.w[3] * t11 + (float(1) / float(384)) * t14 * t3 * si.w[0] + (float(1) / float(384)) * si.w[1] * t15 * t11 + (float(1) / float(384)) * t16 * si.w[2] * t11;
    float t17 = t12 * t4;
    float t18 = t13 * t7;
    float t19 = float(3) * t14 * t3 * ab_ab + float(128) * t18 * a_minus_b + float(128) * ab_ap * t17;
    float t20 = float(128) * t17 + t3 * ab_ap * t19 - float(128) * t18;
    float t21 = float(6) * t20 * ab_ap * t11 + float(10) * t14 * t3 - float(3) * t3 * t19 * ap_ap;
    G_ap = (float(1) / float(3840)) * si.w[2] * t21 * t11 + (float(1) / float(1280)) * t3 * t19 * si.w[0] + (float(1) / float(1280)) * t20 * si.w[1] * t11 + (float(1) / float(3840)) * (float(2) * ab_ap * t21 * t11 + float(10) * t15 * t11 - float(3) * t20 * ap_ap * t11) * si.w[3] * t11;
    G_E = (float(1) / float(3840)) * (float(384) * t17 * si.w[0] + float(3) * t16 * si.w[3] * t11 + float(2) * si.w[2] * t15 * t11 + t14 * t3 * si.w[1] - float(384) * (si.w[1] + si.w[2] + si.w[3] + si.w[0]) * t18) * t11;
  }
  float g_factor = -float(10) * length;
  f = length * F;
  grad[0] = (foot0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = g_factor * (foot1 * G_ap - ab1 * G_E);
  grad[2] = -(ab2 * G_E - foot2 * G_ap) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-11) dt
// Operations: 33 +, 72 *, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i11_w0_f(SegmentInput si) {
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
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / cross_cross;
    float t1 = float(1) / r0;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = float(1) / r1;
    float t6 = t5 * t5;
    float t7 = t6 * t6;
    float t8 = t7 * t7;
    float t9 = t3 * t2;
    float t10 = t7 * t6;
    F = (float(1) / float(315)) * si.w[0] * t0 * (float(35) * ab_ap * t1 * t4 + float(35) * t8 * t5 * a_minus_b + float(8) * (float(5) * ab_ap * t1 * t9 + float(2) * (float(4) * (float(2) * (t5 * a_minus_b + ab_ap * t1) * ab_ab * t0 + ab_ap * t1 * t2 + t6 * t5 * a_minus_b) * ab_ab * t0 + float(3) * t7 * t5 * a_minus_b + float(3) * ab_ap * t1 * t3) * ab_ab * t0 + float(5) * t10 * t5 * a_minus_b) * ab_ab * t0);
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-11) dt
// Operations: 42 +, 116 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i11_w0_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / r1;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = float(1) / r0;
    float t6 = t5 * t5;
    float t7 = t6 * t6;
    float t8 = t7 * t6;
    float t9 = float(1) / cross_cross;
    float t10 = t3 * t2;
    float t11 = t7 * t7;
    float t12 = float(35) * t4 * a_minus_b * t1 + float(8) * (float(5) * ab_ap * t8 * t5 + float(2) * ab_ab * (float(4) * (t2 * a_minus_b * t1 + ab_ap * t6 * t5 + float(2) * ab_ab * (ab_ap * t5 + a_minus_b * t1) * t9) * ab_ab * t9 + float(3) * t3 * a_minus_b * t1 + float(3) * ab_ap * t7 * t5) * t9 + float(5) * t10 * a_minus_b * t1) * ab_ab * t9 + float(35) * ab_ap * t11 * t5;
    F = (float(1) / float(315)) * si.w[0] * t12 * t9;
    float t13 = t4 * t2;
    float t14 = t11 * t6;
    G_ap = (float(1) / float(693)) * (float(63) * t13 * a_minus_b * t1 + float(2) * ab_ab * t12 * t9 + float(63) * ab_ap * t14 * t5) * si.w[0] * t9;
    float t15 = t1 * t1;
    float t16 = t15 * t15;
    float t17 = t16 * t1;
    float t18 = t17 * t17;
    float t19 = t18 * t1;
    float t20 = t5 * t5;
    float t21 = t20 * t20;
    float t22 = t21 * t5;
    float t23 = t22 * t22;
    float t24 = t23 * t5;
    float t25 = float(1) / ab_ab;
    G_E = -(float(1) / float(11)) * (si.w[0] * t19 - si.w[0] * t24) * t25;
  }
  float g_factor = -float(11) * length;
  f = length * F;
  grad[0] = (foot0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = g_factor * (foot1 * G_ap - G_E * ab1);
  grad[2] = (G_ap * foot2 - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-11) dt
// Operations: 36 +, 80 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i11_w1_f(SegmentInput si) {
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
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / r0;
    float t1 = t0 * t0;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = float(1) / r1;
    float t5 = t4 * t4;
    float t6 = t5 * t5;
    float t7 = t6 * t6;
    float t8 = t2 * t1;
    float t9 = float(1) / cross_cross;
    float t10 = t6 * t5;
    float t11 = float(35) * t3 * t0 * ab_ap + float(35) * t4 * a_minus_b * t7 + float(8) * ab_ab * (float(5) * t8 * t0 * ab_ap + float(2) * ab_ab * (float(3) * t4 * a_minus_b * t6 + float(4) * (t1 * t0 * ab_ap + t4 * a_minus_b * t5 + float(2) * (t4 * a_minus_b + t0 * ab_ap) * ab_ab * t9) * ab_ab * t9 + float(3) * t2 * t0 * ab_ap) * t9 + float(5) * t4 * a_minus_b * t10) * t9;
    F = (float(1) / float(315)) * si.w[0] * t11 * t9 + (float(1) / float(315)) * si.w[1] * (float(35) * t3 * t0 + t11 * t9 * ab_ap - float(35) * t4 * t7) / ab_ab;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-11) dt
// Operations: 50 +, 138 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i11_w1_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / r1;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t2;
    float t5 = float(1) / r0;
    float t6 = t5 * t5;
    float t7 = t6 * t6;
    float t8 = t7 * t6;
    float t9 = float(1) / cross_cross;
    float t10 = t3 * t3;
    float t11 = t7 * t7;
    float t12 = float(8) * (float(5) * a_minus_b * t1 * t4 + float(5) * t8 * t5 * ab_ap + float(2) * (float(4) * ab_ab * t9 * (float(2) * (t5 * ab_ap + a_minus_b * t1) * ab_ab * t9 + t6 * t5 * ab_ap + a_minus_b * t1 * t2) + float(3) * a_minus_b * t1 * t3 + float(3) * t7 * t5 * ab_ap) * ab_ab * t9) * ab_ab * t9 + float(35) * a_minus_b * t1 * t10 + float(35) * t11 * t5 * ab_ap;
    float t13 = float(1) / ab_ab;
    F = (float(1) / float(315)) * si.w[0] * t12 * t9 + (float(1) / float(315)) * si.w[1] * t13 * (float(35) * t11 * t5 + t12 * t9 * ab_ap - float(35) * t1 * t10);
    float t14 = t11 * t6;
    float t15 = t10 * t2;
    float t16 = float(63) * a_minus_b * t1 * t15 + float(2) * ab_ab * t12 * t9 + float(63) * t14 * t5 * ab_ap;
    G_ap = (float(1) / float(693)) * (float(63) * t14 * t5 + t16 * t9 * ab_ap - float(63) * t1 * t15) * si.w[1] * t13 + (float(1) / float(693)) * si.w[0] * t16 * t9;
    float t17 = t1 * t1;
    float t18 = t17 * t17;
    float t19 = t18 * t1;
    float t20 = t19 * t19;
    float t21 = t20 * t1;
    float t22 = t5 * t5;
    float t23 = t22 * t22;
    float t24 = t23 * t5;
    float t25 = t24 * t24;
    float t26 = t25 * t5;
    G_E = -(float(1) / float(3465)) * (float(315) * (si.w[0] + si.w[1]) * t21 - float(315) * si.w[0] * t26 - si.w[1] * t12 * t9) * t13;
  }
  float g_factor = -float(11) * length;
  f = F * length;
  grad[0] = (G_ap * foot0 - ab0 * G_E) * g_factor;
  grad[1] = -g_factor * (ab1 * G_E - foot1 * G_ap);
  grad[2] = -g_factor * (ab2 * G_E - G_ap * foot2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-11) dt
// Operations: 39 +, 91 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i11_w2_f(SegmentInput si) {
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / ab_ab;
    float t1 = float(1) / cross_cross;
    float t2 = float(1) / r0;
    float t3 = t2 * t2;
    float t4 = float(1) / r1;
    float t5 = t4 * t4;
    float t6 = t5 * t5;
    float t7 = t3 * t3;
    float t8 = t7 * t3;
    float t9 = t6 * t5;
    float t10 = float(2) * ab_ab * (float(4) * ab_ab * t1 * (t3 * t2 * ab_ap + a_minus_b * t5 * t4 + float(2) * ab_ab * t1 * (t2 * ab_ap + a_minus_b * t4)) + float(3) * a_minus_b * t6 * t4 + float(3) * t7 * t2 * ab_ap) * t1 + float(5) * t8 * t2 * ab_ap + float(5) * a_minus_b * t9 * t4;
    float t11 = t6 * t6;
    float t12 = t7 * t7;
    float t13 = float(35) * a_minus_b * t11 * t4 + float(8) * ab_ab * t10 * t1 + float(35) * t12 * t2 * ab_ap;
    float t14 = t13 * t1 * ab_ap + float(35) * t12 * t2 - float(35) * t11 * t4;
    F = (float(1) / float(315)) * si.w[2] * t0 * (float(9) * t10 * t1 + float(2) * t14 * t0 * ab_ap - ap_ap * t13 * t1) + (float(1) / float(315)) * t14 * t0 * si.w[1] + (float(1) / float(315)) * t13 * t1 * si.w[0];
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-11) dt
// Operations: 58 +, 162 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i11_w2_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / r1;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = float(1) / r0;
    float t6 = t5 * t5;
    float t7 = t6 * t6;
    float t8 = t7 * t7;
    float t9 = float(1) / cross_cross;
    float t10 = t3 * t2;
    float t11 = t7 * t6;
    float t12 = float(5) * t1 * t10 * a_minus_b + float(2) * ab_ab * t9 * (float(4) * ab_ab * t9 * (float(2) * ab_ab * t9 * (t5 * ab_ap + t1 * a_minus_b) + t5 * ab_ap * t6 + t1 * t2 * a_minus_b) + float(3) * t1 * t3 * a_minus_b + float(3) * t5 * ab_ap * t7) + float(5) * t5 * ab_ap * t11;
    float t13 = float(35) * t1 * t4 * a_minus_b + float(35) * t5 * ab_ap * t8 + float(8) * ab_ab * t9 * t12;
    float t14 = float(1) / ab_ab;
    float t15 = t13 * t9 * ab_ap + float(35) * t5 * t8 - float(35) * t1 * t4;
    F = (float(1) / float(315)) * t13 * t9 * si.w[0] + (float(1) / float(315)) * t14 * t15 * si.w[1] + (float(1) / float(315)) * si.w[2] * t14 * (float(2) * t14 * t15 * ab_ap + float(9) * t9 * t12 - t13 * t9 * ap_ap);
    float t16 = t4 * t2;
    float t17 = t8 * t6;
    float t18 = float(63) * t1 * t16 * a_minus_b + float(2) * t13 * ab_ab * t9 + float(63) * t5 * ab_ap * t17;
    float t19 = t9 * ab_ap * t18 + float(63) * t5 * t17 - float(63) * t1 * t16;
    G_ap = (float(1) / float(693)) * t19 * t14 * si.w[1] + (float(1) / float(693)) * t9 * si.w[0] * t18 - (float(1) / float(3465)) * si.w[2] * t14 * (float(5) * t9 * t18 * ap_ap - float(10) * t19 * t14 * ab_ap - float(11) * t13 * t9);
    float t20 = t5 * t5;
    float t21 = t20 * t20;
    float t22 = t21 * t5;
    float t23 = t22 * t22;
    float t24 = t23 * t5;
    float t25 = t1 * t1;
    float t26 = t25 * t25;
    float t27 = t26 * t1;
    float t28 = t27 * t27;
    float t29 = t28 * t1;
    G_E = (float(1) / float(3465)) * (float(2) * si.w[2] * t14 * t15 + float(315) * t24 * si.w[0] + t13 * t9 * si.w[1] - float(315) * (si.w[2] + si.w[0] + si.w[1]) * t29) * t14;
  }
  float g_factor = -float(11) * length;
  f = length * F;
  grad[0] = (G_ap * foot0 - ab0 * G_E) * g_factor;
  grad[1] = -(ab1 * G_E - foot1 * G_ap) * g_factor;
  grad[2] = g_factor * (G_ap * foot2 - ab2 * G_E);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-11) dt
// Operations: 44 +, 107 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i11_w3_f(SegmentInput si) {
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
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / r0;
    float t1 = t0 * t0;
    float t2 = t1 * t1;
    float t3 = t2 * t1;
    float t4 = float(1) / r1;
    float t5 = t4 * t4;
    float t6 = float(1) / cross_cross;
    float t7 = t5 * t5;
    float t8 = t7 * t5;
    float t9 = float(5) * t0 * ab_ap * t3 + float(2) * (float(4) * ab_ab * (t5 * t4 * a_minus_b + float(2) * (t0 * ab_ap + t4 * a_minus_b) * ab_ab * t6 + t0 * ab_ap * t1) * t6 + float(3) * t0 * ab_ap * t2 + float(3) * t7 * t4 * a_minus_b) * ab_ab * t6 + float(5) * t8 * t4 * a_minus_b;
    float t10 = t7 * t7;
    float t11 = t2 * t2;
    float t12 = float(35) * t10 * t4 * a_minus_b + float(8) * t9 * ab_ab * t6 + float(35) * t0 * ab_ap * t11;
    float t13 = float(35) * t10 * t4 - float(35) * t0 * t11 - t12 * ab_ap * t6;
    float t14 = float(1) / ab_ab;
    float t15 = float(9) * t9 * t6 - t12 * ap_ap * t6 - float(2) * ab_ap * t13 * t14;
    F = (float(1) / float(315)) * si.w[2] * t15 * t14 + (float(1) / float(315)) * t12 * si.w[0] * t6 + (float(1) / float(315)) * (float(2) * ab_ap * t15 * t14 + ap_ap * t13 * t14 - float(9) * t14 * (float(5) * t8 * t4 - ab_ap * t9 * t6 - float(5) * t0 * t3)) * si.w[3] * t14 - (float(1) / float(315)) * si.w[1] * t13 * t14;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-11) dt
// Operations: 68 +, 192 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i11_w3_f_and_grad(SegmentInput si, out vec3 grad) {
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
    foot0 = ap0 - ab_ap * t0 * ab0;
    foot1 = ap1 - ab_ap * t0 * ab1;
    foot2 = ap2 - ab_ap * t0 * ab2;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / r1;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = float(1) / r0;
    float t6 = t5 * t5;
    float t7 = t6 * t6;
    float t8 = t7 * t7;
    float t9 = t7 * t6;
    float t10 = float(1) / cross_cross;
    float t11 = t3 * t2;
    float t12 = float(5) * ab_ap * t9 * t5 + float(2) * (float(4) * (ab_ap * t6 * t5 + t2 * a_minus_b * t1 + float(2) * ab_ab * (a_minus_b * t1 + ab_ap * t5) * t10) * ab_ab * t10 + float(3) * t3 * a_minus_b * t1 + float(3) * ab_ap * t7 * t5) * ab_ab * t10 + float(5) * t11 * a_minus_b * t1;
    float t13 = float(35) * t4 * a_minus_b * t1 + float(35) * ab_ap * t8 * t5 + float(8) * ab_ab * t12 * t10;
    float t14 = ab_ap * t13 * t10 + float(35) * t8 * t5 - float(35) * t4 * t1;
    float t15 = float(1) / ab_ab;
    float t16 = t13 * ap_ap * t10 - float(9) * t12 * t10 - float(2) * ab_ap * t14 * t15;
    F = (float(1) / float(315)) * t13 * si.w[0] * t10 + (float(1) / float(315)) * t14 * t15 * si.w[1] - (float(1) / float(315)) * (float(2) * ab_ap * t16 * t15 + t14 * ap_ap * t15 + float(9) * (float(5) * t11 * t1 - float(5) * t9 * t5 - ab_ap * t12 * t10) * t15) * si.w[3] * t15 - (float(1) / float(315)) * t16 * si.w[2] * t15;
    float t17 = t8 * t6;
    float t18 = t4 * t2;
    float t19 = float(63) * ab_ap * t17 * t5 + float(63) * t18 * a_minus_b * t1 + float(2) * t13 * ab_ab * t10;
    float t20 = ab_ap * t19 * t10 + float(63) * t17 * t5 - float(63) * t18 * t1;
    float t21 = float(10) * ab_ap * t20 * t15 + float(11) * t13 * t10 - float(5) * ap_ap * t19 * t10;
    G_ap = (float(1) / float(693)) * si.w[0] * t19 * t10 + (float(1) / float(3465)) * (float(2) * ab_ap * t15 * t21 + float(11) * t14 * t15 - float(5) * ap_ap * t20 * t15) * si.w[3] * t15 + (float(1) / float(3465)) * si.w[2] * t15 * t21 + (float(1) / float(693)) * t20 * t15 * si.w[1];
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
    G_E = -(float(1) / float(3465)) * (float(3) * t16 * si.w[3] * t15 + float(315) * (si.w[2] + si.w[3] + si.w[0] + si.w[1]) * t26 - float(315) * t31 * si.w[0] - t13 * t10 * si.w[1] - float(2) * t14 * si.w[2] * t15) * t15;
  }
  float g_factor = -float(11) * length;
  f = length * F;
  grad[0] = -(ab0 * G_E - foot0 * G_ap) * g_factor;
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = -(ab2 * G_E - G_ap * foot2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-12) dt
// Operations: 36 +, 71 *, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i12_w0_f(SegmentInput si) {
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
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, ap_bp);
    float t2 = float(1) / cross_cross;
    float t3 = float(1) / ap_ap;
    float t4 = t3 * t3;
    float t5 = t4 * t4;
    float t6 = float(1) / bp_bp;
    float t7 = t6 * t6;
    float t8 = t4 * t3;
    float t9 = t7 * t6;
    float t10 = t7 * t7;
    float t11 = t5 * t3;
    float t12 = t10 * t6;
    F = (float(1) / float(1280)) * si.w[0] * t2 * (float(3) * ab_ab * t2 * (float(48) * t5 * ab_ap + float(7) * (float(5) * ab_ab * (float(2) * t4 * ab_ap + float(3) * (ab_ab * J2 + a_minus_b * t6 + t3 * ab_ap) * ab_ab * t2 + float(2) * a_minus_b * t7) * t2 + float(8) * t8 * ab_ap + float(8) * a_minus_b * t9) * ab_ab * t2 + float(48) * a_minus_b * t10) + float(128) * t11 * ab_ap + float(128) * a_minus_b * t12);
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-12) dt
// Operations: 45 +, 103 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i12_w0_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = atan(t1, ap_bp) * t2;
    float t3 = float(1) / cross_cross;
    float t4 = float(1) / ap_ap;
    float t5 = t4 * t4;
    float t6 = t5 * t4;
    float t7 = float(1) / bp_bp;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = t8 * t8;
    float t11 = t5 * t5;
    float t12 = t10 * t7;
    float t13 = t11 * t4;
    float t14 = float(3) * ab_ab * (float(7) * ab_ab * (float(8) * t6 * ab_ap + float(8) * a_minus_b * t9 + float(5) * ab_ab * t3 * (float(2) * t5 * ab_ap + float(3) * (a_minus_b * t7 + t4 * ab_ap + ab_ab * J2) * ab_ab * t3 + float(2) * a_minus_b * t8)) * t3 + float(48) * a_minus_b * t10 + float(48) * t11 * ab_ap) * t3 + float(128) * a_minus_b * t12 + float(128) * t13 * ab_ap;
    F = (float(1) / float(1280)) * si.w[0] * t3 * t14;
    float t15 = t6 * t6;
    float t16 = t9 * t9;
    G_ap = (float(1) / float(15360)) * si.w[0] * (float(11) * ab_ab * t3 * t14 + float(1280) * t15 * ab_ap + float(1280) * a_minus_b * t16) * t3;
    float t17 = float(1) / ab_ab;
    G_E = (float(1) / float(12)) * (t15 * si.w[0] - si.w[0] * t16) * t17;
  }
  float g_factor = -float(12) * length;
  f = F * length;
  grad[0] = (G_ap * foot0 - ab0 * G_E) * g_factor;
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = (G_ap * foot2 - ab2 * G_E) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-12) dt
// Operations: 39 +, 77 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i12_w1_f(SegmentInput si) {
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
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float ap_bp = bp1 * ap1 + bp2 * ap2 + bp0 * ap0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = atan(t0, ap_bp) * t1;
    float t2 = float(1) / cross_cross;
    float t3 = float(1) / ap_ap;
    float t4 = t3 * t3;
    float t5 = t4 * t4;
    float t6 = t5 * t3;
    float t7 = float(1) / bp_bp;
    float t8 = t7 * t7;
    float t9 = t8 * t8;
    float t10 = t4 * t3;
    float t11 = t8 * t7;
    float t12 = t9 * t7;
    float t13 = float(128) * ab_ap * t6 + float(3) * ab_ab * t2 * (float(48) * ab_ap * t5 + float(48) * a_minus_b * t9 + float(7) * ab_ab * t2 * (float(8) * ab_ap * t10 + float(8) * a_minus_b * t11 + float(5) * (float(2) * ab_ap * t4 + float(3) * ab_ab * t2 * (a_minus_b * t7 + J2 * ab_ab + ab_ap * t3) + float(2) * a_minus_b * t8) * ab_ab * t2)) + float(128) * a_minus_b * t12;
    F = (float(1) / float(1280)) * si.w[1] * (t2 * ab_ap * t13 + float(128) * t6 - float(128) * t12) / ab_ab + (float(1) / float(1280)) * t2 * si.w[0] * t13;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-12) dt
// Operations: 53 +, 121 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i12_w1_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = atan(t1, ap_bp) * t2;
    float t3 = float(1) / cross_cross;
    float t4 = float(1) / bp_bp;
    float t5 = t4 * t4;
    float t6 = t5 * t5;
    float t7 = float(1) / ap_ap;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = t5 * t4;
    float t11 = t8 * t8;
    float t12 = t6 * t4;
    float t13 = t11 * t7;
    float t14 = float(3) * ab_ab * (float(48) * t6 * a_minus_b + float(7) * ab_ab * t3 * (float(8) * t9 * ab_ap + float(5) * ab_ab * t3 * (float(2) * t8 * ab_ap + float(2) * t5 * a_minus_b + float(3) * (t4 * a_minus_b + ab_ab * J2 + t7 * ab_ap) * ab_ab * t3) + float(8) * t10 * a_minus_b) + float(48) * t11 * ab_ap) * t3 + float(128) * t12 * a_minus_b + float(128) * t13 * ab_ap;
    float t15 = float(1) / ab_ab;
    F = (float(1) / float(1280)) * t3 * t14 * si.w[0] + (float(1) / float(1280)) * si.w[1] * (t3 * t14 * ab_ap + float(128) * t13 - float(128) * t12) * t15;
    float t16 = t9 * t9;
    float t17 = t10 * t10;
    float t18 = float(11) * ab_ab * t3 * t14 + float(1280) * t17 * a_minus_b + float(1280) * t16 * ab_ap;
    G_ap = (float(1) / float(15360)) * si.w[1] * t15 * (float(1280) * t16 + t18 * t3 * ab_ap - float(1280) * t17) + (float(1) / float(15360)) * t18 * t3 * si.w[0];
    G_E = (float(1) / float(15360)) * t15 * (si.w[1] * t3 * t14 + float(1280) * t16 * si.w[0] - float(1280) * t17 * (si.w[1] + si.w[0]));
  }
  float g_factor = -float(12) * length;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_E - G_ap * foot0);
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = g_factor * (G_ap * foot2 - ab2 * G_E);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-12) dt
// Operations: 42 +, 89 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i12_w2_f(SegmentInput si) {
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
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ab_bp = ab1 * bp1 + bp0 * ab0 + ab2 * bp2;
  float ap_bp = bp0 * ap0 + ap1 * bp1 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, ap_bp);
    float t2 = float(1) / ab_ab;
    float t3 = float(1) / cross_cross;
    float t4 = float(1) / bp_bp;
    float t5 = t4 * t4;
    float t6 = t5 * t4;
    float t7 = float(1) / ap_ap;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = t8 * t8;
    float t11 = t5 * t5;
    float t12 = float(7) * ab_ab * t3 * (float(8) * a_minus_b * t6 + float(8) * ab_ap * t9 + float(5) * ab_ab * (float(2) * a_minus_b * t5 + float(2) * ab_ap * t8 + float(3) * ab_ab * t3 * (ab_ap * t7 + a_minus_b * t4 + J2 * ab_ab)) * t3) + float(48) * ab_ap * t10 + float(48) * a_minus_b * t11;
    float t13 = t11 * t4;
    float t14 = t10 * t7;
    float t15 = float(128) * a_minus_b * t13 + float(3) * ab_ab * t12 * t3 + float(128) * ab_ap * t14;
    float t16 = t15 * t3 * ab_ap + float(128) * t14 - float(128) * t13;
    F = (float(1) / float(3840)) * si.w[2] * t2 * (float(10) * t12 * t3 + float(6) * t2 * ab_ap * t16 - float(3) * t15 * t3 * ap_ap) + (float(1) / float(1280)) * t2 * si.w[1] * t16 + (float(1) / float(1280)) * t15 * t3 * si.w[0];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-12) dt
// Operations: 61 +, 145 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i12_w2_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
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
    foot2 = ap2 - t0 * ab2 * ab_ap;
  }
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = ab1 * bp1 + ab0 * bp0 + ab2 * bp2;
  float ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, ap_bp);
    float t3 = float(1) / ab_ab;
    float t4 = float(1) / bp_bp;
    float t5 = t4 * t4;
    float t6 = t5 * t5;
    float t7 = t5 * t4;
    float t8 = float(1) / cross_cross;
    float t9 = float(1) / ap_ap;
    float t10 = t9 * t9;
    float t11 = t10 * t9;
    float t12 = t10 * t10;
    float t13 = float(48) * t6 * a_minus_b + float(7) * ab_ab * (float(8) * t7 * a_minus_b + float(5) * ab_ab * t8 * (float(2) * t5 * a_minus_b + float(3) * ab_ab * t8 * (ab_ap * t9 + t4 * a_minus_b + ab_ab * J2) + float(2) * ab_ap * t10) + float(8) * ab_ap * t11) * t8 + float(48) * ab_ap * t12;
    float t14 = t6 * t4;
    float t15 = t12 * t9;
    float t16 = float(3) * ab_ab * t13 * t8 + float(128) * ab_ap * t15 + float(128) * t14 * a_minus_b;
    float t17 = float(128) * t14 - float(128) * t15 - t8 * ab_ap * t16;
    F = (float(1) / float(3840)) * si.w[2] * t3 * (float(10) * t13 * t8 - float(6) * t17 * t3 * ab_ap - float(3) * t8 * ap_ap * t16) + (float(1) / float(1280)) * t8 * si.w[0] * t16 - (float(1) / float(1280)) * t17 * t3 * si.w[1];
    float t18 = t7 * t7;
    float t19 = t11 * t11;
    float t20 = float(11) * ab_ab * t8 * t16 + float(1280) * t18 * a_minus_b + float(1280) * ab_ap * t19;
    float t21 = float(1280) * t18 - float(1280) * t19 - t20 * t8 * ab_ap;
    G_ap = (float(1) / float(15360)) * t20 * t8 * si.w[0] - (float(1) / float(15360)) * si.w[2] * t3 * (t20 * t8 * ap_ap + float(2) * t3 * ab_ap * t21 - float(12) * t8 * t16) - (float(1) / float(15360)) * t3 * t21 * si.w[1];
    G_E = (float(1) / float(15360)) * t3 * (t8 * si.w[1] * t16 + float(1280) * si.w[0] * t19 - float(2) * si.w[2] * t17 * t3 - float(1280) * (si.w[2] + si.w[0] + si.w[1]) * t18);
  }
  float g_factor = -float(12) * length;
  f = length * F;
  grad[0] = g_factor * (G_ap * foot0 - ab0 * G_E);
  grad[1] = -(ab1 * G_E - G_ap * foot1) * g_factor;
  grad[2] = -g_factor * (ab2 * G_E - G_ap * foot2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-12) dt
// Operations: 47 +, 104 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i12_w3_f(SegmentInput si) {
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
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  float ap_bp = ap1 * bp1 + ap0 * bp0 + bp2 * ap2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, ap_bp);
    float t2 = float(1) / ap_ap;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = float(1) / bp_bp;
    float t6 = t5 * t5;
    float t7 = float(1) / cross_cross;
    float t8 = t6 * t5;
    float t9 = t3 * t2;
    float t10 = t6 * t6;
    float t11 = float(48) * t4 * ab_ap + float(7) * (float(5) * (float(2) * t6 * a_minus_b + float(3) * (J2 * ab_ab + t2 * ab_ap + t5 * a_minus_b) * ab_ab * t7 + float(2) * t3 * ab_ap) * ab_ab * t7 + float(8) * t8 * a_minus_b + float(8) * t9 * ab_ap) * ab_ab * t7 + float(48) * t10 * a_minus_b;
    float t12 = t10 * t5;
    float t13 = t4 * t2;
    float t14 = float(128) * t13 * ab_ap + float(128) * t12 * a_minus_b + float(3) * t11 * ab_ab * t7;
    float t15 = float(128) * t12 - t14 * t7 * ab_ap - float(128) * t13;
    float t16 = float(1) / ab_ab;
    float t17 = float(10) * t11 * t7 - float(6) * t15 * t16 * ab_ap - float(3) * t14 * ap_ap * t7;
    F = (float(1) / float(3840)) * si.w[2] * t17 * t16 + (float(1) / float(3840)) * (float(3) * ap_ap * t15 * t16 + float(2) * t17 * t16 * ab_ap - float(10) * (float(48) * t10 - t11 * t7 * ab_ap - float(48) * t4) * t16) * si.w[3] * t16 + (float(1) / float(1280)) * t14 * si.w[0] * t7 - (float(1) / float(1280)) * t15 * t16 * si.w[1];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-12) dt
// Operations: 71 +, 172 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i12_w3_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float ap_bp = bp1 * ap1 + bp2 * ap2 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = atan(t1, ap_bp) * t2;
    float t3 = float(1) / ab_ab;
    float t4 = float(1) / cross_cross;
    float t5 = float(1) / bp_bp;
    float t6 = t5 * t5;
    float t7 = t6 * t6;
    float t8 = float(1) / ap_ap;
    float t9 = t8 * t8;
    float t10 = t9 * t8;
    float t11 = t6 * t5;
    float t12 = t9 * t9;
    float t13 = float(48) * t7 * a_minus_b + float(7) * (float(8) * t10 * ab_ap + float(8) * t11 * a_minus_b + float(5) * (float(2) * t6 * a_minus_b + float(3) * ab_ab * (J2 * ab_ab + t8 * ab_ap + t5 * a_minus_b) * t4 + float(2) * t9 * ab_ap) * ab_ab * t4) * ab_ab * t4 + float(48) * t12 * ab_ap;
    float t14 = t7 * t5;
    float t15 = t12 * t8;
    float t16 = float(128) * t14 * a_minus_b + float(128) * t15 * ab_ap + float(3) * ab_ab * t4 * t13;
    float t17 = float(128) * t14 - float(128) * t15 - t16 * t4 * ab_ap;
    float t18 = float(10) * t4 * t13 - float(6) * t3 * t17 * ab_ap - float(3) * t16 * ap_ap * t4;
    F = (float(1) / float(3840)) * si.w[2] * t3 * t18 + (float(1) / float(3840)) * si.w[3] * t3 * (float(2) * t3 * t18 * ab_ap + float(3) * ap_ap * t3 * t17 - float(10) * t3 * (float(48) * t7 - t4 * ab_ap * t13 - float(48) * t12)) + (float(1) / float(1280)) * t16 * si.w[0] * t4 - (float(1) / float(1280)) * t3 * t17 * si.w[1];
    float t19 = t10 * t10;
    float t20 = t11 * t11;
    float t21 = float(11) * t16 * ab_ab * t4 + float(1280) * t19 * ab_ap + float(1280) * t20 * a_minus_b;
    float t22 = float(1280) * t20 - t21 * t4 * ab_ap - float(1280) * t19;
    float t23 = ap_ap * t21 * t4 + float(2) * t22 * t3 * ab_ap - float(12) * t16 * t4;
    G_ap = (float(1) / float(15360)) * t21 * si.w[0] * t4 - (float(1) / float(15360)) * (float(12) * t3 * t17 + float(2) * t23 * t3 * ab_ap - t22 * ap_ap * t3) * si.w[3] * t3 - (float(1) / float(15360)) * si.w[2] * t23 * t3 - (float(1) / float(15360)) * t22 * t3 * si.w[1];
    G_E = (float(1) / float(15360)) * (t16 * t4 * si.w[1] + float(1280) * t19 * si.w[0] + si.w[3] * t3 * t18 - float(1280) * t20 * (si.w[2] + si.w[3] + si.w[0] + si.w[1]) - float(2) * si.w[2] * t3 * t17) * t3;
  }
  float g_factor = -float(12) * length;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_E - G_ap * foot0);
  grad[1] = g_factor * (foot1 * G_ap - ab1 * G_E);
  grad[2] = g_factor * (foot2 * G_ap - ab2 * G_E);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-13) dt
// Operations: 35 +, 83 *, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i13_w0_f(SegmentInput si) {
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
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / r1;
    float t1 = t0 * t0;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t1;
    float t5 = float(1) / cross_cross;
    float t6 = t2 * t1;
    float t7 = float(1) / r0;
    float t8 = t7 * t7;
    float t9 = t8 * t8;
    float t10 = t9 * t8;
    float t11 = t9 * t9;
    float t12 = t11 * t8;
    F = (float(1) / float(693)) * si.w[0] * (float(63) * a_minus_b * t4 * t0 + float(2) * ab_ab * (float(8) * ab_ab * t5 * (float(5) * a_minus_b * t6 * t0 + float(5) * ab_ap * t7 * t10 + float(2) * ab_ab * t5 * (float(4) * (ab_ap * t7 * t8 + a_minus_b * t1 * t0 + float(2) * ab_ab * t5 * (a_minus_b * t0 + ab_ap * t7)) * ab_ab * t5 + float(3) * a_minus_b * t2 * t0 + float(3) * ab_ap * t7 * t9)) + float(35) * a_minus_b * t3 * t0 + float(35) * ab_ap * t7 * t11) * t5 + float(63) * ab_ap * t7 * t12) * t5;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-13) dt
// Operations: 44 +, 127 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i13_w0_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / r0;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = t4 * t2;
    float t6 = float(1) / r1;
    float t7 = t6 * t6;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = float(1) / cross_cross;
    float t11 = t3 * t2;
    float t12 = t8 * t8;
    float t13 = t12 * t7;
    float t14 = float(63) * ab_ap * t1 * t5 + float(2) * (float(8) * (float(5) * t6 * t9 * a_minus_b + float(2) * (float(3) * ab_ap * t1 * t3 + float(3) * t6 * t8 * a_minus_b + float(4) * (float(2) * (t6 * a_minus_b + ab_ap * t1) * ab_ab * t10 + t6 * t7 * a_minus_b + ab_ap * t1 * t2) * ab_ab * t10) * ab_ab * t10 + float(5) * ab_ap * t1 * t11) * ab_ab * t10 + float(35) * ab_ap * t1 * t4 + float(35) * t6 * t12 * a_minus_b) * ab_ab * t10 + float(63) * t6 * t13 * a_minus_b;
    F = (float(1) / float(693)) * si.w[0] * t14 * t10;
    float t15 = t11 * t11;
    float t16 = t9 * t9;
    G_ap = (float(1) / float(3003)) * si.w[0] * t10 * (float(4) * ab_ab * t14 * t10 + float(231) * ab_ap * t1 * t15 + float(231) * t6 * t16 * a_minus_b);
    float t17 = float(1) / ab_ab;
    float t18 = t1 * t1;
    float t19 = t18 * t1;
    float t20 = t19 * t19;
    float t21 = t20 * t20;
    float t22 = t21 * t1;
    float t23 = t6 * t6;
    float t24 = t23 * t6;
    float t25 = t24 * t24;
    float t26 = t25 * t25;
    float t27 = t26 * t6;
    G_E = (float(1) / float(13)) * t17 * (si.w[0] * t22 - t27 * si.w[0]);
  }
  float g_factor = -float(13) * length;
  f = length * F;
  grad[0] = -(G_E * ab0 - foot0 * G_ap) * g_factor;
  grad[1] = -(G_E * ab1 - foot1 * G_ap) * g_factor;
  grad[2] = -(G_E * ab2 - foot2 * G_ap) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-13) dt
// Operations: 38 +, 91 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i13_w1_f(SegmentInput si) {
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
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / cross_cross;
    float t1 = float(1) / r0;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = t4 * t2;
    float t6 = float(1) / r1;
    float t7 = t6 * t6;
    float t8 = t7 * t7;
    float t9 = t8 * t8;
    float t10 = t9 * t7;
    float t11 = t3 * t2;
    float t12 = t8 * t7;
    float t13 = float(63) * t1 * ab_ap * t5 + float(63) * a_minus_b * t10 * t6 + float(2) * ab_ab * t0 * (float(35) * t1 * ab_ap * t4 + float(35) * a_minus_b * t9 * t6 + float(8) * ab_ab * (float(5) * t1 * ab_ap * t11 + float(2) * ab_ab * t0 * (float(4) * ab_ab * t0 * (float(2) * ab_ab * t0 * (t1 * ab_ap + a_minus_b * t6) + a_minus_b * t7 * t6 + t1 * ab_ap * t2) + float(3) * t1 * ab_ap * t3 + float(3) * a_minus_b * t8 * t6) + float(5) * a_minus_b * t12 * t6) * t0);
    F = (float(1) / float(693)) * (t0 * ab_ap * t13 + float(63) * t1 * t5 - float(63) * t10 * t6) * si.w[1] / ab_ab + (float(1) / float(693)) * t0 * si.w[0] * t13;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-13) dt
// Operations: 52 +, 149 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i13_w1_f_and_grad(SegmentInput si, out vec3 grad) {
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
    foot2 = ap2 - t0 * ab2 * ab_ap;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab1 * bp1 + ab2 * bp2 + ab0 * bp0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / ab_ab;
    float t2 = float(1) / cross_cross;
    float t3 = float(1) / r0;
    float t4 = t3 * t3;
    float t5 = t4 * t4;
    float t6 = t5 * t5;
    float t7 = t6 * t4;
    float t8 = float(1) / r1;
    float t9 = t8 * t8;
    float t10 = t9 * t9;
    float t11 = t10 * t10;
    float t12 = t11 * t9;
    float t13 = t5 * t4;
    float t14 = t10 * t9;
    float t15 = float(63) * t3 * ab_ap * t7 + float(63) * t8 * t12 * a_minus_b + float(2) * ab_ab * (float(35) * t3 * ab_ap * t6 + float(35) * t8 * t11 * a_minus_b + float(8) * ab_ab * t2 * (float(5) * t3 * ab_ap * t13 + float(5) * t8 * t14 * a_minus_b + float(2) * ab_ab * t2 * (float(3) * t3 * ab_ap * t5 + float(4) * ab_ab * t2 * (t8 * t9 * a_minus_b + float(2) * ab_ab * t2 * (t3 * ab_ap + t8 * a_minus_b) + t3 * ab_ap * t4) + float(3) * t8 * t10 * a_minus_b))) * t2;
    F = (float(1) / float(693)) * t1 * (t2 * t15 * ab_ap + float(63) * t3 * t7 - float(63) * t8 * t12) * si.w[1] + (float(1) / float(693)) * t2 * t15 * si.w[0];
    float t16 = t14 * t14;
    float t17 = t13 * t13;
    float t18 = float(4) * ab_ab * t2 * t15 + float(231) * t8 * t16 * a_minus_b + float(231) * t3 * ab_ap * t17;
    G_ap = (float(1) / float(3003)) * t2 * t18 * si.w[0] - (float(1) / float(3003)) * t1 * (float(231) * t8 * t16 - float(231) * t3 * t17 - t2 * ab_ap * t18) * si.w[1];
    float t19 = t3 * t3;
    float t20 = t19 * t3;
    float t21 = t20 * t20;
    float t22 = t21 * t21;
    float t23 = t22 * t3;
    float t24 = t8 * t8;
    float t25 = t24 * t8;
    float t26 = t25 * t25;
    float t27 = t26 * t26;
    float t28 = t27 * t8;
    G_E = (float(1) / float(9009)) * t1 * (t2 * t15 * si.w[1] + float(693) * t23 * si.w[0] - float(693) * t28 * (si.w[0] + si.w[1]));
  }
  float g_factor = -float(13) * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_E - G_ap * foot0);
  grad[1] = g_factor * (G_ap * foot1 - ab1 * G_E);
  grad[2] = -g_factor * (ab2 * G_E - foot2 * G_ap);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-13) dt
// Operations: 41 +, 103 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i13_w2_f(SegmentInput si) {
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
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / r0;
    float t1 = t0 * t0;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t1;
    float t5 = float(1) / cross_cross;
    float t6 = float(1) / r1;
    float t7 = t6 * t6;
    float t8 = t7 * t7;
    float t9 = t8 * t8;
    float t10 = t2 * t1;
    float t11 = t8 * t7;
    float t12 = float(35) * t0 * ab_ap * t3 + float(35) * t9 * t6 * a_minus_b + float(8) * t5 * (float(5) * t0 * ab_ap * t10 + float(5) * t11 * t6 * a_minus_b + float(2) * t5 * (float(3) * t8 * t6 * a_minus_b + float(3) * t0 * ab_ap * t2 + float(4) * t5 * (float(2) * t5 * (t0 * ab_ap + t6 * a_minus_b) * ab_ab + t0 * ab_ap * t1 + t7 * t6 * a_minus_b) * ab_ab) * ab_ab) * ab_ab;
    float t13 = t9 * t7;
    float t14 = float(63) * t0 * ab_ap * t4 + float(2) * t5 * t12 * ab_ab + float(63) * t13 * t6 * a_minus_b;
    float t15 = float(63) * t0 * t4 + t5 * ab_ap * t14 - float(63) * t13 * t6;
    float t16 = float(1) / ab_ab;
    F = (float(1) / float(693)) * t15 * si.w[1] * t16 + (float(1) / float(693)) * t5 * si.w[0] * t14 - (float(1) / float(3465)) * (float(5) * t5 * ap_ap * t14 - float(10) * t15 * ab_ap * t16 - float(11) * t5 * t12) * si.w[2] * t16;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-13) dt
// Operations: 60 +, 174 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i13_w2_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = ab0 * bp0 + bp1 * ab1 + bp2 * ab2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / cross_cross;
    float t2 = float(1) / r0;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = t4 * t4;
    float t6 = t5 * t3;
    float t7 = float(1) / r1;
    float t8 = t7 * t7;
    float t9 = t8 * t8;
    float t10 = t9 * t9;
    float t11 = t10 * t8;
    float t12 = t9 * t8;
    float t13 = t4 * t3;
    float t14 = float(35) * ab_ap * t5 * t2 + float(8) * t1 * (float(2) * t1 * (float(4) * t1 * (t7 * t8 * a_minus_b + ab_ap * t3 * t2 + float(2) * t1 * (t7 * a_minus_b + ab_ap * t2) * ab_ab) * ab_ab + float(3) * ab_ap * t4 * t2 + float(3) * t7 * t9 * a_minus_b) * ab_ab + float(5) * t7 * t12 * a_minus_b + float(5) * ab_ap * t13 * t2) * ab_ab + float(35) * t7 * t10 * a_minus_b;
    float t15 = float(63) * ab_ap * t6 * t2 + float(63) * t7 * t11 * a_minus_b + float(2) * t1 * t14 * ab_ab;
    float t16 = float(63) * t6 * t2 + t1 * ab_ap * t15 - float(63) * t7 * t11;
    float t17 = float(1) / ab_ab;
    F = (float(1) / float(693)) * t1 * si.w[0] * t15 + (float(1) / float(693)) * t16 * si.w[1] * t17 - (float(1) / float(3465)) * si.w[2] * (float(5) * t1 * ap_ap * t15 - float(10) * ab_ap * t16 * t17 - float(11) * t1 * t14) * t17;
    float t18 = t12 * t12;
    float t19 = t13 * t13;
    float t20 = float(231) * t7 * t18 * a_minus_b + float(231) * ab_ap * t19 * t2 + float(4) * t1 * t15 * ab_ab;
    float t21 = float(231) * t7 * t18 - t20 * t1 * ab_ap - float(231) * t19 * t2;
    G_ap = (float(1) / float(9009)) * si.w[2] * (float(13) * t1 * t15 - float(6) * ab_ap * t17 * t21 - float(3) * t20 * t1 * ap_ap) * t17 + (float(1) / float(3003)) * t20 * t1 * si.w[0] - (float(1) / float(3003)) * si.w[1] * t17 * t21;
    float t22 = t7 * t7;
    float t23 = t22 * t7;
    float t24 = t23 * t23;
    float t25 = t24 * t24;
    float t26 = t25 * t7;
    float t27 = t2 * t2;
    float t28 = t27 * t2;
    float t29 = t28 * t28;
    float t30 = t29 * t29;
    float t31 = t30 * t2;
    G_E = -(float(1) / float(9009)) * (float(693) * t26 * (si.w[0] + si.w[1] + si.w[2]) - float(2) * t16 * si.w[2] * t17 - float(693) * si.w[0] * t31 - t1 * si.w[1] * t15) * t17;
  }
  float g_factor = -float(13) * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = -(G_E * ab1 - foot1 * G_ap) * g_factor;
  grad[2] = -(G_E * ab2 - foot2 * G_ap) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-13) dt
// Operations: 46 +, 120 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i13_w3_f(SegmentInput si) {
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
  float ab_bp = ab2 * bp2 + bp0 * ab0 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / cross_cross;
    float t1 = float(1) / r0;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t2;
    float t5 = float(1) / r1;
    float t6 = t5 * t5;
    float t7 = t6 * t6;
    float t8 = t7 * t6;
    float t9 = t3 * t3;
    float t10 = t7 * t7;
    float t11 = float(8) * ab_ab * t0 * (float(5) * t1 * ab_ap * t4 + float(5) * a_minus_b * t8 * t5 + float(2) * (float(3) * a_minus_b * t7 * t5 + float(3) * t1 * ab_ap * t3 + float(4) * ab_ab * t0 * (float(2) * ab_ab * (t1 * ab_ap + a_minus_b * t5) * t0 + t1 * ab_ap * t2 + a_minus_b * t6 * t5)) * ab_ab * t0) + float(35) * t1 * ab_ap * t9 + float(35) * a_minus_b * t10 * t5;
    float t12 = t9 * t2;
    float t13 = t10 * t6;
    float t14 = float(2) * t11 * ab_ab * t0 + float(63) * t1 * ab_ap * t12 + float(63) * a_minus_b * t13 * t5;
    float t15 = float(63) * t13 * t5 - t0 * ab_ap * t14 - float(63) * t1 * t12;
    float t16 = float(1) / ab_ab;
    float t17 = float(10) * t15 * t16 * ab_ap + float(5) * t0 * t14 * ap_ap - float(11) * t11 * t0;
    F = (float(1) / float(693)) * si.w[0] * t0 * t14 - (float(1) / float(693)) * t15 * t16 * si.w[1] - (float(1) / float(3465)) * t16 * t17 * si.w[2] - (float(1) / float(3465)) * (float(2) * t16 * t17 * ab_ap + float(11) * (float(35) * t10 * t5 - t11 * t0 * ab_ap - float(35) * t1 * t9) * t16 - float(5) * t15 * t16 * ap_ap) * si.w[3] * t16;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-13) dt
// Operations: 70 +, 206 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i13_w3_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ab_bp = ab2 * bp2 + ab1 * bp1 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / cross_cross;
    float t2 = float(1) / r1;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = t4 * t4;
    float t6 = t5 * t3;
    float t7 = float(1) / r0;
    float t8 = t7 * t7;
    float t9 = t8 * t8;
    float t10 = t9 * t8;
    float t11 = t4 * t3;
    float t12 = t9 * t9;
    float t13 = float(8) * (float(5) * t10 * t7 * ab_ap + float(5) * t2 * t11 * a_minus_b + float(2) * ab_ab * t1 * (float(4) * (float(2) * ab_ab * t1 * (t7 * ab_ap + t2 * a_minus_b) + t8 * t7 * ab_ap + t2 * t3 * a_minus_b) * ab_ab * t1 + float(3) * t2 * t4 * a_minus_b + float(3) * t9 * t7 * ab_ap)) * ab_ab * t1 + float(35) * t2 * t5 * a_minus_b + float(35) * t12 * t7 * ab_ap;
    float t14 = t12 * t8;
    float t15 = float(63) * t2 * t6 * a_minus_b + float(2) * ab_ab * t13 * t1 + float(63) * t14 * t7 * ab_ap;
    float t16 = float(1) / ab_ab;
    float t17 = float(63) * t2 * t6 - float(63) * t14 * t7 - t1 * ab_ap * t15;
    float t18 = float(11) * t13 * t1 - float(5) * ap_ap * t1 * t15 - float(10) * t16 * t17 * ab_ap;
    F = (float(1) / float(693)) * si.w[0] * t1 * t15 + (float(1) / float(3465)) * t16 * si.w[2] * t18 + (float(1) / float(3465)) * si.w[3] * t16 * (float(5) * ap_ap * t16 * t17 + float(2) * t16 * ab_ap * t18 + float(11) * t16 * (t13 * t1 * ab_ap + float(35) * t12 * t7 - float(35) * t2 * t5)) - (float(1) / float(693)) * t16 * si.w[1] * t17;
    float t19 = t10 * t10;
    float t20 = t11 * t11;
    float t21 = float(4) * ab_ab * t1 * t15 + float(231) * t19 * t7 * ab_ap + float(231) * t2 * t20 * a_minus_b;
    float t22 = float(231) * t19 * t7 + t1 * ab_ap * t21 - float(231) * t2 * t20;
    float t23 = float(13) * t1 * t15 + float(6) * t22 * t16 * ab_ap - float(3) * ap_ap * t1 * t21;
    G_ap = (float(1) / float(3003)) * t22 * t16 * si.w[1] + (float(1) / float(9009)) * si.w[3] * t16 * (float(2) * t16 * t23 * ab_ap - float(13) * t16 * t17 - float(3) * ap_ap * t22 * t16) + (float(1) / float(3003)) * si.w[0] * t1 * t21 + (float(1) / float(9009)) * t16 * t23 * si.w[2];
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
    G_E = (float(1) / float(45045)) * t16 * (float(3) * si.w[3] * t16 * t18 + float(5) * si.w[1] * t1 * t15 + float(3465) * si.w[0] * t28 - float(10) * t16 * t17 * si.w[2] - float(3465) * (si.w[3] + si.w[0] + si.w[1] + si.w[2]) * t33);
  }
  float g_factor = -float(13) * length;
  f = F * length;
  grad[0] = (G_ap * foot0 - ab0 * G_E) * g_factor;
  grad[1] = -g_factor * (ab1 * G_E - foot1 * G_ap);
  grad[2] = -(ab2 * G_E - G_ap * foot2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-14) dt
// Operations: 38 +, 80 *, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i14_w0_f(SegmentInput si) {
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
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, ap_bp);
    float t2 = float(1) / cross_cross;
    float t3 = float(1) / ap_ap;
    float t4 = t3 * t3;
    float t5 = t4 * t4;
    float t6 = t4 * t3;
    float t7 = float(1) / bp_bp;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = t8 * t8;
    float t11 = t5 * t3;
    float t12 = t10 * t7;
    float t13 = t6 * t6;
    float t14 = t9 * t9;
    F = (float(1) / float(15360)) * t2 * (float(11) * (float(3) * t2 * (float(48) * ab_ap * t5 + float(7) * t2 * (float(8) * ab_ap * t6 + float(5) * (float(2) * ab_ap * t4 + float(3) * t2 * (ab_ab * J2 + a_minus_b * t7 + ab_ap * t3) * ab_ab + float(2) * a_minus_b * t8) * t2 * ab_ab + float(8) * a_minus_b * t9) * ab_ab + float(48) * a_minus_b * t10) * ab_ab + float(128) * ab_ap * t11 + float(128) * a_minus_b * t12) * t2 * ab_ab + float(1280) * ab_ap * t13 + float(1280) * a_minus_b * t14) * si.w[0];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-14) dt
// Operations: 47 +, 112 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i14_w0_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float ap_ap = ap0 * ap0 + ap2 * ap2 + ap1 * ap1;
  float plain_cross0 = ab1 * ap2 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ap2 * ab0;
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
    foot0 = ap0 - ab_ap * ab0 * t0;
    foot1 = ap1 - ab_ap * ab1 * t0;
    foot2 = ap2 - ab_ap * t0 * ab2;
  }
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = ab1 * bp1 + bp2 * ab2 + ab0 * bp0;
  float ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = atan(t1, ap_bp) * t2;
    float t3 = float(1) / bp_bp;
    float t4 = t3 * t3;
    float t5 = t4 * t3;
    float t6 = t5 * t5;
    float t7 = float(1) / cross_cross;
    float t8 = t4 * t4;
    float t9 = t8 * t3;
    float t10 = float(1) / ap_ap;
    float t11 = t10 * t10;
    float t12 = t11 * t10;
    float t13 = t11 * t11;
    float t14 = t13 * t10;
    float t15 = t12 * t12;
    float t16 = float(1280) * t6 * a_minus_b + float(11) * ab_ab * t7 * (float(128) * t9 * a_minus_b + float(3) * (float(48) * t8 * a_minus_b + float(7) * (float(5) * (float(3) * (t3 * a_minus_b + J2 * ab_ab + ab_ap * t10) * ab_ab * t7 + float(2) * ab_ap * t11 + float(2) * t4 * a_minus_b) * ab_ab * t7 + float(8) * ab_ap * t12 + float(8) * t5 * a_minus_b) * ab_ab * t7 + float(48) * ab_ap * t13) * ab_ab * t7 + float(128) * ab_ap * t14) + float(1280) * ab_ap * t15;
    F = (float(1) / float(15360)) * t16 * si.w[0] * t7;
    float t17 = t6 * t3;
    float t18 = t15 * t10;
    G_ap = (float(1) / float(215040)) * (float(15360) * t17 * a_minus_b + float(13) * t16 * ab_ab * t7 + float(15360) * ab_ap * t18) * si.w[0] * t7;
    float t19 = float(1) / ab_ab;
    G_E = -(float(1) / float(14)) * (t17 * si.w[0] - t18 * si.w[0]) * t19;
  }
  float g_factor = -float(14) * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = -g_factor * (ab1 * G_E - foot1 * G_ap);
  grad[2] = (G_ap * foot2 - ab2 * G_E) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-14) dt
// Operations: 41 +, 86 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i14_w1_f(SegmentInput si) {
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
  float ab_ap = ab0 * ap0 + ab1 * ap1 + ap2 * ab2;
  float ap_ap = ap2 * ap2 + ap0 * ap0 + ap1 * ap1;
  float plain_cross0 = ab1 * ap2 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
  float plain_cross2 = ab0 * ap1 - ab1 * ap0;
  float plain_cross_cross = plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  float ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, ap_bp);
    float t2 = float(1) / ap_ap;
    float t3 = t2 * t2;
    float t4 = t3 * t2;
    float t5 = t4 * t4;
    float t6 = float(1) / cross_cross;
    float t7 = float(1) / bp_bp;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = t9 * t9;
    float t11 = t8 * t8;
    float t12 = t3 * t3;
    float t13 = t11 * t7;
    float t14 = t12 * t2;
    float t15 = float(1280) * t10 * a_minus_b + float(11) * t6 * (float(3) * t6 * (float(48) * t11 * a_minus_b + float(7) * (float(5) * t6 * ab_ab * (float(3) * t6 * (t7 * a_minus_b + ab_ap * t2 + J2 * ab_ab) * ab_ab + float(2) * ab_ap * t3 + float(2) * t8 * a_minus_b) + float(8) * t9 * a_minus_b + float(8) * ab_ap * t4) * t6 * ab_ab + float(48) * ab_ap * t12) * ab_ab + float(128) * t13 * a_minus_b + float(128) * ab_ap * t14) * ab_ab + float(1280) * ab_ap * t5;
    F = (float(1) / float(15360)) * si.w[1] * (float(1280) * t5 + t6 * ab_ap * t15 - float(1280) * t10) / ab_ab + (float(1) / float(15360)) * t6 * si.w[0] * t15;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-14) dt
// Operations: 55 +, 130 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i14_w1_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float ab_bp = ab1 * bp1 + ab0 * bp0 + bp2 * ab2;
  float ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, ap_bp);
    float t3 = float(1) / bp_bp;
    float t4 = t3 * t3;
    float t5 = t4 * t4;
    float t6 = t5 * t3;
    float t7 = float(1) / ap_ap;
    float t8 = t7 * t7;
    float t9 = t8 * t8;
    float t10 = t9 * t7;
    float t11 = float(1) / cross_cross;
    float t12 = t8 * t7;
    float t13 = t4 * t3;
    float t14 = t13 * t13;
    float t15 = t12 * t12;
    float t16 = float(11) * (float(128) * t6 * a_minus_b + float(128) * ab_ap * t10 + float(3) * t11 * (float(48) * t5 * a_minus_b + float(7) * t11 * (float(5) * (float(3) * t11 * (ab_ap * t7 + t3 * a_minus_b + J2 * ab_ab) * ab_ab + float(2) * t4 * a_minus_b + float(2) * ab_ap * t8) * t11 * ab_ab + float(8) * ab_ap * t12 + float(8) * t13 * a_minus_b) * ab_ab + float(48) * ab_ap * t9) * ab_ab) * t11 * ab_ab + float(1280) * t14 * a_minus_b + float(1280) * ab_ap * t15;
    float t17 = float(1) / ab_ab;
    F = (float(1) / float(15360)) * t16 * t11 * si.w[0] + (float(1) / float(15360)) * (t16 * t11 * ab_ap + float(1280) * t15 - float(1280) * t14) * si.w[1] * t17;
    float t18 = t14 * t3;
    float t19 = t15 * t7;
    float t20 = float(13) * t16 * t11 * ab_ab + float(15360) * t18 * a_minus_b + float(15360) * ab_ap * t19;
    G_ap = (float(1) / float(215040)) * t11 * si.w[0] * t20 + (float(1) / float(215040)) * (float(15360) * t19 + t11 * ab_ap * t20 - float(15360) * t18) * si.w[1] * t17;
    G_E = -(float(1) / float(215040)) * t17 * (float(15360) * t18 * (si.w[0] + si.w[1]) - t16 * t11 * si.w[1] - float(15360) * si.w[0] * t19);
  }
  float g_factor = -float(14) * length;
  f = length * F;
  grad[0] = (foot0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = -(ab1 * G_E - foot1 * G_ap) * g_factor;
  grad[2] = (foot2 * G_ap - G_E * ab2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-14) dt
// Operations: 44 +, 97 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i14_w2_f(SegmentInput si) {
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
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = bp2 * ab2 + bp0 * ab0 + bp1 * ab1;
  float ap_bp = ap2 * bp2 + ap1 * bp1 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = atan(t0, ap_bp) * t1;
    float t2 = float(1) / bp_bp;
    float t3 = t2 * t2;
    float t4 = t3 * t2;
    float t5 = float(1) / ap_ap;
    float t6 = t5 * t5;
    float t7 = t6 * t5;
    float t8 = float(1) / cross_cross;
    float t9 = t3 * t3;
    float t10 = t6 * t6;
    float t11 = t9 * t2;
    float t12 = t10 * t5;
    float t13 = float(3) * (float(7) * (float(8) * t4 * a_minus_b + float(8) * ab_ap * t7 + float(5) * (float(3) * (J2 * ab_ab + ab_ap * t5 + t2 * a_minus_b) * ab_ab * t8 + float(2) * t3 * a_minus_b + float(2) * ab_ap * t6) * ab_ab * t8) * ab_ab * t8 + float(48) * t9 * a_minus_b + float(48) * ab_ap * t10) * ab_ab * t8 + float(128) * t11 * a_minus_b + float(128) * ab_ap * t12;
    float t14 = t4 * t4;
    float t15 = t7 * t7;
    float t16 = float(11) * t13 * ab_ab * t8 + float(1280) * t14 * a_minus_b + float(1280) * ab_ap * t15;
    float t17 = float(1) / ab_ab;
    float t18 = float(1280) * t14 - ab_ap * t16 * t8 - float(1280) * t15;
    F = (float(1) / float(15360)) * t16 * t8 * si.w[0] - (float(1) / float(15360)) * si.w[1] * t17 * t18 - (float(1) / float(15360)) * si.w[2] * t17 * (t16 * ap_ap * t8 + float(2) * ab_ap * t17 * t18 - float(12) * t13 * t8);
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-14) dt
// Operations: 63 +, 153 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i14_w2_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float ab_ap = ap2 * ab2 + ap0 * ab0 + ap1 * ab1;
  float ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
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
    foot0 = ap0 - ab_ap * ab0 * t0;
    foot1 = ap1 - ab_ap * ab1 * t0;
    foot2 = ap2 - ab_ap * t0 * ab2;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp1 * ab1 + bp0 * ab0 + bp2 * ab2;
  float ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, ap_bp);
    float t3 = float(1) / ab_ab;
    float t4 = float(1) / cross_cross;
    float t5 = float(1) / ap_ap;
    float t6 = t5 * t5;
    float t7 = t6 * t6;
    float t8 = t7 * t5;
    float t9 = float(1) / bp_bp;
    float t10 = t9 * t9;
    float t11 = t10 * t9;
    float t12 = t6 * t5;
    float t13 = t10 * t10;
    float t14 = t13 * t9;
    float t15 = float(128) * ab_ap * t8 + float(3) * t4 * (float(48) * ab_ap * t7 + float(7) * t4 * (float(8) * t11 * a_minus_b + float(8) * ab_ap * t12 + float(5) * t4 * (float(2) * ab_ap * t6 + float(2) * t10 * a_minus_b + float(3) * t4 * (t9 * a_minus_b + ab_ap * t5 + J2 * ab_ab) * ab_ab) * ab_ab) * ab_ab + float(48) * t13 * a_minus_b) * ab_ab + float(128) * t14 * a_minus_b;
    float t16 = t12 * t12;
    float t17 = t11 * t11;
    float t18 = float(11) * t4 * t15 * ab_ab + float(1280) * ab_ap * t16 + float(1280) * t17 * a_minus_b;
    float t19 = t4 * ab_ap * t18 + float(1280) * t16 - float(1280) * t17;
    F = (float(1) / float(15360)) * (float(2) * ab_ap * t3 * t19 + float(12) * t4 * t15 - t4 * t18 * ap_ap) * si.w[2] * t3 + (float(1) / float(15360)) * t4 * t18 * si.w[0] + (float(1) / float(15360)) * si.w[1] * t3 * t19;
    float t20 = t16 * t5;
    float t21 = t17 * t9;
    float t22 = float(15360) * ab_ap * t20 + float(13) * t4 * t18 * ab_ab + float(15360) * t21 * a_minus_b;
    float t23 = t4 * ab_ap * t22 + float(15360) * t20 - float(15360) * t21;
    G_ap = (float(1) / float(215040)) * t23 * si.w[1] * t3 + (float(1) / float(215040)) * (float(2) * t23 * ab_ap * t3 + float(14) * t4 * t18 - t4 * t22 * ap_ap) * si.w[2] * t3 + (float(1) / float(215040)) * t4 * t22 * si.w[0];
    G_E = (float(1) / float(215040)) * (float(2) * si.w[2] * t3 * t19 + t4 * si.w[1] * t18 + float(15360) * t20 * si.w[0] - float(15360) * t21 * (si.w[1] + si.w[2] + si.w[0])) * t3;
  }
  float g_factor = -float(14) * length;
  f = length * F;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = -g_factor * (G_E * ab1 - foot1 * G_ap);
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-14) dt
// Operations: 49 +, 111 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i14_w3_f(SegmentInput si) {
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
  float ap_ap = ap1 * ap1 + ap0 * ap0 + ap2 * ap2;
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
  float ab_bp = ab2 * bp2 + ab1 * bp1 + ab0 * bp0;
  float ap_bp = ap2 * bp2 + ap0 * bp0 + ap1 * bp1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, ap_bp);
    float t2 = float(1) / cross_cross;
    float t3 = float(1) / ap_ap;
    float t4 = t3 * t3;
    float t5 = t4 * t3;
    float t6 = float(1) / bp_bp;
    float t7 = t6 * t6;
    float t8 = t7 * t6;
    float t9 = t7 * t7;
    float t10 = t4 * t4;
    float t11 = t9 * t6;
    float t12 = t10 * t3;
    float t13 = float(3) * (float(7) * ab_ab * t2 * (float(8) * ab_ap * t5 + float(5) * ab_ab * t2 * (float(3) * (a_minus_b * t6 + ab_ap * t3 + J2 * ab_ab) * ab_ab * t2 + float(2) * ab_ap * t4 + float(2) * a_minus_b * t7) + float(8) * a_minus_b * t8) + float(48) * a_minus_b * t9 + float(48) * ab_ap * t10) * ab_ab * t2 + float(128) * a_minus_b * t11 + float(128) * ab_ap * t12;
    float t14 = t8 * t8;
    float t15 = t5 * t5;
    float t16 = float(11) * ab_ab * t2 * t13 + float(1280) * a_minus_b * t14 + float(1280) * ab_ap * t15;
    float t17 = float(1) / ab_ab;
    float t18 = float(1280) * t14 - float(1280) * t15 - t2 * t16 * ab_ap;
    float t19 = t2 * t16 * ap_ap + float(2) * t17 * ab_ap * t18 - float(12) * t2 * t13;
    F = (float(1) / float(15360)) * si.w[0] * t2 * t16 + (float(1) / float(15360)) * si.w[3] * t17 * (t17 * ap_ap * t18 - float(2) * t17 * ab_ap * t19 - float(12) * t17 * (float(128) * t11 - t2 * ab_ap * t13 - float(128) * t12)) - (float(1) / float(15360)) * t17 * t19 * si.w[2] - (float(1) / float(15360)) * t17 * si.w[1] * t18;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-14) dt
// Operations: 73 +, 180 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i14_w3_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float ab_bp = ab2 * bp2 + ab0 * bp0 + ab1 * bp1;
  float ap_bp = ap0 * bp0 + ap2 * bp2 + ap1 * bp1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, ap_bp);
    float t3 = float(1) / cross_cross;
    float t4 = float(1) / bp_bp;
    float t5 = t4 * t4;
    float t6 = t5 * t4;
    float t7 = t6 * t6;
    float t8 = t5 * t5;
    float t9 = float(1) / ap_ap;
    float t10 = t9 * t9;
    float t11 = t10 * t9;
    float t12 = t10 * t10;
    float t13 = t8 * t4;
    float t14 = t12 * t9;
    float t15 = float(3) * ab_ab * t3 * (float(48) * t8 * a_minus_b + float(7) * ab_ab * t3 * (float(5) * ab_ab * (float(2) * ab_ap * t10 + float(3) * ab_ab * (t4 * a_minus_b + ab_ap * t9 + ab_ab * J2) * t3 + float(2) * t5 * a_minus_b) * t3 + float(8) * ab_ap * t11 + float(8) * t6 * a_minus_b) + float(48) * ab_ap * t12) + float(128) * t13 * a_minus_b + float(128) * ab_ap * t14;
    float t16 = t11 * t11;
    float t17 = float(1280) * t7 * a_minus_b + float(11) * ab_ab * t3 * t15 + float(1280) * ab_ap * t16;
    float t18 = float(1) / ab_ab;
    float t19 = float(1280) * t7 - float(1280) * t16 - t3 * ab_ap * t17;
    float t20 = t3 * t17 * ap_ap + float(2) * t18 * t19 * ab_ap - float(12) * t3 * t15;
    F = (float(1) / float(15360)) * si.w[0] * t3 * t17 - (float(1) / float(15360)) * t18 * t19 * si.w[1] - (float(1) / float(15360)) * si.w[3] * t18 * (float(2) * t18 * ab_ap * t20 + float(12) * t18 * (float(128) * t13 - t3 * t15 * ab_ap - float(128) * t14) - t18 * t19 * ap_ap) - (float(1) / float(15360)) * t18 * t20 * si.w[2];
    float t21 = t7 * t4;
    float t22 = t16 * t9;
    float t23 = float(15360) * t21 * a_minus_b + float(15360) * ab_ap * t22 + float(13) * ab_ab * t3 * t17;
    float t24 = float(15360) * t21 - t3 * ab_ap * t23 - float(15360) * t22;
    float t25 = float(2) * t18 * t24 * ab_ap + t3 * t23 * ap_ap - float(14) * t3 * t17;
    G_ap = (float(1) / float(215040)) * si.w[0] * t3 * t23 - (float(1) / float(215040)) * si.w[3] * t18 * (float(2) * t18 * ab_ap * t25 + float(14) * t18 * t19 - t18 * t24 * ap_ap) - (float(1) / float(215040)) * t18 * t25 * si.w[2] - (float(1) / float(215040)) * t18 * t24 * si.w[1];
    G_E = -(float(1) / float(215040)) * t18 * (float(15360) * (si.w[3] + si.w[0] + si.w[1] + si.w[2]) * t21 + float(3) * si.w[3] * t18 * t20 + float(2) * t18 * t19 * si.w[2] - t3 * si.w[1] * t17 - float(15360) * si.w[0] * t22);
  }
  float g_factor = -float(14) * length;
  f = length * F;
  grad[0] = -(ab0 * G_E - G_ap * foot0) * g_factor;
  grad[1] = (G_ap * foot1 - ab1 * G_E) * g_factor;
  grad[2] = -(ab2 * G_E - G_ap * foot2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-15) dt
// Operations: 37 +, 94 *, 3 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i15_w0_f(SegmentInput si) {
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
  float ab_ap = ap1 * ab1 + ap2 * ab2 + ab0 * ap0;
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
  float bp_bp = bp1 * bp1 + bp0 * bp0 + bp2 * bp2;
  float ab_bp = bp2 * ab2 + ab0 * bp0 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / cross_cross;
    float t1 = float(1) / r0;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t2;
    float t5 = t4 * t4;
    float t6 = float(1) / r1;
    float t7 = t6 * t6;
    float t8 = t7 * t7;
    float t9 = t8 * t8;
    float t10 = t9 * t7;
    float t11 = t8 * t7;
    float t12 = t3 * t3;
    float t13 = t12 * t2;
    float t14 = t11 * t11;
    F = (float(1) / float(3003)) * t0 * (float(231) * ab_ap * t1 * t5 + float(4) * t0 * ab_ab * (float(63) * t10 * t6 * a_minus_b + float(2) * t0 * (float(8) * t0 * (float(5) * ab_ap * t1 * t4 + float(2) * t0 * ab_ab * (float(3) * t8 * t6 * a_minus_b + float(3) * ab_ap * t1 * t3 + float(4) * t0 * (float(2) * t0 * ab_ab * (t6 * a_minus_b + ab_ap * t1) + t7 * t6 * a_minus_b + ab_ap * t1 * t2) * ab_ab) + float(5) * t11 * t6 * a_minus_b) * ab_ab + float(35) * t9 * t6 * a_minus_b + float(35) * ab_ap * t1 * t12) * ab_ab + float(63) * ab_ap * t1 * t13) + float(231) * t14 * t6 * a_minus_b) * si.w[0];
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-15) dt
// Operations: 46 +, 140 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i15_w0_f_and_grad(SegmentInput si, out vec3 grad) {
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
    foot2 = ap2 - t0 * ab2 * ab_ap;
  }
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / cross_cross;
    float t2 = float(1) / r1;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = t4 * t3;
    float t6 = t5 * t5;
    float t7 = float(1) / r0;
    float t8 = t7 * t7;
    float t9 = t8 * t8;
    float t10 = t9 * t9;
    float t11 = t10 * t8;
    float t12 = t9 * t8;
    float t13 = t4 * t4;
    float t14 = t13 * t3;
    float t15 = t12 * t12;
    float t16 = float(231) * t2 * t6 * a_minus_b + float(4) * (float(63) * t11 * t7 * ab_ap + float(2) * ab_ab * t1 * (float(35) * t10 * t7 * ab_ap + float(8) * (float(5) * t2 * t5 * a_minus_b + float(2) * (float(3) * t9 * t7 * ab_ap + float(3) * t2 * t4 * a_minus_b + float(4) * ab_ab * t1 * (float(2) * ab_ab * t1 * (t7 * ab_ap + t2 * a_minus_b) + t2 * t3 * a_minus_b + t8 * t7 * ab_ap)) * ab_ab * t1 + float(5) * t12 * t7 * ab_ap) * ab_ab * t1 + float(35) * t2 * t13 * a_minus_b) + float(63) * t2 * t14 * a_minus_b) * ab_ab * t1 + float(231) * t15 * t7 * ab_ap;
    F = (float(1) / float(3003)) * si.w[0] * t1 * t16;
    float t17 = t6 * t3;
    float t18 = t15 * t8;
    G_ap = (float(1) / float(6435)) * si.w[0] * t1 * (float(2) * ab_ab * t1 * t16 + float(429) * t2 * t17 * a_minus_b + float(429) * t18 * t7 * ab_ap);
    float t19 = t2 * t2;
    float t20 = t19 * t2;
    float t21 = t20 * t20;
    float t22 = t21 * t2;
    float t23 = t22 * t22;
    float t24 = t23 * t2;
    float t25 = t7 * t7;
    float t26 = t25 * t7;
    float t27 = t26 * t26;
    float t28 = t27 * t7;
    float t29 = t28 * t28;
    float t30 = t29 * t7;
    float t31 = float(1) / ab_ab;
    G_E = -(float(1) / float(15)) * (si.w[0] * t24 - si.w[0] * t30) * t31;
  }
  float g_factor = -float(15) * length;
  f = F * length;
  grad[0] = -g_factor * (ab0 * G_E - G_ap * foot0);
  grad[1] = g_factor * (foot1 * G_ap - ab1 * G_E);
  grad[2] = -g_factor * (ab2 * G_E - G_ap * foot2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-15) dt
// Operations: 40 +, 102 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i15_w1_f(SegmentInput si) {
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
  float ab_ap = ab2 * ap2 + ap0 * ab0 + ap1 * ab1;
  float ap_ap = ap0 * ap0 + ap1 * ap1 + ap2 * ap2;
  float plain_cross0 = ab1 * ap2 - ap1 * ab2;
  float plain_cross1 = ap0 * ab2 - ab0 * ap2;
  float plain_cross2 = ap1 * ab0 - ap0 * ab1;
  float plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / cross_cross;
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
    float t13 = t11 * t2;
    float t14 = t12 * t7;
    float t15 = float(231) * t5 * t1 * a_minus_b + float(231) * t10 * t6 * ab_ap + float(4) * (float(2) * ab_ab * t0 * (float(35) * t11 * t1 * a_minus_b + float(8) * (float(5) * t9 * t6 * ab_ap + float(5) * t4 * t1 * a_minus_b + float(2) * (float(4) * (t2 * t1 * a_minus_b + t7 * t6 * ab_ap + float(2) * (t1 * a_minus_b + t6 * ab_ap) * ab_ab * t0) * ab_ab * t0 + float(3) * t3 * t1 * a_minus_b + float(3) * t8 * t6 * ab_ap) * ab_ab * t0) * ab_ab * t0 + float(35) * t12 * t6 * ab_ap) + float(63) * t13 * t1 * a_minus_b + float(63) * t14 * t6 * ab_ap) * ab_ab * t0;
    F = (float(1) / float(3003)) * si.w[1] * (t0 * t15 * ab_ap + float(231) * t10 * t6 - float(231) * t5 * t1) / ab_ab + (float(1) / float(3003)) * si.w[0] * t0 * t15;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-15) dt
// Operations: 54 +, 162 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i15_w1_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
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
    float t6 = t3 * t3;
    float t7 = t6 * t2;
    float t8 = float(1) / r1;
    float t9 = t8 * t8;
    float t10 = t9 * t9;
    float t11 = t10 * t10;
    float t12 = t11 * t9;
    float t13 = t10 * t9;
    float t14 = float(1) / cross_cross;
    float t15 = t13 * t13;
    float t16 = float(231) * ab_ap * t5 * t1 + float(4) * (float(63) * ab_ap * t7 * t1 + float(63) * t12 * a_minus_b * t8 + float(2) * ab_ab * (float(8) * (float(5) * t13 * a_minus_b * t8 + float(5) * ab_ap * t4 * t1 + float(2) * (float(4) * (float(2) * (a_minus_b * t8 + ab_ap * t1) * ab_ab * t14 + ab_ap * t2 * t1 + t9 * a_minus_b * t8) * ab_ab * t14 + float(3) * t10 * a_minus_b * t8 + float(3) * ab_ap * t3 * t1) * ab_ab * t14) * ab_ab * t14 + float(35) * ab_ap * t6 * t1 + float(35) * t11 * a_minus_b * t8) * t14) * ab_ab * t14 + float(231) * t15 * a_minus_b * t8;
    float t17 = float(1) / ab_ab;
    F = (float(1) / float(3003)) * si.w[0] * t16 * t14 - (float(1) / float(3003)) * (float(231) * t15 * t8 - ab_ap * t16 * t14 - float(231) * t5 * t1) * si.w[1] * t17;
    float t18 = t15 * t9;
    float t19 = t5 * t2;
    float t20 = float(429) * t18 * a_minus_b * t8 + float(429) * ab_ap * t19 * t1 + float(2) * t16 * ab_ab * t14;
    G_ap = (float(1) / float(6435)) * si.w[0] * t20 * t14 - (float(1) / float(6435)) * (float(429) * t18 * t8 - ab_ap * t20 * t14 - float(429) * t19 * t1) * si.w[1] * t17;
    float t21 = t1 * t1;
    float t22 = t21 * t1;
    float t23 = t22 * t22;
    float t24 = t23 * t1;
    float t25 = t24 * t24;
    float t26 = t25 * t1;
    float t27 = t8 * t8;
    float t28 = t27 * t8;
    float t29 = t28 * t28;
    float t30 = t29 * t8;
    float t31 = t30 * t30;
    float t32 = t31 * t8;
    G_E = (float(1) / float(45045)) * (float(3003) * si.w[0] * t26 + si.w[1] * t16 * t14 - float(3003) * t32 * (si.w[0] + si.w[1])) * t17;
  }
  float g_factor = -float(15) * length;
  f = length * F;
  grad[0] = (foot0 * G_ap - G_E * ab0) * g_factor;
  grad[1] = -(G_E * ab1 - foot1 * G_ap) * g_factor;
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-15) dt
// Operations: 43 +, 114 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i15_w2_f(SegmentInput si) {
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
  float plain_cross_cross = plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1 + plain_cross0 * plain_cross0;
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
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / cross_cross;
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
    float t11 = t3 * t3;
    float t12 = t8 * t8;
    float t13 = t11 * t2;
    float t14 = t12 * t7;
    float t15 = float(2) * (float(35) * t11 * t1 * ab_ap + float(8) * ab_ab * t0 * (float(2) * ab_ab * (float(3) * t3 * t1 * ab_ap + float(4) * ab_ab * t0 * (t6 * a_minus_b * t7 + t2 * t1 * ab_ap + float(2) * ab_ab * t0 * (t6 * a_minus_b + t1 * ab_ap)) + float(3) * t6 * a_minus_b * t8) * t0 + float(5) * t6 * a_minus_b * t9 + float(5) * t4 * t1 * ab_ap) + float(35) * t6 * a_minus_b * t12) * ab_ab * t0 + float(63) * t13 * t1 * ab_ap + float(63) * t6 * a_minus_b * t14;
    float t16 = float(231) * t5 * t1 * ab_ap + float(231) * t6 * a_minus_b * t10 + float(4) * t15 * ab_ab * t0;
    float t17 = float(1) / ab_ab;
    float t18 = float(231) * t6 * t10 - float(231) * t5 * t1 - t0 * t16 * ab_ap;
    F = (float(1) / float(3003)) * t0 * si.w[0] * t16 - (float(1) / float(3003)) * t17 * t18 * si.w[1] - (float(1) / float(9009)) * si.w[2] * t17 * (float(3) * ap_ap * t0 * t16 + float(6) * t17 * ab_ap * t18 - float(13) * t15 * t0);
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-15) dt
// Operations: 62 +, 187 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i15_w2_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float ab_ap = ab2 * ap2 + ab0 * ap0 + ab1 * ap1;
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
    foot2 = ap2 - t0 * ab2 * ab_ap;
  }
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / r1;
    float t2 = t1 * t1;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = t4 * t2;
    float t6 = float(1) / cross_cross;
    float t7 = t3 * t2;
    float t8 = float(1) / r0;
    float t9 = t8 * t8;
    float t10 = t9 * t9;
    float t11 = t10 * t9;
    float t12 = t10 * t10;
    float t13 = t12 * t9;
    float t14 = float(63) * a_minus_b * t1 * t5 + float(2) * (float(8) * ab_ab * t6 * (float(5) * a_minus_b * t1 * t7 + float(5) * t11 * t8 * ab_ap + float(2) * (float(3) * a_minus_b * t1 * t3 + float(4) * ab_ab * (t9 * t8 * ab_ap + float(2) * (t8 * ab_ap + a_minus_b * t1) * ab_ab * t6 + a_minus_b * t1 * t2) * t6 + float(3) * t10 * t8 * ab_ap) * ab_ab * t6) + float(35) * a_minus_b * t1 * t4 + float(35) * t12 * t8 * ab_ap) * ab_ab * t6 + float(63) * t13 * t8 * ab_ap;
    float t15 = float(1) / ab_ab;
    float t16 = t11 * t11;
    float t17 = t7 * t7;
    float t18 = float(231) * t16 * t8 * ab_ap + float(231) * a_minus_b * t1 * t17 + float(4) * ab_ab * t14 * t6;
    float t19 = float(231) * t16 * t8 + t18 * t6 * ab_ap - float(231) * t1 * t17;
    F = (float(1) / float(9009)) * (float(13) * t14 * t6 + float(6) * t15 * ab_ap * t19 - float(3) * ap_ap * t18 * t6) * si.w[2] * t15 + (float(1) / float(3003)) * si.w[1] * t15 * t19 + (float(1) / float(3003)) * t18 * t6 * si.w[0];
    float t20 = t16 * t9;
    float t21 = t17 * t2;
    float t22 = float(429) * a_minus_b * t1 * t21 + float(429) * t20 * t8 * ab_ap + float(2) * ab_ab * t18 * t6;
    float t23 = float(429) * t20 * t8 + t22 * t6 * ab_ap - float(429) * t1 * t21;
    G_ap = (float(1) / float(6435)) * si.w[1] * t15 * t23 + (float(1) / float(6435)) * t22 * t6 * si.w[0] + (float(1) / float(45045)) * si.w[2] * t15 * (float(15) * t18 * t6 + float(14) * t15 * t23 * ab_ap - float(7) * ap_ap * t22 * t6);
    float t24 = t8 * t8;
    float t25 = t24 * t8;
    float t26 = t25 * t25;
    float t27 = t26 * t8;
    float t28 = t27 * t27;
    float t29 = t28 * t8;
    float t30 = t1 * t1;
    float t31 = t30 * t1;
    float t32 = t31 * t31;
    float t33 = t32 * t1;
    float t34 = t33 * t33;
    float t35 = t34 * t1;
    G_E = (float(1) / float(45045)) * (float(3003) * t29 * si.w[0] + float(2) * si.w[2] * t15 * t19 + si.w[1] * t18 * t6 - float(3003) * t35 * (si.w[1] + si.w[2] + si.w[0])) * t15;
  }
  float g_factor = -float(15) * length;
  f = F * length;
  grad[0] = -(ab0 * G_E - G_ap * foot0) * g_factor;
  grad[1] = -(ab1 * G_E - foot1 * G_ap) * g_factor;
  grad[2] = -(ab2 * G_E - G_ap * foot2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-15) dt
// Operations: 48 +, 131 *, 4 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i15_w3_f(SegmentInput si) {
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
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = float(1) / r0;
    float t1 = t0 * t0;
    float t2 = t1 * t1;
    float t3 = t2 * t1;
    float t4 = t3 * t3;
    float t5 = float(1) / cross_cross;
    float t6 = float(1) / r1;
    float t7 = t6 * t6;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = t9 * t9;
    float t11 = t2 * t2;
    float t12 = t11 * t1;
    float t13 = t8 * t8;
    float t14 = t13 * t7;
    float t15 = float(63) * t0 * ab_ap * t12 + float(63) * t14 * t6 * a_minus_b + float(2) * (float(8) * t5 * (float(5) * t0 * ab_ap * t3 + float(5) * t9 * t6 * a_minus_b + float(2) * t5 * (float(3) * t0 * ab_ap * t2 + float(3) * t8 * t6 * a_minus_b + float(4) * t5 * (t7 * t6 * a_minus_b + t0 * ab_ap * t1 + float(2) * t5 * (t0 * ab_ap + t6 * a_minus_b) * ab_ab) * ab_ab) * ab_ab) * ab_ab + float(35) * t0 * ab_ap * t11 + float(35) * t13 * t6 * a_minus_b) * t5 * ab_ab;
    float t16 = float(231) * t10 * t6 * a_minus_b + float(4) * t5 * t15 * ab_ab + float(231) * t0 * ab_ap * t4;
    float t17 = float(231) * t0 * t4 + t5 * ab_ap * t16 - float(231) * t10 * t6;
    float t18 = float(1) / ab_ab;
    float t19 = float(3) * t5 * t16 * ap_ap - float(6) * ab_ap * t17 * t18 - float(13) * t5 * t15;
    F = (float(1) / float(3003)) * si.w[1] * t17 * t18 + (float(1) / float(9009)) * si.w[3] * t18 * (float(13) * (float(63) * t0 * t12 + t5 * ab_ap * t15 - float(63) * t14 * t6) * t18 - float(2) * ab_ap * t19 * t18 - float(3) * ap_ap * t17 * t18) + (float(1) / float(3003)) * t5 * t16 * si.w[0] - (float(1) / float(9009)) * t19 * si.w[2] * t18;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-15) dt
// Operations: 72 +, 217 *, 5 /, 3 sqrt, 0 atan, 0 log/asinh (generic form).
float segment_inverse_i15_w3_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float r0 = sqrt(ap_ap);
  float r1 = sqrt(bp_bp);
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = float(1) / cross_cross;
    float t2 = float(1) / r1;
    float t3 = t2 * t2;
    float t4 = t3 * t3;
    float t5 = t4 * t3;
    float t6 = float(1) / r0;
    float t7 = t6 * t6;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = t8 * t8;
    float t11 = t4 * t4;
    float t12 = t10 * t7;
    float t13 = t11 * t3;
    float t14 = float(2) * t1 * (float(8) * (float(5) * t2 * t5 * a_minus_b + float(5) * ab_ap * t9 * t6 + float(2) * t1 * (float(3) * ab_ap * t8 * t6 + float(3) * t2 * t4 * a_minus_b + float(4) * t1 * (float(2) * t1 * (t2 * a_minus_b + ab_ap * t6) * ab_ab + t2 * t3 * a_minus_b + ab_ap * t7 * t6) * ab_ab) * ab_ab) * t1 * ab_ab + float(35) * ab_ap * t10 * t6 + float(35) * t2 * t11 * a_minus_b) * ab_ab + float(63) * ab_ap * t12 * t6 + float(63) * t2 * t13 * a_minus_b;
    float t15 = t5 * t5;
    float t16 = t9 * t9;
    float t17 = float(4) * t1 * ab_ab * t14 + float(231) * t2 * t15 * a_minus_b + float(231) * ab_ap * t16 * t6;
    float t18 = float(231) * t2 * t15 - float(231) * t16 * t6 - t1 * t17 * ab_ap;
    float t19 = float(1) / ab_ab;
    float t20 = float(6) * ab_ap * t18 * t19 + float(3) * t1 * t17 * ap_ap - float(13) * t1 * t14;
    F = (float(1) / float(3003)) * t1 * t17 * si.w[0] - (float(1) / float(3003)) * si.w[1] * t18 * t19 - (float(1) / float(9009)) * si.w[2] * t19 * t20 - (float(1) / float(9009)) * (float(13) * (float(63) * t2 * t13 - t1 * ab_ap * t14 - float(63) * t12 * t6) * t19 + float(2) * ab_ap * t19 * t20 - float(3) * t18 * ap_ap * t19) * si.w[3] * t19;
    float t21 = t15 * t3;
    float t22 = t16 * t7;
    float t23 = float(2) * t1 * t17 * ab_ab + float(429) * t2 * t21 * a_minus_b + float(429) * ab_ap * t22 * t6;
    float t24 = float(429) * t2 * t21 - t1 * ab_ap * t23 - float(429) * t22 * t6;
    float t25 = float(7) * t1 * t23 * ap_ap + float(14) * ab_ap * t19 * t24 - float(15) * t1 * t17;
    G_ap = (float(1) / float(6435)) * t1 * t23 * si.w[0] - (float(1) / float(45045)) * si.w[2] * t25 * t19 - (float(1) / float(45045)) * (float(2) * ab_ap * t25 * t19 + float(15) * t18 * t19 - float(7) * ap_ap * t19 * t24) * si.w[3] * t19 - (float(1) / float(6435)) * si.w[1] * t19 * t24;
    float t26 = t2 * t2;
    float t27 = t26 * t2;
    float t28 = t27 * t27;
    float t29 = t28 * t2;
    float t30 = t29 * t29;
    float t31 = t30 * t2;
    float t32 = t6 * t6;
    float t33 = t32 * t6;
    float t34 = t33 * t33;
    float t35 = t34 * t6;
    float t36 = t35 * t35;
    float t37 = t36 * t6;
    G_E = -(float(1) / float(45045)) * (float(3003) * t31 * (si.w[1] + si.w[2] + si.w[3] + si.w[0]) + float(2) * si.w[2] * t18 * t19 + si.w[3] * t19 * t20 - t1 * si.w[1] * t17 - float(3003) * t37 * si.w[0]) * t19;
  }
  float g_factor = -float(15) * length;
  f = length * F;
  grad[0] = -g_factor * (ab0 * G_E - foot0 * G_ap);
  grad[1] = g_factor * (foot1 * G_ap - G_E * ab1);
  grad[2] = -(G_E * ab2 - G_ap * foot2) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-16) dt
// Operations: 40 +, 89 *, 4 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i16_w0_f(SegmentInput si) {
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
  float plain_cross_cross = plain_cross0 * plain_cross0 + plain_cross2 * plain_cross2 + plain_cross1 * plain_cross1;
  float cross_cross;
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float ap_bp = bp2 * ap2 + ap0 * bp0 + bp1 * ap1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = atan(t0, ap_bp) * t1;
    float t2 = float(1) / ap_ap;
    float t3 = t2 * t2;
    float t4 = t3 * t2;
    float t5 = t4 * t4;
    float t6 = float(1) / bp_bp;
    float t7 = t6 * t6;
    float t8 = t7 * t6;
    float t9 = t8 * t8;
    float t10 = float(1) / cross_cross;
    float t11 = t3 * t3;
    float t12 = t11 * t2;
    float t13 = t7 * t7;
    float t14 = t13 * t6;
    float t15 = t5 * t2;
    float t16 = t9 * t6;
    F = (float(1) / float(215040)) * (float(13) * (float(1280) * t5 * ab_ap + float(1280) * a_minus_b * t9 + float(11) * ab_ab * t10 * (float(128) * t12 * ab_ap + float(3) * (float(48) * t11 * ab_ap + float(48) * a_minus_b * t13 + float(7) * ab_ab * (float(5) * (float(3) * ab_ab * (J2 * ab_ab + a_minus_b * t6 + t2 * ab_ap) * t10 + float(2) * t3 * ab_ap + float(2) * a_minus_b * t7) * ab_ab * t10 + float(8) * t4 * ab_ap + float(8) * a_minus_b * t8) * t10) * ab_ab * t10 + float(128) * a_minus_b * t14)) * ab_ab * t10 + float(15360) * t15 * ab_ap + float(15360) * a_minus_b * t16) * si.w[0] * t10;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 w0 |P - Gamma(t)|^(-16) dt
// Operations: 49 +, 120 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i16_w0_f_and_grad(SegmentInput si, out vec3 grad) {
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
    foot2 = ap2 - t0 * ab2 * ab_ap;
  }
  float bp_bp = bp0 * bp0 + bp1 * bp1 + bp2 * bp2;
  float ab_bp = ab2 * bp2 + ab1 * bp1 + bp0 * ab0;
  float ap_bp = ap1 * bp1 + bp0 * ap0 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = t2 * atan(t1, ap_bp);
    float t3 = float(1) / bp_bp;
    float t4 = t3 * t3;
    float t5 = t4 * t3;
    float t6 = t5 * t5;
    float t7 = t6 * t3;
    float t8 = float(1) / ap_ap;
    float t9 = t8 * t8;
    float t10 = t9 * t8;
    float t11 = t10 * t10;
    float t12 = t11 * t8;
    float t13 = float(1) / cross_cross;
    float t14 = t9 * t9;
    float t15 = t4 * t4;
    float t16 = t15 * t3;
    float t17 = t14 * t8;
    float t18 = float(15360) * t7 * a_minus_b + float(15360) * ab_ap * t12 + float(13) * (float(11) * (float(3) * ab_ab * t13 * (float(7) * ab_ab * (float(8) * t5 * a_minus_b + float(5) * (float(2) * t4 * a_minus_b + float(3) * ab_ab * (ab_ap * t8 + ab_ab * J2 + t3 * a_minus_b) * t13 + float(2) * ab_ap * t9) * ab_ab * t13 + float(8) * ab_ap * t10) * t13 + float(48) * ab_ap * t14 + float(48) * t15 * a_minus_b) + float(128) * t16 * a_minus_b + float(128) * ab_ap * t17) * ab_ab * t13 + float(1280) * t6 * a_minus_b + float(1280) * ab_ap * t11) * ab_ab * t13;
    F = (float(1) / float(215040)) * t18 * si.w[0] * t13;
    float t19 = t14 * t14;
    float t20 = t15 * t15;
    G_ap = (float(1) / float(229376)) * si.w[0] * (float(14336) * ab_ap * t19 + float(14336) * t20 * a_minus_b + t18 * ab_ab * t13) * t13;
    float t21 = float(1) / ab_ab;
    G_E = (float(1) / float(16)) * t21 * (si.w[0] * t19 - si.w[0] * t20);
  }
  float g_factor = -float(16) * length;
  f = length * F;
  grad[0] = (G_ap * foot0 - ab0 * G_E) * g_factor;
  grad[1] = (foot1 * G_ap - ab1 * G_E) * g_factor;
  grad[2] = (G_ap * foot2 - ab2 * G_E) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-16) dt
// Operations: 43 +, 95 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i16_w1_f(SegmentInput si) {
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
  float bp_bp = bp2 * bp2 + bp0 * bp0 + bp1 * bp1;
  float ab_bp = bp0 * ab0 + bp2 * ab2 + bp1 * ab1;
  float ap_bp = bp2 * ap2 + bp1 * ap1 + bp0 * ap0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, ap_bp);
    float t2 = float(1) / bp_bp;
    float t3 = t2 * t2;
    float t4 = t3 * t2;
    float t5 = t4 * t4;
    float t6 = t5 * t2;
    float t7 = float(1) / ap_ap;
    float t8 = t7 * t7;
    float t9 = t8 * t7;
    float t10 = t9 * t9;
    float t11 = t10 * t7;
    float t12 = float(1) / cross_cross;
    float t13 = t8 * t8;
    float t14 = t13 * t7;
    float t15 = t3 * t3;
    float t16 = t15 * t2;
    float t17 = float(15360) * a_minus_b * t6 + float(15360) * t11 * ab_ap + float(13) * (float(1280) * a_minus_b * t5 + float(1280) * t10 * ab_ap + float(11) * ab_ab * t12 * (float(128) * t14 * ab_ap + float(128) * a_minus_b * t16 + float(3) * (float(48) * a_minus_b * t15 + float(48) * t13 * ab_ap + float(7) * ab_ab * t12 * (float(5) * ab_ab * (float(2) * a_minus_b * t3 + float(3) * (t7 * ab_ap + a_minus_b * t2 + J2 * ab_ab) * ab_ab * t12 + float(2) * t8 * ab_ap) * t12 + float(8) * a_minus_b * t4 + float(8) * t9 * ab_ap)) * ab_ab * t12)) * ab_ab * t12;
    F = (float(1) / float(215040)) * t17 * t12 * si.w[0] + (float(1) / float(215040)) * si.w[1] * (float(15360) * t11 + t17 * t12 * ab_ap - float(15360) * t6) / ab_ab;
  }
  f = F * length;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t) |P - Gamma(t)|^(-16) dt
// Operations: 57 +, 138 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i16_w1_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = atan(t1, ap_bp) * t2;
    float t3 = float(1) / cross_cross;
    float t4 = float(1) / bp_bp;
    float t5 = t4 * t4;
    float t6 = t5 * t4;
    float t7 = t6 * t6;
    float t8 = t5 * t5;
    float t9 = float(1) / ap_ap;
    float t10 = t9 * t9;
    float t11 = t10 * t9;
    float t12 = t10 * t10;
    float t13 = t8 * t4;
    float t14 = t12 * t9;
    float t15 = t11 * t11;
    float t16 = t7 * t4;
    float t17 = t15 * t9;
    float t18 = float(13) * ab_ab * t3 * (float(1280) * a_minus_b * t7 + float(11) * ab_ab * (float(3) * (float(48) * a_minus_b * t8 + float(7) * (float(5) * (float(3) * (J2 * ab_ab + t9 * ab_ap + a_minus_b * t4) * ab_ab * t3 + float(2) * a_minus_b * t5 + float(2) * t10 * ab_ap) * ab_ab * t3 + float(8) * t11 * ab_ap + float(8) * a_minus_b * t6) * ab_ab * t3 + float(48) * t12 * ab_ap) * ab_ab * t3 + float(128) * a_minus_b * t13 + float(128) * t14 * ab_ap) * t3 + float(1280) * t15 * ab_ap) + float(15360) * a_minus_b * t16 + float(15360) * t17 * ab_ap;
    float t19 = float(1) / ab_ab;
    F = (float(1) / float(215040)) * si.w[0] * t18 * t3 + (float(1) / float(215040)) * (float(15360) * t17 + t18 * t3 * ab_ap - float(15360) * t16) * si.w[1] * t19;
    float t20 = t8 * t8;
    float t21 = t12 * t12;
    float t22 = float(14336) * a_minus_b * t20 + float(14336) * t21 * ab_ap + t18 * ab_ab * t3;
    G_ap = (float(1) / float(229376)) * si.w[0] * t22 * t3 - (float(1) / float(229376)) * (float(14336) * t20 - t22 * t3 * ab_ap - float(14336) * t21) * si.w[1] * t19;
    G_E = -(float(1) / float(3440640)) * (float(215040) * (si.w[0] + si.w[1]) * t20 - si.w[1] * t18 * t3 - float(215040) * si.w[0] * t21) * t19;
  }
  float g_factor = -float(16) * length;
  f = F * length;
  grad[0] = (foot0 * G_ap - ab0 * G_E) * g_factor;
  grad[1] = -(ab1 * G_E - foot1 * G_ap) * g_factor;
  grad[2] = g_factor * (G_ap * foot2 - ab2 * G_E);
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-16) dt
// Operations: 46 +, 106 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i16_w2_f(SegmentInput si) {
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
  {
    // P away from the line (sin???(AB, AP) >= 1/16)
    cross_cross = plain_cross_cross;
  }
  float bp_bp = bp2 * bp2 + bp1 * bp1 + bp0 * bp0;
  float ab_bp = bp0 * ab0 + bp1 * ab1 + bp2 * ab2;
  float ap_bp = bp2 * ap2 + bp0 * ap0 + bp1 * ap1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = t1 * atan(t0, ap_bp);
    float t2 = float(1) / ab_ab;
    float t3 = float(1) / cross_cross;
    float t4 = float(1) / ap_ap;
    float t5 = t4 * t4;
    float t6 = t5 * t4;
    float t7 = t6 * t6;
    float t8 = t5 * t5;
    float t9 = t8 * t4;
    float t10 = float(1) / bp_bp;
    float t11 = t10 * t10;
    float t12 = t11 * t10;
    float t13 = t11 * t11;
    float t14 = t13 * t10;
    float t15 = t12 * t12;
    float t16 = float(1280) * ab_ap * t7 + float(11) * (float(128) * ab_ap * t9 + float(3) * ab_ab * t3 * (float(48) * ab_ap * t8 + float(7) * (float(8) * ab_ap * t6 + float(8) * a_minus_b * t12 + float(5) * ab_ab * t3 * (float(2) * ab_ap * t5 + float(3) * ab_ab * (a_minus_b * t10 + J2 * ab_ab + ab_ap * t4) * t3 + float(2) * a_minus_b * t11)) * ab_ab * t3 + float(48) * a_minus_b * t13) + float(128) * a_minus_b * t14) * ab_ab * t3 + float(1280) * a_minus_b * t15;
    float t17 = t7 * t4;
    float t18 = t15 * t10;
    float t19 = float(13) * ab_ab * t3 * t16 + float(15360) * ab_ap * t17 + float(15360) * a_minus_b * t18;
    float t20 = t19 * t3 * ab_ap + float(15360) * t17 - float(15360) * t18;
    F = (float(1) / float(215040)) * t2 * t20 * si.w[1] + (float(1) / float(215040)) * t19 * t3 * si.w[0] - (float(1) / float(215040)) * (t19 * t3 * ap_ap - float(2) * t2 * ab_ap * t20 - float(14) * t3 * t16) * si.w[2] * t2;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2) |P - Gamma(t)|^(-16) dt
// Operations: 65 +, 162 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i16_w2_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float ab_ap = ab2 * ap2 + ab1 * ap1 + ab0 * ap0;
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
    foot2 = ap2 - t0 * ab2 * ab_ap;
  }
  float bp_bp = bp1 * bp1 + bp2 * bp2 + bp0 * bp0;
  float ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  float ap_bp = bp0 * ap0 + bp2 * ap2 + bp1 * ap1;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = atan(t1, ap_bp) * t2;
    float t3 = float(1) / ap_ap;
    float t4 = t3 * t3;
    float t5 = t4 * t3;
    float t6 = t5 * t5;
    float t7 = t6 * t3;
    float t8 = float(1) / cross_cross;
    float t9 = float(1) / bp_bp;
    float t10 = t9 * t9;
    float t11 = t10 * t9;
    float t12 = t11 * t11;
    float t13 = t12 * t9;
    float t14 = t10 * t10;
    float t15 = t14 * t9;
    float t16 = t4 * t4;
    float t17 = t16 * t3;
    float t18 = float(1280) * t12 * a_minus_b + float(1280) * t6 * ab_ap + float(11) * (float(128) * t15 * a_minus_b + float(128) * t17 * ab_ap + float(3) * ab_ab * t8 * (float(48) * t14 * a_minus_b + float(7) * ab_ab * t8 * (float(5) * ab_ab * (float(2) * t4 * ab_ap + float(2) * t10 * a_minus_b + float(3) * (ab_ab * J2 + t9 * a_minus_b + t3 * ab_ap) * ab_ab * t8) * t8 + float(8) * t5 * ab_ap + float(8) * t11 * a_minus_b) + float(48) * t16 * ab_ap)) * ab_ab * t8;
    float t19 = float(15360) * t13 * a_minus_b + float(13) * t18 * ab_ab * t8 + float(15360) * t7 * ab_ap;
    float t20 = float(15360) * t7 + t8 * ab_ap * t19 - float(15360) * t13;
    float t21 = float(1) / ab_ab;
    F = (float(1) / float(215040)) * t20 * t21 * si.w[1] + (float(1) / float(215040)) * t8 * si.w[0] * t19 - (float(1) / float(215040)) * (ap_ap * t8 * t19 - float(14) * t18 * t8 - float(2) * t20 * t21 * ab_ap) * si.w[2] * t21;
    float t22 = t14 * t14;
    float t23 = t16 * t16;
    float t24 = ab_ab * t8 * t19 + float(14336) * t22 * a_minus_b + float(14336) * t23 * ab_ap;
    float t25 = float(14336) * t22 - float(14336) * t23 - t24 * t8 * ab_ap;
    G_ap = (float(1) / float(229376)) * t24 * t8 * si.w[0] + (float(1) / float(3440640)) * (float(16) * t8 * t19 - float(30) * t21 * ab_ap * t25 - float(15) * t24 * ap_ap * t8) * si.w[2] * t21 - (float(1) / float(229376)) * t21 * t25 * si.w[1];
    G_E = (float(1) / float(3440640)) * (float(2) * t20 * si.w[2] * t21 + float(215040) * t23 * si.w[0] + t8 * si.w[1] * t19 - float(215040) * (si.w[2] + si.w[0] + si.w[1]) * t22) * t21;
  }
  float g_factor = -float(16) * length;
  f = F * length;
  grad[0] = -(ab0 * G_E - G_ap * foot0) * g_factor;
  grad[1] = -(ab1 * G_E - foot1 * G_ap) * g_factor;
  grad[2] = (G_ap * foot2 - ab2 * G_E) * g_factor;
  return f;
}

// the field, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-16) dt
// Operations: 51 +, 120 *, 5 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i16_w3_f(SegmentInput si) {
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
  float ab_bp = bp1 * ab1 + bp2 * ab2 + bp0 * ab0;
  float ap_bp = ap0 * bp0 + ap1 * bp1 + ap2 * bp2;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  {
    // recurrence (1) upwards from J_1, J_2
    float t0 = sqrt(cross_cross);
    float t1 = float(1) / t0;
    float J2 = atan(t0, ap_bp) * t1;
    float t2 = float(1) / bp_bp;
    float t3 = t2 * t2;
    float t4 = t3 * t2;
    float t5 = t4 * t4;
    float t6 = t3 * t3;
    float t7 = t6 * t2;
    float t8 = float(1) / ap_ap;
    float t9 = t8 * t8;
    float t10 = t9 * t9;
    float t11 = t10 * t8;
    float t12 = float(1) / cross_cross;
    float t13 = t9 * t8;
    float t14 = t13 * t13;
    float t15 = float(1280) * t5 * a_minus_b + float(11) * (float(128) * t7 * a_minus_b + float(128) * ab_ap * t11 + float(3) * (float(48) * t6 * a_minus_b + float(7) * (float(5) * (float(3) * (t2 * a_minus_b + ab_ap * t8 + ab_ab * J2) * ab_ab * t12 + float(2) * ab_ap * t9 + float(2) * t3 * a_minus_b) * ab_ab * t12 + float(8) * ab_ap * t13 + float(8) * t4 * a_minus_b) * ab_ab * t12 + float(48) * ab_ap * t10) * ab_ab * t12) * ab_ab * t12 + float(1280) * ab_ap * t14;
    float t16 = t5 * t2;
    float t17 = t14 * t8;
    float t18 = float(13) * t15 * ab_ab * t12 + float(15360) * t16 * a_minus_b + float(15360) * ab_ap * t17;
    float t19 = float(15360) * t16 - ab_ap * t18 * t12 - float(15360) * t17;
    float t20 = float(1) / ab_ab;
    float t21 = float(2) * ab_ap * t19 * t20 + t18 * ap_ap * t12 - float(14) * t15 * t12;
    F = (float(1) / float(215040)) * t18 * si.w[0] * t12 - (float(1) / float(215040)) * t19 * t20 * si.w[1] - (float(1) / float(215040)) * si.w[3] * t20 * (float(14) * t20 * (float(1280) * t5 - ab_ap * t15 * t12 - float(1280) * t14) + float(2) * ab_ap * t21 * t20 - t19 * ap_ap * t20) - (float(1) / float(215040)) * t21 * si.w[2] * t20;
  }
  f = length * F;
  return f;
}

// the field and its gradient, where
//     f(P) = |AB| int_0^1 (w0 + w1 t + w2 t^2 + w3 t^3) |P - Gamma(t)|^(-16) dt
// Operations: 75 +, 190 *, 6 /, 2 sqrt, 1 atan, 0 log/asinh (generic form).
float segment_inverse_i16_w3_f_and_grad(SegmentInput si, out vec3 grad) {
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
  float bp_bp = bp0 * bp0 + bp2 * bp2 + bp1 * bp1;
  float ab_bp = bp2 * ab2 + bp1 * ab1 + bp0 * ab0;
  float ap_bp = ap1 * bp1 + ap2 * bp2 + ap0 * bp0;
  float length = sqrt(ab_ab);
  float a_minus_b = -ab_bp;
  float F;
  float G_ap;
  float G_E;
  {
    // recurrence (1) upwards from J_1, J_2
    float t1 = sqrt(cross_cross);
    float t2 = float(1) / t1;
    float J2 = atan(t1, ap_bp) * t2;
    float t3 = float(1) / bp_bp;
    float t4 = t3 * t3;
    float t5 = t4 * t3;
    float t6 = float(1) / ap_ap;
    float t7 = t6 * t6;
    float t8 = t7 * t6;
    float t9 = float(1) / cross_cross;
    float t10 = t4 * t4;
    float t11 = t7 * t7;
    float t12 = t11 * t6;
    float t13 = t10 * t3;
    float t14 = t5 * t5;
    float t15 = t8 * t8;
    float t16 = float(11) * ab_ab * (float(3) * (float(7) * ab_ab * (float(8) * t5 * a_minus_b + float(8) * ab_ap * t8 + float(5) * ab_ab * (float(3) * (ab_ap * t6 + t3 * a_minus_b + J2 * ab_ab) * ab_ab * t9 + float(2) * t4 * a_minus_b + float(2) * ab_ap * t7) * t9) * t9 + float(48) * t10 * a_minus_b + float(48) * ab_ap * t11) * ab_ab * t9 + float(128) * ab_ap * t12 + float(128) * t13 * a_minus_b) * t9 + float(1280) * t14 * a_minus_b + float(1280) * ab_ap * t15;
    float t17 = t14 * t3;
    float t18 = t15 * t6;
    float t19 = float(13) * ab_ab * t16 * t9 + float(15360) * t17 * a_minus_b + float(15360) * ab_ap * t18;
    float t20 = float(1) / ab_ab;
    float t21 = float(15360) * t17 - ab_ap * t19 * t9 - float(15360) * t18;
    float t22 = float(2) * ab_ap * t20 * t21 + t19 * ap_ap * t9 - float(14) * t16 * t9;
    F = (float(1) / float(215040)) * t19 * si.w[0] * t9 - (float(1) / float(215040)) * si.w[2] * t22 * t20 - (float(1) / float(215040)) * (float(14) * (float(1280) * t14 - ab_ap * t16 * t9 - float(1280) * t15) * t20 + float(2) * ab_ap * t22 * t20 - ap_ap * t20 * t21) * si.w[3] * t20 - (float(1) / float(215040)) * t20 * t21 * si.w[1];
    float t23 = t11 * t11;
    float t24 = t10 * t10;
    float t25 = float(14336) * ab_ap * t23 + float(14336) * t24 * a_minus_b + t19 * ab_ab * t9;
    float t26 = float(14336) * t23 + ab_ap * t25 * t9 - float(14336) * t24;
    float t27 = float(16) * t19 * t9 + float(30) * ab_ap * t26 * t20 - float(15) * ap_ap * t25 * t9;
    G_ap = (float(1) / float(229376)) * t26 * t20 * si.w[1] + (float(1) / float(229376)) * t25 * si.w[0] * t9 + (float(1) / float(3440640)) * si.w[2] * t27 * t20 + (float(1) / float(3440640)) * si.w[3] * t20 * (float(2) * ab_ap * t27 * t20 - float(15) * t26 * ap_ap * t20 - float(16) * t20 * t21);
    G_E = -(float(1) / float(3440640)) * t20 * (float(215040) * t24 * (si.w[2] + si.w[3] + si.w[0] + si.w[1]) + float(3) * t22 * si.w[3] * t20 + float(2) * si.w[2] * t20 * t21 - float(215040) * t23 * si.w[0] - t19 * t9 * si.w[1]);
  }
  float g_factor = -float(16) * length;
  f = length * F;
  grad[0] = g_factor * (foot0 * G_ap - G_E * ab0);
  grad[1] = -(G_E * ab1 - foot1 * G_ap) * g_factor;
  grad[2] = -g_factor * (G_E * ab2 - G_ap * foot2);
  return f;
}

