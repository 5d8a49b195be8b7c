// src/view/view_march.glsl - the fragment shader of `skelconv view`
// (docs/view.md): ray marching of the surface f = iso of a sum of segment
// primitives, shaded with grad f.
//
// skelconv view (src/view/view_page.cpp) fills the three markers below: the
// kernels of generated/glsl/ the skeleton uses, the functions that dispatch
// on a kernel index, and the primitive count. Everything is in the page's
// frame: the skeleton translated to its box centre and divided by a power of
// two (view_page.hpp), which keeps float far from overflow and underflow.
//
// Primitive k is row k of u_primitives (RGBA32F, 4 texels wide):
//   texel 0: A.xyz, kernel index (kernel_f below)
//   texel 1: B.xyz, the family: 0 inverse, 1 compact, 2 Cauchy
//   texel 2: w0 .. w3, the weight polynomial
//   texel 3: s, R, c (its weight in the sum, 0 when toggled off), then the
//            degree i (inverse, Cauchy) or the Lipschitz bound c L (compact)

//@@KERNELS@@

//@@DISPATCH@@

const int primitive_count = /*@@PRIMITIVE_COUNT@@*/1;
// Most marching steps per ray, and bisection steps on a crossing. Near the
// surface a step covers a fixed fraction of the gap (a third for an inverse
// segment, less for compact terms, whose Lipschitz bound is global), so rays
// that run out are grazing ones.
const int max_steps = 512;
const int bisection_steps = 14;

uniform highp sampler2D u_primitives;
uniform vec3 u_eye;
uniform vec3 u_right;     // camera basis, unit vectors
uniform vec3 u_up;
uniform vec3 u_forward;
uniform float u_tan_half_fov;
uniform vec2 u_resolution;
uniform float u_iso;
uniform vec3 u_centre;    // the bounding sphere: f < iso outside it
uniform float u_radius;
uniform float u_min_step; // floor of the step, so that every ray ends
out vec4 colour;

// The field at p and what the step bound needs (safe_step).
struct Probe {
  float f;          // the sum
  float f_ratio;    // its inverse and Cauchy part
  float d_inverse;  // the least distance from p to the inverse segments
  float i_inverse;  // their largest degree
  float d_cauchy;   // the same for the Cauchy segments
  float i_cauchy;
  float s_cauchy;   // their largest s
  float lip_near;   // sum of c L of the compact segments whose support holds p
  float lip_far;    // the same for the others
  float gap_far;    // the least distance from p to the support of those
};

SegmentInput segment_input(int k, vec3 p, out vec4 t0, out vec4 t1, out vec4 t3, out float dist) {
  t0 = texelFetch(u_primitives, ivec2(0, k), 0);
  t1 = texelFetch(u_primitives, ivec2(1, k), 0);
  vec4 t2 = texelFetch(u_primitives, ivec2(2, k), 0);
  t3 = texelFetch(u_primitives, ivec2(3, k), 0);
  SegmentInput si;
  si.a = t0.xyz;
  si.b = t1.xyz;
  si.p = p;
  si.w = t2;
  si.s = t3.x;
  si.R = t3.y;
  si.t0 = 0.0;
  si.t1 = 1.0;
  vec3 ab = si.b - si.a;
  vec3 ap = p - si.a;
  float ab_ab = dot(ab, ab);
  float t = clamp(dot(ab, ap) / ab_ab, 0.0, 1.0);
  dist = length(ap - t * ab);
  if (t1.w == 1.0) {
    // The part of AB inside the ball of radius R around p, as
    // skelconv/detail/clip.hpp: the discriminant from the cross product.
    vec3 c = cross(ab, ap);
    float disc = ab_ab * si.R * si.R - dot(c, c);
    float centre = dot(ab, ap) / ab_ab;
    float half_width = disc > 0.0 ? sqrt(disc) / ab_ab : 0.0;
    si.t0 = max(0.0, centre - half_width);
    si.t1 = min(1.0, centre + half_width);
  }
  return si;
}

// Beyond an end of its segment (the projection of p outside [0, 1]) an
// inverse or Cauchy term is integrated here rather than by its generated
// generic form: in float those lose digits there, most near the segment's
// line (0/0 on it; docs/view.md, tests/glsl/probe_beyond_end.py), as the
// C++ target's stable forms avoid with a Gauss rule too. The integrand
// w(t) K(|p - G(t)|) is smooth there: with s the distance along AB from the
// nearer end in units of |AB| and rho = |p - end| / |AB|, panels
// [s_k, s_k+1] of width s_k + rho (at most the distance to p, so the
// nearest complex singularity of the integrand is a panel width away) and
// 8 Gauss-Legendre nodes each keep the rule's error below float's.
const float gauss_x[8] = float[8](0.019855072, 0.101666761, 0.237233795, 0.408282679,
                                  0.591717321, 0.762766205, 0.898333239, 0.980144928);
const float gauss_w[8] = float[8](0.050614268, 0.111190517, 0.156853323, 0.181341892,
                                  0.181341892, 0.156853323, 0.111190517, 0.050614268);
// More panels than this only for p within 2^-20 |AB| of an end (deep inside
// any surface): the last panel then stretches to the far end.
const int max_panels = 20;

bool beyond_end(SegmentInput si) {
  vec3 ab = si.b - si.a;
  float t = dot(si.p - si.a, ab) / dot(ab, ab);
  return t < 0.0 || t > 1.0;
}

// f (and grad f) of an inverse (family 0) or Cauchy (family 2) term of
// degree i at a point beyond an end: K = base^(-i/2) with base = r^2 or
// 1 + s r^2, so grad K = -i alpha K / base (p - G(t)), alpha = 1 or s.
float segment_by_quadrature(SegmentInput si, float family, float degree, out vec3 grad) {
  vec3 ab = si.b - si.a;
  float length_ab = length(ab);
  bool at_b = dot(si.p - si.a, ab) > 0.0;
  float end = at_b ? 1.0 : 0.0, direction = at_b ? -1.0 : 1.0;
  float rho = length(si.p - (at_b ? si.b : si.a)) / length_ab;
  float alpha = family == 0.0 ? 1.0 : si.s;
  float offset = family == 0.0 ? 0.0 : 1.0;
  float f = 0.0;
  grad = vec3(0.0);
  float low = 0.0;
  for (int k = 0; k < max_panels && low < 1.0; ++k) {
    float high = k == max_panels - 1 ? 1.0 : min(1.0, 2.0 * low + rho);
    for (int j = 0; j < 8; ++j) {
      float t = end + direction * (low + (high - low) * gauss_x[j]);
      vec3 d = si.p - (si.a + t * ab);
      float base = offset + alpha * dot(d, d);
      float kernel = pow(base, -0.5 * degree);
      float weight = (high - low) * gauss_w[j] * (si.w.x + t * (si.w.y + t * (si.w.z + t * si.w.w)));
      f += weight * kernel;
      grad += (weight * kernel / base) * d;
    }
    low = high;
  }
  grad *= -degree * alpha * length_ab;
  return f * length_ab;
}

// One term c f_k (and its gradient when `with_grad`): the generated kernel,
// or the quadrature beyond an end for inverse and Cauchy kernels.
float term(int kernel, float family, float degree, SegmentInput si, bool with_grad, out vec3 grad) {
  grad = vec3(0.0);
  if (family != 1.0 && beyond_end(si)) return segment_by_quadrature(si, family, degree, grad);
  if (with_grad) return kernel_f_and_grad(kernel, si, grad);
  return kernel_f(kernel, si);
}

Probe probe(vec3 p) {
  Probe pr = Probe(0.0, 0.0, 1e30, 0.0, 1e30, 0.0, 0.0, 0.0, 0.0, 1e30);
  for (int k = 0; k < primitive_count; ++k) {
    vec4 t0, t1, t3;
    float dist;
    SegmentInput si = segment_input(k, p, t0, t1, t3, dist);
    float c = t3.z;
    if (c == 0.0) continue;
    if (t1.w == 1.0) {
      if (dist < si.R) {
        pr.lip_near += t3.w;
        if (si.t0 < si.t1) pr.f += c * kernel_f(int(t0.w), si);
      } else {
        pr.lip_far += t3.w;
        pr.gap_far = min(pr.gap_far, dist - si.R);
      }
    } else {
      vec3 unused;
      float fk = c * term(int(t0.w), t1.w, t3.w, si, false, unused);
      pr.f += fk;
      pr.f_ratio += fk;
      if (t1.w == 0.0) {
        pr.d_inverse = min(pr.d_inverse, dist);
        pr.i_inverse = max(pr.i_inverse, t3.w);
      } else {
        pr.d_cauchy = min(pr.d_cauchy, dist);
        pr.i_cauchy = max(pr.i_cauchy, t3.w);
        pr.s_cauchy = max(pr.s_cauchy, si.s);
      }
    }
  }
  return pr;
}

// A step that cannot cross the surface (docs/view.md). The margin
// m = iso - f(p) > 0 is shared equally between the kinds of terms present
// (a share m_k each), and along any move of length delta
//   - the inverse and Cauchy terms together grow by at most the factor
//     q = 1 + m_k / f_ratio when every term does: an inverse term grows at
//     most by (d/(d - delta))^i, d the distance to its segment
//     (K(r - delta)/K(r) <= (r/(r - delta))^i, w >= 0), so delta <=
//     d (1 - q^(-1/i)) will do; a Cauchy term by that too, or by
//     sup_r ((1 + s r^2)/(1 + s (r - delta)^2))^(i/2) <= q, which holds for
//     every r when delta <= (Q - 1)/sqrt(s Q), Q = q^(2/i) (the quadratic in
//     r has no root): either bound will do, the larger is taken;
//   - a compact term whose support holds p grows at most by c L delta;
//   - the other compact terms stay 0 until delta passes their gap, then grow
//     by at most c L per unit length.
// The largest degree and s and the least distance of a family stand for all
// its terms (each bound decreases in i and s and increases in d).
float safe_step(Probe pr) {
  float kinds = (pr.f_ratio > 0.0 ? 1.0 : 0.0) + (pr.lip_near > 0.0 ? 1.0 : 0.0) + (pr.lip_far > 0.0 ? 1.0 : 0.0);
  float share = (u_iso - pr.f) / max(kinds, 1.0);
  float step = 1e30;
  if (pr.f_ratio > 0.0) {
    float q = 1.0 + share / pr.f_ratio;
    if (pr.i_inverse > 0.0) step = pr.d_inverse * (1.0 - pow(q, -1.0 / pr.i_inverse));
    if (pr.i_cauchy > 0.0) {
      float Q = pow(q, 2.0 / pr.i_cauchy);
      float any_r = (Q - 1.0) / sqrt(pr.s_cauchy * Q);
      step = min(step, max(any_r, pr.d_cauchy * (1.0 - pow(q, -1.0 / pr.i_cauchy))));
    }
  }
  if (pr.lip_near > 0.0) step = min(step, share / pr.lip_near);
  if (pr.lip_far > 0.0) step = min(step, pr.gap_far + share / pr.lip_far);
  return step;
}

float field(vec3 p) { return probe(p).f; }

vec3 field_gradient(vec3 p) {
  vec3 total = vec3(0.0);
  for (int k = 0; k < primitive_count; ++k) {
    vec4 t0, t1, t3;
    float dist;
    SegmentInput si = segment_input(k, p, t0, t1, t3, dist);
    if (t3.z == 0.0) continue;
    if (t1.w == 1.0 && !(si.t0 < si.t1)) continue;
    vec3 g;
    if (t1.w == 1.0) kernel_f_and_grad(int(t0.w), si, g);
    else term(int(t0.w), t1.w, t3.w, si, true, g);
    total += t3.z * g;
  }
  return total;
}

vec3 shade(vec3 p, vec3 rd) {
  vec3 g = field_gradient(p);
  vec3 n = length(g) > 0.0 ? -normalize(g) : -rd;
  vec3 light = normalize(u_up + 0.6 * u_right - 0.8 * u_forward);
  float diffuse = max(dot(n, light), 0.0);
  float rim = pow(1.0 - max(dot(n, -rd), 0.0), 3.0);
  float specular = pow(max(dot(reflect(-light, n), -rd), 0.0), 40.0);
  vec3 base = vec3(0.80, 0.55, 0.35);
  return base * (0.18 + 0.82 * diffuse) + 0.25 * specular + 0.15 * rim;
}

void main() {
  vec2 ndc = (2.0 * gl_FragCoord.xy - u_resolution) / u_resolution.y;
  vec3 rd = normalize(u_forward + u_tan_half_fov * (ndc.x * u_right + ndc.y * u_up));
  colour = vec4(1.0, 1.0, 1.0, 1.0);
  // The ray against the bounding sphere.
  vec3 oc = u_eye - u_centre;
  float b = dot(oc, rd);
  float disc = b * b - (dot(oc, oc) - u_radius * u_radius);
  if (disc <= 0.0) return;
  float t_far = -b + sqrt(disc);
  float t = max(-b - sqrt(disc), 0.0);
  if (t_far <= t) return;
  float t_prev = t;
  for (int step = 0; step < max_steps; ++step) {
    Probe pr = probe(u_eye + t * rd);
    if (pr.f >= u_iso) {
      // Crossed between t_prev and t: bisection on f - iso.
      float lo = t_prev, hi = t;
      for (int j = 0; j < bisection_steps; ++j) {
        float mid = 0.5 * (lo + hi);
        if (field(u_eye + mid * rd) >= u_iso) hi = mid; else lo = mid;
      }
      colour = vec4(shade(u_eye + hi * rd, rd), 1.0);
      return;
    }
    float s = safe_step(pr);
    // A NaN (float failing in a generic form) gives the floor step.
    if (!(s >= u_min_step)) s = u_min_step;
    t_prev = t;
    t += s;
    if (t > t_far) return;
  }
}
