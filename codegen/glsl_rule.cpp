// codegen/glsl_rule.cpp — see glsl_rule.hpp.
//
// Why a rule and not the closed forms: in float the C++ target's generic
// forms (recurrence (1) upwards, the moment relations) cancel. Measured on
// the generated GLSL (tests/glsl/check_glsl_numeric.py --backend cpu):
// beyond an end and far from the segment their relative error reaches 1e-4
// at degree 1–3 and 1e5–1e29 at high degrees (inverse and Cauchy, plain and
// SCALIS), and beside AB 1e-4 already for Cauchy i = 2 and SCALIS inverse
// i = 10. The C++ target escapes this with double, downward recurrences,
// the exact cross product and Gauss rules on panels; float has no room for
// the first three. The integrand of every kernel here is positive (w ≥ 0),
// so a Gauss rule, whose weights are positive, has nothing to cancel: its
// error is the rule's truncation plus a few ulps per node.
//
// The rule (skelconv_segment_rule below), for an integrand v(t) q(t)^(−n/2):
//  * n > 0 (inverse, Cauchy, SCALIS): q's complex roots c' ± i y (in units
//    of t); c = c' clamped to [0, 1] and h = |c' + i y − c| > 0, the
//    distance from c to them. On each side of c the variable s = |t − c| =
//    h sinh(u), u uniform in [0, asinh(S/h)] (S the side's length): the
//    sinh map of nearly singular integrals (Johnston & Elliott 2005). Beside
//    AB the roots sit at s = ±i h, i.e. u = ±iπ/2, so the integrand is
//    analytic in a strip of half-width π/2 around an interval of length
//    asinh(S/h) ≤ asinh(1/h). The truncation error of n nodes per side
//    (tests/glsl/rule_truncation.py: in double, SCALIS inverse and Cauchy
//    of degree 2–10, against the graded reference quadrature) for 16, 20,
//    24 nodes: 3.5e-10, 2.2e-13, 1.4e-14 at h ≥ 0.1; 1.1e-6, 8.4e-9, 5.1e-11
//    at h ≥ 0.01; 3.1e-5, 8.0e-7, 1.6e-8 at h ≥ 1e-3; 24 nodes keep it
//    below float's rounding down to h = 1e-3 (3.6e-7 at 1e-4; the table
//    in docs/view.md). Beyond an end the roots are off the real axis by
//    less but further from the interval (s = −h on the line: u = −0.88).
//    Where the side is no longer than h (far from the segment) the plain
//    rule in s is used: the roots are then ≥ 2 half-widths from the side's
//    start (Bernstein parameter ≥ 2.9), and no transcendental function
//    enters, whose GPU accuracy near 0 is absolute, not relative.
//  * n < 0 (compact): q^(|n|/2) on the clipped [t0, t1], whose ends may be
//    roots of q (branch points for odd n): t = mid + half sin(πx/2), as
//    NodeMap::sine of skelconv/detail/gauss_moments.hpp, makes the integrand
//    analytic there; 24 nodes, mapped at generation (a table).
// Rounding: d = P − Γ(t) is formed from the end nearest to c (P − A or
// P − B, exact to rounding) so that beyond an end |d| keeps its digits;
// beside AB at distance h|AB| it loses ε/h as every float form does.
#include "glsl_rule.hpp"

#include <sstream>

namespace skelconv::codegen {

namespace {

// The 24-point Gauss–Legendre rule on [−1, 1]: its 12 positive nodes and
// their weights (numpy.polynomial.legendre.leggauss(24), to 9 digits: float
// keeps 7).
constexpr const char* kRuleBlock = R"(#ifndef SKELCONV_SEGMENT_RULE
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

)";

// The weight polynomial of degree `weight_degree` as a vec4 (higher terms 0).
std::string weight_vector(int weight_degree) {
  std::ostringstream os;
  os << "vec4(";
  for (int k = 0; k < 4; ++k) os << (k ? ", " : "") << (k <= weight_degree ? "si.w[" + std::to_string(k) + "]" : "0.0");
  os << ")";
  return os.str();
}

// NAME_f and NAME_f_and_grad around one call `call` (its last argument the
// gradient), with `guard` before it (empty or a return for an empty interval).
std::string wrappers(const std::string& name, const std::string& equation, const std::string& input,
                     const std::string& guard, const std::string& call) {
  std::ostringstream os;
  const std::string form = "// Form: the definition integral by skelconv_segment_rule (24 nodes per side).\n";
  os << "// the field, where\n//     " << equation << "\n" << form << "float " << name << "_f(" << input
     << " si) {\n  vec3 grad;\n" << guard << "  return " << call << ";\n}\n\n"
     << "// the field and its gradient, where\n//     " << equation << "\n" << form << "float " << name
     << "_f_and_grad(" << input << " si, out vec3 grad) {\n"
     << guard << "  return " << call << ";\n}\n\n";
  return os.str();
}

}  // namespace

const std::string& glsl_rule_block() {
  static const std::string block = kRuleBlock;
  return block;
}

std::string glsl_segment_rule_functions(const SegmentKernelSpec& spec) {
  const std::string i = std::to_string(spec.degree);
  const std::string w = weight_vector(spec.weight_degree);
  std::string kernel, guard, interval = "0.0, 1.0";
  switch (spec.family) {
    case KernelFamily::cauchy: kernel = "si.s, 1.0, 0.0, " + i; break;
    case KernelFamily::compact:
      kernel = "-1.0 / (si.R * si.R), 1.0, 0.0, -" + i;
      guard = "  grad = vec3(0.0);\n  if (!(si.t0 < si.t1)) return 0.0;\n";
      interval = "si.t0, si.t1";
      break;
    default: kernel = "1.0, 0.0, 0.0, " + i; break;
  }
  const std::string call =
      "skelconv_segment_rule(si.a, si.b, si.p, " + w + ", 1.0, 1.0, 0, " + kernel + ", " + interval + ", grad)";
  return wrappers(spec.name(), spec.equation(), "SegmentInput", guard, call);
}

std::string glsl_scalis_rule_functions(const ScalisKernelSpec& spec) {
  const std::string i = std::to_string(spec.degree);
  const std::string gamma = spec.family == KernelFamily::cauchy ? "si.sigma * si.sigma" : "0.0";
  // sigma^i = skelconv_rule_power(sigma, -2 i).
  const std::string call = "skelconv_segment_rule(si.a, si.b, si.p, vec4(skelconv_rule_power(si.sigma, -" +
                           std::to_string(2 * spec.degree) + "), 0.0, 0.0, 0.0), si.tau0, si.tau1, " +
                           std::to_string(spec.degree - 1) + ", 1.0, 0.0, " + gamma + ", " + i + ", 0.0, 1.0, grad)";
  return wrappers(spec.name(), spec.equation(), "ScalisSegmentInput", "", call);
}

}  // namespace skelconv::codegen
