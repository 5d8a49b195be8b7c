// generated/glsl/scalis_segment_cauchy.glsl - SCALIS segment kernels of the cauchy family in GLSL (float; ES 3.00 and 4.50), by a Gauss-Legendre rule.
//
// GENERATED FILE: DO NOT EDIT. Regenerate with
//     skelconv-codegen --inverse 1:16 --cauchy 1:16 --compact 2:16 --weights 0:3 --polygon-inverse 3:12 --polygon-cauchy 3:12 --polygon-compact 4:12 --scalis-inverse 2:10 --scalis-cauchy 2:10 --scalis-compact 2:10 --out generated
// Generator: skelconv-codegen 0.1.0 (GiNaC 1.8.6)
// From: codegen/segment_families.cpp (the families) and codegen/segment_moments.cpp
// (recurrence (1) of Hubert & Cani unrolled; docs/mathematics.md sec. 2, Hubert 2012 sec. 3).
// Unnormalised, as generated/scalis_segment_cauchy.hpp: f = c F / h is the caller's
// (skelconv/primitives/scalis_segment.hpp).

#ifndef SKELCONV_SCALIS_SEGMENT_INPUT
#define SKELCONV_SCALIS_SEGMENT_INPUT
// The segment AB, the query point p, the radii tau0 at A and tau1 at B
// (>= 0, not both 0) and the kernel scale sigma (docs/mathematics.md sec. 4).
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
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-2/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^2 |AB| int_0^1 tau^1 (|P - Gamma|^2 + sigma^2tau^2)^(-2/2) dt; docs/mathematics.md sec. 4, Zanni 2013 eq. 13, Table 3]
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float scalis_segment_cauchy_i2_f(ScalisSegmentInput si) {
  vec3 grad;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(skelconv_rule_power(si.sigma, -4), 0.0, 0.0, 0.0), si.tau0, si.tau1, 1, 1.0, 0.0, si.sigma * si.sigma, 2, 0.0, 1.0, grad);
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-2/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^2 |AB| int_0^1 tau^1 (|P - Gamma|^2 + sigma^2tau^2)^(-2/2) dt; docs/mathematics.md sec. 4, Zanni 2013 eq. 13, Table 3]
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float scalis_segment_cauchy_i2_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(skelconv_rule_power(si.sigma, -4), 0.0, 0.0, 0.0), si.tau0, si.tau1, 1, 1.0, 0.0, si.sigma * si.sigma, 2, 0.0, 1.0, grad);
}

// the field, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-3/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^3 |AB| int_0^1 tau^2 (|P - Gamma|^2 + sigma^2tau^2)^(-3/2) dt; docs/mathematics.md sec. 4, Zanni 2013 eq. 13, Table 3]
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float scalis_segment_cauchy_i3_f(ScalisSegmentInput si) {
  vec3 grad;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(skelconv_rule_power(si.sigma, -6), 0.0, 0.0, 0.0), si.tau0, si.tau1, 2, 1.0, 0.0, si.sigma * si.sigma, 3, 0.0, 1.0, grad);
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-3/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^3 |AB| int_0^1 tau^2 (|P - Gamma|^2 + sigma^2tau^2)^(-3/2) dt; docs/mathematics.md sec. 4, Zanni 2013 eq. 13, Table 3]
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float scalis_segment_cauchy_i3_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(skelconv_rule_power(si.sigma, -6), 0.0, 0.0, 0.0), si.tau0, si.tau1, 2, 1.0, 0.0, si.sigma * si.sigma, 3, 0.0, 1.0, grad);
}

// the field, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-4/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^4 |AB| int_0^1 tau^3 (|P - Gamma|^2 + sigma^2tau^2)^(-4/2) dt; docs/mathematics.md sec. 4, Zanni 2013 eq. 13, Table 3]
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float scalis_segment_cauchy_i4_f(ScalisSegmentInput si) {
  vec3 grad;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(skelconv_rule_power(si.sigma, -8), 0.0, 0.0, 0.0), si.tau0, si.tau1, 3, 1.0, 0.0, si.sigma * si.sigma, 4, 0.0, 1.0, grad);
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-4/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^4 |AB| int_0^1 tau^3 (|P - Gamma|^2 + sigma^2tau^2)^(-4/2) dt; docs/mathematics.md sec. 4, Zanni 2013 eq. 13, Table 3]
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float scalis_segment_cauchy_i4_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(skelconv_rule_power(si.sigma, -8), 0.0, 0.0, 0.0), si.tau0, si.tau1, 3, 1.0, 0.0, si.sigma * si.sigma, 4, 0.0, 1.0, grad);
}

// the field, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-5/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^5 |AB| int_0^1 tau^4 (|P - Gamma|^2 + sigma^2tau^2)^(-5/2) dt; docs/mathematics.md sec. 4, Zanni 2013 eq. 13, Table 3]
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float scalis_segment_cauchy_i5_f(ScalisSegmentInput si) {
  vec3 grad;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(skelconv_rule_power(si.sigma, -10), 0.0, 0.0, 0.0), si.tau0, si.tau1, 4, 1.0, 0.0, si.sigma * si.sigma, 5, 0.0, 1.0, grad);
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-5/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^5 |AB| int_0^1 tau^4 (|P - Gamma|^2 + sigma^2tau^2)^(-5/2) dt; docs/mathematics.md sec. 4, Zanni 2013 eq. 13, Table 3]
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float scalis_segment_cauchy_i5_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(skelconv_rule_power(si.sigma, -10), 0.0, 0.0, 0.0), si.tau0, si.tau1, 4, 1.0, 0.0, si.sigma * si.sigma, 5, 0.0, 1.0, grad);
}

// the field, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-6/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^6 |AB| int_0^1 tau^5 (|P - Gamma|^2 + sigma^2tau^2)^(-6/2) dt; docs/mathematics.md sec. 4, Zanni 2013 eq. 13, Table 3]
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float scalis_segment_cauchy_i6_f(ScalisSegmentInput si) {
  vec3 grad;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(skelconv_rule_power(si.sigma, -12), 0.0, 0.0, 0.0), si.tau0, si.tau1, 5, 1.0, 0.0, si.sigma * si.sigma, 6, 0.0, 1.0, grad);
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-6/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^6 |AB| int_0^1 tau^5 (|P - Gamma|^2 + sigma^2tau^2)^(-6/2) dt; docs/mathematics.md sec. 4, Zanni 2013 eq. 13, Table 3]
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float scalis_segment_cauchy_i6_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(skelconv_rule_power(si.sigma, -12), 0.0, 0.0, 0.0), si.tau0, si.tau1, 5, 1.0, 0.0, si.sigma * si.sigma, 6, 0.0, 1.0, grad);
}

// the field, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-7/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^7 |AB| int_0^1 tau^6 (|P - Gamma|^2 + sigma^2tau^2)^(-7/2) dt; docs/mathematics.md sec. 4, Zanni 2013 eq. 13, Table 3]
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float scalis_segment_cauchy_i7_f(ScalisSegmentInput si) {
  vec3 grad;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(skelconv_rule_power(si.sigma, -14), 0.0, 0.0, 0.0), si.tau0, si.tau1, 6, 1.0, 0.0, si.sigma * si.sigma, 7, 0.0, 1.0, grad);
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-7/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^7 |AB| int_0^1 tau^6 (|P - Gamma|^2 + sigma^2tau^2)^(-7/2) dt; docs/mathematics.md sec. 4, Zanni 2013 eq. 13, Table 3]
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float scalis_segment_cauchy_i7_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(skelconv_rule_power(si.sigma, -14), 0.0, 0.0, 0.0), si.tau0, si.tau1, 6, 1.0, 0.0, si.sigma * si.sigma, 7, 0.0, 1.0, grad);
}

// the field, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-8/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^8 |AB| int_0^1 tau^7 (|P - Gamma|^2 + sigma^2tau^2)^(-8/2) dt; docs/mathematics.md sec. 4, Zanni 2013 eq. 13, Table 3]
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float scalis_segment_cauchy_i8_f(ScalisSegmentInput si) {
  vec3 grad;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(skelconv_rule_power(si.sigma, -16), 0.0, 0.0, 0.0), si.tau0, si.tau1, 7, 1.0, 0.0, si.sigma * si.sigma, 8, 0.0, 1.0, grad);
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-8/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^8 |AB| int_0^1 tau^7 (|P - Gamma|^2 + sigma^2tau^2)^(-8/2) dt; docs/mathematics.md sec. 4, Zanni 2013 eq. 13, Table 3]
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float scalis_segment_cauchy_i8_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(skelconv_rule_power(si.sigma, -16), 0.0, 0.0, 0.0), si.tau0, si.tau1, 7, 1.0, 0.0, si.sigma * si.sigma, 8, 0.0, 1.0, grad);
}

// the field, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-9/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^9 |AB| int_0^1 tau^8 (|P - Gamma|^2 + sigma^2tau^2)^(-9/2) dt; docs/mathematics.md sec. 4, Zanni 2013 eq. 13, Table 3]
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float scalis_segment_cauchy_i9_f(ScalisSegmentInput si) {
  vec3 grad;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(skelconv_rule_power(si.sigma, -18), 0.0, 0.0, 0.0), si.tau0, si.tau1, 8, 1.0, 0.0, si.sigma * si.sigma, 9, 0.0, 1.0, grad);
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-9/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^9 |AB| int_0^1 tau^8 (|P - Gamma|^2 + sigma^2tau^2)^(-9/2) dt; docs/mathematics.md sec. 4, Zanni 2013 eq. 13, Table 3]
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float scalis_segment_cauchy_i9_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(skelconv_rule_power(si.sigma, -18), 0.0, 0.0, 0.0), si.tau0, si.tau1, 8, 1.0, 0.0, si.sigma * si.sigma, 9, 0.0, 1.0, grad);
}

// the field, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-10/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^10 |AB| int_0^1 tau^9 (|P - Gamma|^2 + sigma^2tau^2)^(-10/2) dt; docs/mathematics.md sec. 4, Zanni 2013 eq. 13, Table 3]
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float scalis_segment_cauchy_i10_f(ScalisSegmentInput si) {
  vec3 grad;
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(skelconv_rule_power(si.sigma, -20), 0.0, 0.0, 0.0), si.tau0, si.tau1, 9, 1.0, 0.0, si.sigma * si.sigma, 10, 0.0, 1.0, grad);
}

// the field and its gradient, where
//     F(P) = int_0^1 K(|P - Gamma(t)|/tau(t)) |AB| dt/tau(t), K(d) = (1 + (d/sigma)^2)^(-10/2), tau(t) = tau0 + (tau1 - tau0) t  [= sigma^10 |AB| int_0^1 tau^9 (|P - Gamma|^2 + sigma^2tau^2)^(-10/2) dt; docs/mathematics.md sec. 4, Zanni 2013 eq. 13, Table 3]
// Form: the definition integral by skelconv_segment_rule (24 nodes per side).
float scalis_segment_cauchy_i10_f_and_grad(ScalisSegmentInput si, out vec3 grad) {
  return skelconv_segment_rule(si.a, si.b, si.p, vec4(skelconv_rule_power(si.sigma, -20), 0.0, 0.0, 0.0), si.tau0, si.tau1, 9, 1.0, 0.0, si.sigma * si.sigma, 10, 0.0, 1.0, grad);
}

