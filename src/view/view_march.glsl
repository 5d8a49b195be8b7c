// src/view/view_march.glsl - the fragment shader of `skelconv view`
// (docs/view.md): ray marching of the surface f = iso of a sum of segment,
// point and SCALIS segment primitives, shaded with grad f.
//
// skelconv view (src/view/view_page.cpp) fills the three markers below: the
// kernels of generated/glsl/ the skeleton uses, the functions that dispatch
// on a kernel index, and the primitive count. Everything is in the page's
// frame: the skeleton translated to its box centre and divided by a power of
// two (view_page.hpp), which keeps float far from overflow and underflow.
//
// Primitive k is row k of u_primitives (RGBA32F, 4 texels wide):
//   texel 0: A.xyz (a point's centre), kernel index (kernel_f below)
//   texel 1: B.xyz (= A for a point), the family code:
//            0 inverse segment, 1 compact segment, 2 Cauchy segment,
//            4 SCALIS inverse, 5 SCALIS Cauchy, 6 inverse point,
//            7 Cauchy point, 8 point with a support radius R (compact,
//            soft, wyvill, ferley), 9 Gaussian point
//   texel 2: segments: w0 .. w3, the weight polynomial; SCALIS: tau0, tau1,
//            sigma; points: the degree i, Ferley's e, the Gaussian's a, b
//   texel 3: s, R, c (its weight in the sum, 0 when toggled off), then the
//            degree i (inverse, Cauchy, SCALIS) or the Lipschitz bound c L
//            (codes 1, 8, 9)

//@@KERNELS@@

// One primitive's row of u_primitives (below).
struct Row {
  vec4 t0;
  vec4 t1;
  vec4 t2;
  vec4 t3;
};

SegmentInput segment_input(Row r, vec3 p);
ScalisSegmentInput scalis_input(Row r, vec3 p);
PointInput point_input(Row r, vec3 p);

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
  float f_ratio;    // its part bounded by ratios (inverse, Cauchy, SCALIS)
  float d_inverse;  // the least distance from p to the inverse-like elements
  float i_inverse;  // their largest degree
  float d_cauchy;   // the same for the Cauchy segments and points
  float i_cauchy;
  float s_cauchy;   // their largest s
  float lip_near;   // sum of c L of the supported terms whose support holds p
  float lip_far;    // the same for the others
  float gap_far;    // the least distance from p to the support of those
};

Row row(int k) {
  return Row(texelFetch(u_primitives, ivec2(0, k), 0), texelFetch(u_primitives, ivec2(1, k), 0),
             texelFetch(u_primitives, ivec2(2, k), 0), texelFetch(u_primitives, ivec2(3, k), 0));
}

// The distance from p to the element AB (a point when A = B).
float element_distance(Row r, vec3 p) {
  vec3 ab = r.t1.xyz - r.t0.xyz;
  vec3 ap = p - r.t0.xyz;
  float ab_ab = dot(ab, ab);
  float t = ab_ab > 0.0 ? clamp(dot(ab, ap) / ab_ab, 0.0, 1.0) : 0.0;
  return length(ap - t * ab);
}

SegmentInput segment_input(Row r, vec3 p) {
  SegmentInput si;
  si.a = r.t0.xyz;
  si.b = r.t1.xyz;
  si.p = p;
  si.w = r.t2;
  si.s = r.t3.x;
  si.R = r.t3.y;
  si.t0 = 0.0;
  si.t1 = 1.0;
  if (r.t1.w == 1.0) {
    // The part of AB inside the ball of radius R around p, as
    // skelconv/detail/clip.hpp: the discriminant from the cross product.
    vec3 ab = si.b - si.a;
    vec3 ap = p - si.a;
    float ab_ab = dot(ab, ab);
    vec3 c = cross(ab, ap);
    float disc = ab_ab * si.R * si.R - dot(c, c);
    float centre = dot(ab, ap) / ab_ab;
    float half_width = disc > 0.0 ? sqrt(disc) / ab_ab : 0.0;
    si.t0 = max(0.0, centre - half_width);
    si.t1 = min(1.0, centre + half_width);
  }
  return si;
}

ScalisSegmentInput scalis_input(Row r, vec3 p) {
  return ScalisSegmentInput(r.t0.xyz, r.t1.xyz, p, r.t2.x, r.t2.y, r.t2.z);
}

PointInput point_input(Row r, vec3 p) {
  return PointInput(r.t0.xyz, p, 1.0, r.t2.x, r.t3.x, r.t3.y, r.t2.y, r.t2.z, r.t2.w);
}

// One term f_k (and its gradient when `with_grad`; weight c not applied):
// the generated kernel; 0 for a compact segment whose clipped part is empty.
float term(Row r, vec3 p, bool with_grad, out vec3 grad) {
  grad = vec3(0.0);
  float code = r.t1.w;
  int kernel = int(r.t0.w);
  if (code == 1.0) {
    SegmentInput si = segment_input(r, p);
    if (!(si.t0 < si.t1)) return 0.0;
  }
  if (with_grad) return kernel_f_and_grad(kernel, r, p, grad);
  return kernel_f(kernel, r, p);
}

Probe probe(vec3 p) {
  Probe pr = Probe(0.0, 0.0, 1e30, 0.0, 1e30, 0.0, 0.0, 0.0, 0.0, 1e30);
  for (int k = 0; k < primitive_count; ++k) {
    Row r = row(k);
    float c = r.t3.z;
    if (c == 0.0) continue;
    float code = r.t1.w;
    float dist = element_distance(r, p);
    vec3 unused;
    if (code == 1.0 || code == 8.0) {
      if (dist < r.t3.y) {
        pr.lip_near += r.t3.w;
        pr.f += c * term(r, p, false, unused);
      } else {
        pr.lip_far += r.t3.w;
        pr.gap_far = min(pr.gap_far, dist - r.t3.y);
      }
    } else if (code == 9.0) {
      pr.lip_near += r.t3.w;
      pr.f += c * term(r, p, false, unused);
    } else {
      float fk = c * term(r, p, false, unused);
      pr.f += fk;
      pr.f_ratio += fk;
      if (code == 2.0 || code == 7.0) {
        pr.d_cauchy = min(pr.d_cauchy, dist);
        pr.i_cauchy = max(pr.i_cauchy, r.t3.w);
        pr.s_cauchy = max(pr.s_cauchy, r.t3.x);
      } else {
        pr.d_inverse = min(pr.d_inverse, dist);
        pr.i_inverse = max(pr.i_inverse, r.t3.w);
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
    Row r = row(k);
    if (r.t3.z == 0.0) continue;
    vec3 g;
    term(r, p, true, g);
    total += r.t3.z * g;
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
    // The floor: half the footprint of a pixel at t (a surface the step
    // jumps over is then thinner than half a pixel along the ray, below what
    // the image resolves), and at least u_min_step. Without the footprint,
    // rays grazing a compact term's surface (global Lipschitz bound, tiny
    // margin) run out of steps and leave holes along its silhouette. A NaN
    // (float failing in a generic form) also takes the floor.
    float floor_step = max(u_min_step, u_tan_half_fov * t / u_resolution.y);
    if (!(s >= floor_step)) s = floor_step;
    t_prev = t;
    t += s;
    if (t > t_far) return;
  }
}
