// generated/glsl/point.glsl - point kernels in GLSL (float; ES 3.00 and 4.50).
//
// GENERATED FILE: DO NOT EDIT. Regenerate with
//     skelconv-codegen --inverse 1:16 --cauchy 1:16 --compact 2:16 --weights 0:3 --polygon-inverse 3:12 --polygon-cauchy 3:12 --polygon-compact 4:12 --scalis-inverse 2:10 --scalis-cauchy 2:10 --scalis-compact 2:10 --out generated
// From: codegen/glsl_point_writer.cpp, the radial kernels of docs/mathematics.md sec. 1 as the
// traits of include/skelconv/kernels/ define them: f = w K(r) and
// grad f = w K'(r) (p - c) / r, r = |p - c| (skelconv/primitives/point.hpp).

#ifndef SKELCONV_POINT_INPUT
#define SKELCONV_POINT_INPUT
// The centre c, the query point p, the weight w and the kernel's
// parameters (those of skelconv::KernelSpec; each family reads its own):
// the degree i (inverse, cauchy, compact), the Cauchy sharpness s, the
// support radius R (compact, soft, wyvill, ferley), Ferley's coating
// thickness e, the Gaussian's a and b (K = b exp(-a r^2)).
struct PointInput {
  vec3 c;
  vec3 p;
  float w;
  float i;
  float s;
  float R;
  float e;
  float a;
  float b;
};

// x^n for an integer n >= 0 by binary powering (exact for small n).
float skelconv_powi(float x, int n) {
  float result = 1.0;
  for (int k = n; k > 0; k >>= 1) {
    if ((k & 1) != 0) result *= x;
    x *= x;
  }
  return result;
}

// x^(n/2) for x >= 0 and an integer n >= 0: one square root at most.
float skelconv_half_power(float x, int n) {
  float result = skelconv_powi(x, n / 2);
  return (n % 2 != 0) ? result * sqrt(x) : result;
}
#endif

// inverse: K = r^(-i), K'(r)/r = -i r^(-i-2); +inf at the centre (the
// marker of skelconv/primitives/point.hpp).
float point_inverse_f(PointInput pt) {
  vec3 d = pt.p - pt.c;
  float u = dot(d, d);
  if (u == 0.0) return uintBitsToFloat(0x7f800000u);
  return pt.w / skelconv_half_power(u, int(pt.i));
}
float point_inverse_f_and_grad(PointInput pt, out vec3 grad) {
  vec3 d = pt.p - pt.c;
  float u = dot(d, d);
  float inf = uintBitsToFloat(0x7f800000u);
  grad = vec3(inf);
  if (u == 0.0) return inf;
  float f = pt.w / skelconv_half_power(u, int(pt.i));
  grad = (-pt.i * f / u) * d;
  return f;
}

// cauchy: K = (1 + s r^2)^(-i/2), K'(r)/r = -i s K / (1 + s r^2).
float point_cauchy_f(PointInput pt) {
  vec3 d = pt.p - pt.c;
  return pt.w / skelconv_half_power(1.0 + pt.s * dot(d, d), int(pt.i));
}
float point_cauchy_f_and_grad(PointInput pt, out vec3 grad) {
  vec3 d = pt.p - pt.c;
  float q = 1.0 + pt.s * dot(d, d);
  float f = pt.w / skelconv_half_power(q, int(pt.i));
  grad = (-pt.i * pt.s * f / q) * d;
  return f;
}

// compact: K = v^(i/2), v = 1 - r^2/R^2, for r < R (else 0);
// K'(r)/r = -i v^((i-2)/2) / R^2 (i >= 2).
float point_compact_f(PointInput pt) {
  vec3 d = pt.p - pt.c;
  float v = 1.0 - dot(d, d) / (pt.R * pt.R);
  return v > 0.0 ? pt.w * skelconv_half_power(v, int(pt.i)) : 0.0;
}
float point_compact_f_and_grad(PointInput pt, out vec3 grad) {
  vec3 d = pt.p - pt.c;
  float v = 1.0 - dot(d, d) / (pt.R * pt.R);
  grad = vec3(0.0);
  if (!(v > 0.0)) return 0.0;
  grad = (-pt.w * pt.i * skelconv_half_power(v, int(pt.i) - 2) / (pt.R * pt.R)) * d;
  return pt.w * skelconv_half_power(v, int(pt.i));
}

// soft: K = v^2, v = 1 - r^2/R^2, for r < R; K'(r)/r = -4 v / R^2.
float point_soft_f(PointInput pt) {
  vec3 d = pt.p - pt.c;
  float v = 1.0 - dot(d, d) / (pt.R * pt.R);
  return v > 0.0 ? pt.w * v * v : 0.0;
}
float point_soft_f_and_grad(PointInput pt, out vec3 grad) {
  vec3 d = pt.p - pt.c;
  float v = 1.0 - dot(d, d) / (pt.R * pt.R);
  grad = vec3(0.0);
  if (!(v > 0.0)) return 0.0;
  grad = (-4.0 * pt.w * v / (pt.R * pt.R)) * d;
  return pt.w * v * v;
}

// wyvill: K = v^2 (5 + 4 v) / 9 (= 1 - 22/9 x + 17/9 x^2 - 4/9 x^3 with
// x = r^2/R^2 = 1 - v), for r < R; K'(r)/r = -2 v (10 + 12 v) / (9 R^2).
float point_wyvill_f(PointInput pt) {
  vec3 d = pt.p - pt.c;
  float v = 1.0 - dot(d, d) / (pt.R * pt.R);
  return v > 0.0 ? pt.w * v * v * (5.0 + 4.0 * v) / 9.0 : 0.0;
}
float point_wyvill_f_and_grad(PointInput pt, out vec3 grad) {
  vec3 d = pt.p - pt.c;
  float v = 1.0 - dot(d, d) / (pt.R * pt.R);
  grad = vec3(0.0);
  if (!(v > 0.0)) return 0.0;
  grad = (-2.0 * pt.w * v * (10.0 + 12.0 * v) / (9.0 * pt.R * pt.R)) * d;
  return pt.w * v * v * (5.0 + 4.0 * v) / 9.0;
}

// ferley: K = 1 + k (e - r) for r < e, (r - R)^2 / (e - R)^2 for
// e <= r < R, else 0, k = 2/(R - e) (C^1 at e; skelconv/kernels/ferley.hpp);
// K'(r) = -k, then 2 (r - R) / (e - R)^2. grad 0 at the centre (the
// average of the one-sided slopes).
float point_ferley_f(PointInput pt) {
  float r = length(pt.p - pt.c);
  if (!(r < pt.R)) return 0.0;
  if (r < pt.e) return pt.w * (1.0 + 2.0 * (pt.e - r) / (pt.R - pt.e));
  float x = (r - pt.R) / (pt.e - pt.R);
  return pt.w * x * x;
}
float point_ferley_f_and_grad(PointInput pt, out vec3 grad) {
  vec3 d = pt.p - pt.c;
  float r = length(d);
  grad = vec3(0.0);
  if (!(r < pt.R)) return 0.0;
  float slope = r < pt.e ? -2.0 / (pt.R - pt.e) : 2.0 * (r - pt.R) / ((pt.e - pt.R) * (pt.e - pt.R));
  if (r > 0.0) grad = (pt.w * slope / r) * d;
  return point_ferley_f(pt);
}

// gaussian: K = b exp(-a r^2), K'(r)/r = -2 a K.
float point_gaussian_f(PointInput pt) {
  vec3 d = pt.p - pt.c;
  return pt.w * pt.b * exp(-pt.a * dot(d, d));
}
float point_gaussian_f_and_grad(PointInput pt, out vec3 grad) {
  vec3 d = pt.p - pt.c;
  float f = pt.w * pt.b * exp(-pt.a * dot(d, d));
  grad = (-2.0 * pt.a * f) * d;
  return f;
}
