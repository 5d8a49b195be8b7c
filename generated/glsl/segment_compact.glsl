// generated/glsl/segment_compact.glsl - segment kernels of the compact family in GLSL (float; ES 3.00 and 4.50), by a Gauss-Legendre rule.
//
// GENERATED FILE: DO NOT EDIT. Regenerate with
//     skelconv-codegen --inverse 1:16 --cauchy 1:16 --compact 2:16 --weights 0:3 --polygon-inverse 3:12 --polygon-cauchy 3:12 --polygon-compact 4:12 --scalis-inverse 2:10 --scalis-cauchy 2:10 --scalis-compact 2:10 --out generated
// Generator: skelconv-codegen 0.1.0 (GiNaC 1.8.6)
// From: codegen/segment_families.cpp (the families) and codegen/segment_moments.cpp
// (recurrence (1) of Hubert & Cani unrolled; docs/mathematics.md sec. 2, Hubert 2012 sec. 3).

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

#ifndef SKELCONV_SEGMENT_RULE
#define SKELCONV_SEGMENT_RULE
// f = |AB| int_lo^hi v(t) q(t)^(-n/2) dt and grad f = -n alpha |AB| int_lo^hi
// v(t) q(t)^(-n/2-1) (p - G(t)) dt, G(t) = a + t (b - a), where
//   v(t) = (w0 + w1 t + w2 t^2 + w3 t^3) tau(t)^m, tau(t) = tau0 (1 - t) + tau1 t,
//   q(t) = alpha |p - G(t)|^2 + beta + gamma tau(t)^2,
// by a Gauss-Legendre rule of 24 nodes on each side of the point of [lo, hi]
// nearest to the roots of q, in the variable s = h sinh(u) (n > 0; s itself
// where the side is shorter than h), or of 24 nodes on [lo, hi] after
// t = mid + half sin(pi x / 2) (n < 0, compact).
// Why this rule and how accurate: codegen/glsl_rule.cpp, docs/view.md.
const float skelconv_rule_x[12] = float[12](0.064056893, 0.191118867, 0.315042680, 0.433793508,
    0.545421471, 0.648093652, 0.740124192, 0.820001986, 0.886415527, 0.938274552, 0.974728556, 0.995187220);
const float skelconv_rule_w[12] = float[12](0.127938195, 0.125837456, 0.121670473, 0.115505668,
    0.107444270, 0.097618652, 0.086190162, 0.073346481, 0.059298585, 0.044277439, 0.028531389, 0.012341230);
// The same after the sine map: sin(pi x / 2) and w (pi / 2) cos(pi x / 2)
// (tabulated: GLSL's sin and cos are only required to be within 2^-11).
const float skelconv_rule_sine_x[12] = float[12](0.100450630, 0.295719689, 0.474915389, 0.629881979,
    0.755715552, 0.851071730, 0.917832084, 0.960294556, 0.984125673, 0.995303244, 0.999212206, 0.999971424);
const float skelconv_rule_sine_w[12] = float[12](1.999483759e-01, 1.888243989e-01, 1.681912010e-01,
    1.409195891e-01, 1.105294795e-01, 8.051056606e-02, 5.374449648e-02, 3.214288518e-02, 1.653089819e-02,
    6.732956754e-03, 1.778601508e-03, 1.465514320e-04);

// q^(-n/2) for an integer n and q >= 0 (n < 0: q^(|n|/2)): binary powering
// of 1/q or q, one square root for odd n.
float skelconv_rule_power(float q, int n) {
  float x = n > 0 ? 1.0 / q : q;
  int k = n > 0 ? n : -n;
  float result = k % 2 != 0 ? sqrt(x) : 1.0;
  for (k /= 2; k > 0; k /= 2) {
    if (k % 2 != 0) result *= x;
    x *= x;
  }
  return result;
}

// One node: t = c + s, d = p - G(t) = cp - s ab (cp = p - G(c)), weight g
// (dt/dx included); adds g v q^(-n/2) to f and g v q^(-n/2-1) d to gsum.
void skelconv_rule_node(vec3 cp, vec3 ab, float c, float s, float g, vec4 w, float tau0, float tau1, int m,
                        float alpha, float beta, float gamma, int n, inout float f, inout vec3 gsum) {
  float t = c + s;
  vec3 d = cp - s * ab;
  float tau = tau0 * (1.0 - t) + tau1 * t;
  float q = alpha * dot(d, d) + beta + gamma * tau * tau;
  float v = g * (w[0] + t * (w[1] + t * (w[2] + t * w[3])));
  for (int k = 0; k < m; ++k) v *= tau;
  f += v * skelconv_rule_power(q, n);
  gsum += (v * skelconv_rule_power(q, n + 2)) * d;
}

float skelconv_segment_rule(vec3 a, vec3 b, vec3 p, vec4 w, float tau0, float tau1, int m, float alpha,
                            float beta, float gamma, int n, float lo, float hi, out vec3 grad) {
  vec3 ab = b - a;
  vec3 ap = p - a;
  float f = 0.0;
  vec3 gsum = vec3(0.0);
  if (n < 0) {
    float mid = 0.5 * (lo + hi);
    float half_width = 0.5 * (hi - lo);
    vec3 mp = ap - mid * ab;
    for (int j = 0; j < 12; ++j) {
      for (int side = -1; side <= 1; side += 2) {
        float s = float(side) * half_width * skelconv_rule_sine_x[j];
        skelconv_rule_node(mp, ab, mid, s, half_width * skelconv_rule_sine_w[j], w, tau0, tau1, m, alpha, beta, gamma,
                           n, f, gsum);
      }
    }
  } else {
    // q = qa t^2 - 2 qb t + qc; qa qc - qb^2 as a sum of non-negative terms.
    float dtau = tau1 - tau0;
    float qa = alpha * dot(ab, ab) + gamma * dtau * dtau;
    float qb = alpha * dot(ab, ap) - gamma * tau0 * dtau;
    vec3 c1 = cross(ab, ap);
    vec3 c2 = tau0 * ab + dtau * ap;
    float disc = alpha * alpha * dot(c1, c1) + beta * qa + alpha * gamma * dot(c2, c2);
    float centre = qb / qa;
    float c = clamp(centre, lo, hi);
    float y = sqrt(disc) / qa;
    float h = max(sqrt((centre - c) * (centre - c) + y * y), 1e-20);
    vec3 cp = c <= 0.0 ? ap : (c >= 1.0 ? p - b : ap - c * ab);
    for (int side = -1; side <= 1; side += 2) {
      float span = side < 0 ? c - lo : hi - c;
      if (!(span > 0.0)) continue;
      // The roots at least the side's length away: no map (GLSL's log,
      // sinh and cosh are only required to be accurate to ~2^-21 absolute
      // near 0, too little for a relative 1e-6). Else u_max >= asinh(1).
      bool linear = span <= h;
      float u_max = linear ? span : skelconv_asinh(span / h);
      for (int j = 0; j < 12; ++j) {
        for (int k = -1; k <= 1; k += 2) {
          float u = 0.5 * u_max * (1.0 + float(k) * skelconv_rule_x[j]);
          float s = linear ? u : h * sinh(u);
          float g = 0.5 * u_max * (linear ? 1.0 : h * cosh(u)) * skelconv_rule_w[j];
          skelconv_rule_node(cp, ab, c, float(side) * s, g, w, tau0, tau1, m, alpha, beta, gamma, n, f, gsum);
        }
      }
    }
  }
  float length_ab = length(ab);
  grad = (-float(n) * alpha * length_ab) * gsum;
  return length_ab * f;
}
#endif

// the field, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(2/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i2_w0_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -2, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(2/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i2_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -2, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(2/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i2_w1_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -2, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(2/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i2_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -2, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(2/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i2_w2_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -2, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(2/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i2_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -2, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(2/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i2_w3_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -2, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(2/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i2_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -2, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(3/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i3_w0_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -3, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(3/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i3_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -3, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(3/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i3_w1_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -3, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(3/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i3_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -3, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(3/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i3_w2_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -3, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(3/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i3_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -3, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(3/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i3_w3_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -3, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(3/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i3_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -3, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(4/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i4_w0_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -4, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(4/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i4_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -4, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(4/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i4_w1_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -4, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(4/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i4_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -4, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(4/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i4_w2_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -4, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(4/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i4_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -4, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(4/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i4_w3_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -4, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(4/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i4_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -4, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(5/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i5_w0_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -5, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(5/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i5_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -5, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(5/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i5_w1_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -5, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(5/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i5_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -5, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(5/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i5_w2_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -5, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(5/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i5_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -5, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(5/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i5_w3_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -5, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(5/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i5_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -5, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(6/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i6_w0_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -6, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(6/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i6_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -6, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(6/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i6_w1_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -6, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(6/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i6_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -6, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(6/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i6_w2_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -6, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(6/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i6_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -6, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(6/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i6_w3_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -6, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(6/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i6_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -6, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(7/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i7_w0_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -7, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(7/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i7_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -7, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(7/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i7_w1_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -7, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(7/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i7_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -7, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(7/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i7_w2_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -7, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(7/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i7_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -7, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(7/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i7_w3_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -7, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(7/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i7_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -7, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(8/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i8_w0_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -8, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(8/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i8_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -8, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(8/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i8_w1_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -8, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(8/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i8_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -8, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(8/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i8_w2_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -8, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(8/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i8_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -8, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(8/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i8_w3_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -8, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(8/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i8_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -8, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(9/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i9_w0_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -9, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(9/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i9_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -9, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(9/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i9_w1_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -9, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(9/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i9_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -9, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(9/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i9_w2_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -9, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(9/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i9_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -9, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(9/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i9_w3_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -9, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(9/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i9_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -9, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(10/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i10_w0_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -10, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(10/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i10_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -10, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(10/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i10_w1_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -10, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(10/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i10_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -10, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(10/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i10_w2_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -10, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(10/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i10_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -10, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(10/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i10_w3_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -10, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(10/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i10_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -10, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(11/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i11_w0_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -11, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(11/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i11_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -11, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(11/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i11_w1_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -11, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(11/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i11_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -11, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(11/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i11_w2_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -11, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(11/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i11_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -11, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(11/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i11_w3_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -11, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(11/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i11_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -11, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(12/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i12_w0_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -12, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(12/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i12_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -12, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(12/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i12_w1_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -12, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(12/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i12_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -12, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(12/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i12_w2_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -12, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(12/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i12_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -12, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(12/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i12_w3_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -12, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(12/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i12_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -12, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(13/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i13_w0_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -13, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(13/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i13_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -13, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(13/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i13_w1_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -13, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(13/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i13_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -13, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(13/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i13_w2_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -13, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(13/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i13_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -13, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(13/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i13_w3_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -13, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(13/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i13_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -13, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(14/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i14_w0_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -14, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(14/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i14_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -14, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(14/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i14_w1_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -14, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(14/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i14_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -14, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(14/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i14_w2_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -14, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(14/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i14_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -14, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(14/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i14_w3_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -14, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(14/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i14_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -14, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(15/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i15_w0_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -15, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(15/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i15_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -15, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(15/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i15_w1_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -15, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(15/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i15_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -15, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(15/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i15_w2_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -15, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(15/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i15_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -15, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(15/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i15_w3_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -15, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(15/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i15_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -15, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(16/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i16_w0_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -16, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 w0 (1 - |P - Gamma(t)|^2/R^2)^(16/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i16_w0_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], 0.0, 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -16, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(16/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i16_w1_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -16, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t) (1 - |P - Gamma(t)|^2/R^2)^(16/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i16_w1_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], 0.0, 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -16, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(16/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i16_w2_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -16, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2) (1 - |P - Gamma(t)|^2/R^2)^(16/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i16_w2_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], 0.0), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -16, si.t0, si.t1, grad);
}

// the field, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(16/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i16_w3_f(SegmentInput si) {
  vec3 grad;
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -16, si.t0, si.t1, grad);
}

// the field and its gradient, where
//     f(P) = |AB| int_t0^t1 (w0 + w1 t + w2 t^2 + w3 t^3) (1 - |P - Gamma(t)|^2/R^2)^(16/2) dt
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float segment_compact_i16_w3_f_and_grad(SegmentInput si, out vec3 grad) {
  grad = vec3(0.0);
  if (!(si.t0 < si.t1)) return 0.0;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(si.w[0], si.w[1], si.w[2], si.w[3]), 1.0, 1.0, 0, -1.0 / (si.R * si.R), 1.0, 0.0, -16, si.t0, si.t1, grad);
}

