// verify/arb_reference.cpp — see arb_reference.hpp. The only file that
// includes Arb.
//
// Every quantity is a ball (arb_t: midpoint ± radius; acb_t: complex) whose
// radius Arb propagates rigorously through each operation. The inputs are
// exact (doubles), so the final balls contain the exact field. An integral
// is acb_calc_integrate of an integrand that is analytic on the integration
// path: Arb bounds the Gauss–Legendre error from the integrand on ellipses
// around each subinterval, and bisects where a singularity comes close (the
// peak of p^i beside the line, 1/ρ² near a polygon edge). Where the
// integrand is not analytic across a point (the support of k_R^i), the
// interval is split there, so that each piece is.
//
// Segments (docs/mathematics.md §2). X(t) = P − A − t (B − A), r² = X·X (a polynomial in t,
// continued to complex t; no a, b, c, no J recurrence):
//  * p^i:   K = (r²)^(−i/2),       K'/r = −i (r²)^(−(i+2)/2)
//  * c_s^i: K = (1 + s r²)^(−i/2), K'/r = −i s (1 + s r²)^(−(i+2)/2)
//    Odd powers take the principal square root, which acb_sqrt_analytic
//    certifies away from its branch cut (r² > 0 on the path, so the cut is
//    never near it). [0, 1] is split at the double nearest to the foot of P
//    (where the peak is).
//  * k_R^i (i ≥ 2): inside the support, q(t) = 1 − r²/R² = (a/R²)(t − t₋)(t₊ − t)
//    with a = |AB|² and t± the roots of r²(t) = R² (balls). Substituting
//    t = m + h sin φ (m, h the midpoint and half-width of [t₋, t₊]) gives
//    √q = (√a/R) h cos φ exactly, so K = (√a h cos φ / R)^i and
//    K'/r = −(i/R²)(√a h cos φ / R)^(i−2) are entire in φ, for odd i too,
//    and dt = h cos φ dφ. The support's ends t± are φ = ∓π/2; an end of the
//    segment inside the support is φ = asin((t − m)/h).
// Endpoints that are balls (φ from asin, t± of polygon edges) are handled by
// integrating between their midpoints and adding rad · sup|integrand| over
// the endpoint ball.
//
// Polygons (docs/mathematics.md §3), exactly planar (ExactPolygon), unit normal n, height
// z = (P − Q₀)·n, foot P̄ = P − z n, edges Q_m → Q_{m+1} = Q_m + E_m.
// Fan about P̄: Q = P̄ + τ (Γ_m(t) − P̄), Γ_m(t) = Q_m + t E_m, has the signed
// area element τ σ_m dτ dt with σ_m = ((Q_m − P̄) × (Q_{m+1} − P̄))·n, constant
// along the edge, and the signed fans add up to Ω (winding number 1 inside,
// 0 outside). With ρ_m(t)² = |Γ_m(t) − P̄|² and x = τ²ρ² + z² (dx = 2τρ² dτ),
//     ∫_0^1 τ K(√(τ²ρ² + z²)) dτ = (F(z² + ρ²) − F(z²)) / ρ²,   F'(x) = K(√x)/2,
// and Σ_m σ_m ∫_0^1 dt/ρ_m² = Θ, the winding angle (2π inside, 0 outside;
// dθ/dt = σ_m/ρ_m²). Hence, exactly,
//     f = Σ_m σ_m ∫_0^1 F(z² + ρ_m²)/ρ_m² dt − Θ F(z²)
// with F(x) = x^(1−i/2)/(2 − i) (p^i), (1 + s x)^(1−i/2)/(s (2 − i)) (c_s^i),
// −R²/(i + 2) (1 − x/R²)^(1+i/2) for x < R², else 0 (k_R^i). The gradient:
// the normal part ∂f/∂z = z ∬ K'/r dQ is the same construction with K'/r,
// whose F is K itself (d/dx K(√x) = (K'/r)(√x)/2):
//     ∂f/∂z = z (Σ_m σ_m ∫_0^1 K(z² + ρ_m²)/ρ_m² dt − Θ K(z²)),
// and the in-plane part ∬ K'/r (P̄ − Q) dQ = −∬ ∇_Q K dQ = −Σ_m (E_m × n) ∫_0^1 K dt
// (divergence theorem; K is continuous on Ω, also across the compact
// support's circle for i ≥ 2). The edge integrands are analytic in t except
// at ρ = 0 (P̄ on the edge: refused, see below) and, for k_R^i, where the
// edge crosses the support sphere: the edge is cut at the roots of
// |P − Γ_m(t)|² = R² and only the pieces inside are integrated (F = K = 0
// outside). Θ is the ball Σ atan2(σ_m, (Q_m − P̄)·(Q_{m+1} − P̄)), which must
// contain exactly one multiple of 2π; P̄ on an edge (a σ_m ball that
// contains 0 while the edge is seen at an angle near π) is refused.
#include "arb_reference.hpp"

#include <acb.h>
#include <acb_calc.h>
#include <arb.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace skelconv::verify {
namespace {

// ---- RAII for Arb's balls -------------------------------------------------

// Arb's arb_midref / arb_radref are macros on pointers: functions, so that
// the wrappers below convert.
arf_srcptr mid_of(arb_srcptr x) { return arb_midref(x); }
mag_srcptr rad_of(arb_srcptr x) { return arb_radref(x); }

class Ball {
 public:
  Ball() { arb_init(v_); }
  explicit Ball(double x) {
    arb_init(v_);
    arb_set_d(v_, x);
  }
  ~Ball() { arb_clear(v_); }
  Ball(const Ball& o) {
    arb_init(v_);
    arb_set(v_, o.v_);
  }
  Ball& operator=(const Ball& o) {
    arb_set(v_, o.v_);
    return *this;
  }
  operator arb_ptr() { return v_; }
  operator arb_srcptr() const { return v_; }

 private:
  arb_t v_;
};

class Complex {
 public:
  Complex() { acb_init(v_); }
  ~Complex() { acb_clear(v_); }
  Complex(const Complex&) = delete;
  Complex& operator=(const Complex&) = delete;
  operator acb_ptr() { return v_; }
  operator acb_srcptr() const { return v_; }
  arb_ptr real() { return acb_realref(v_); }

 private:
  acb_t v_;
};

using BallVec = std::array<Ball, 3>;

BallVec exact_vector(const Vec3<double>& v) { return {Ball(v[0]), Ball(v[1]), Ball(v[2])}; }

void dot(arb_t out, const BallVec& u, const BallVec& v, slong prec) {
  Ball term;
  arb_mul(out, u[0], v[0], prec);
  for (int c = 1; c < 3; ++c) {
    arb_mul(term, u[c], v[c], prec);
    arb_add(out, out, term, prec);
  }
}

BallVec difference(const BallVec& u, const BallVec& v, slong prec) {
  BallVec out;
  for (int c = 0; c < 3; ++c) arb_sub(out[c], u[c], v[c], prec);
  return out;
}

BallVec cross(const BallVec& u, const BallVec& v, slong prec) {
  BallVec out;
  Ball term;
  for (int c = 0; c < 3; ++c) {
    const int j = (c + 1) % 3, k = (c + 2) % 3;
    arb_mul(out[c], u[j], v[k], prec);
    arb_mul(term, u[k], v[j], prec);
    arb_sub(out[c], out[c], term, prec);
  }
  return out;
}

/// x^(n/2) for any integer n: an integer power, or the principal square root
/// (certified analytic when `analytic`: Arb makes it indeterminate near the
/// branch cut) raised to n.
void half_power(acb_t out, const acb_t x, int n, bool analytic, slong prec) {
  if (n % 2 == 0) {
    acb_pow_si(out, x, n / 2, prec);
    return;
  }
  acb_sqrt_analytic(out, x, analytic, prec);
  acb_pow_si(out, out, n, prec);
}

/// Dot product of a ball vector with (c + t e), t complex: Σ_c (c_c + t e_c)².
void squared_norm_along(acb_t out, const BallVec& c, const BallVec& e, const acb_t t, slong prec) {
  Complex x;
  acb_zero(out);
  for (int k = 0; k < 3; ++k) {
    acb_mul_arb(x, t, e[k], prec);
    acb_add_arb(x, x, c[k], prec);
    acb_addmul(out, x, x, prec);
  }
}

// ---- Integration ----------------------------------------------------------

/// An integrand on the complex plane (acb_calc_integrate's contract: with
/// `analytic`, the value must be indeterminate unless the function is
/// analytic on the whole ball x).
class Integrand {
 public:
  virtual ~Integrand() = default;
  virtual void evaluate(acb_t out, const acb_t x, bool analytic, slong prec) const = 0;
};

int integrand_callback(acb_ptr out, const acb_t x, void* param, slong order, slong prec) {
  static_cast<const Integrand*>(param)->evaluate(out, x, order != 0, prec);
  return 0;
}

/// out += ∫_lo^hi g, lo and hi real balls: acb_calc_integrate between their
/// midpoints (exact points), plus rad · sup|g| over each endpoint ball for
/// the part of [lo, hi] the midpoints leave out (or add). `abs_tol`: where
/// the adaptive subdivision may stop (absolute); `goal` bits relative.
void add_integral(arb_t out, const Integrand& g, const arb_t lo, const arb_t hi, const mag_t abs_tol,
                  const ArbSettings& settings) {
  const slong prec = settings.precision_bits;
  Complex a, b, result, value;
  arb_set_arf(a.real(), mid_of(lo));
  arb_set_arf(b.real(), mid_of(hi));
  acb_calc_integrate(result, integrand_callback, const_cast<Integrand*>(&g), a, b, settings.goal_bits, abs_tol,
                     nullptr, prec);
  Ball sum;
  arb_set(sum, result.real());  // the exact integral is real
  for (arb_srcptr end : {lo, hi}) {
    if (mag_is_zero(rad_of(end))) continue;
    Complex ball;
    acb_set_arb(ball, end);
    g.evaluate(value, ball, false, prec);
    Ball magnitude;
    acb_abs(magnitude, value, prec);
    mag_t bound;
    mag_init(bound);
    arb_get_mag(bound, magnitude);
    mag_mul(bound, bound, rad_of(end));
    arb_add_error_mag(sum, bound);
    mag_clear(bound);
  }
  arb_add(out, out, sum, prec);
}

/// 2^-(goal + extra) · scale as a magnitude (0 when scale is 0 or not finite).
void tolerance(mag_t out, double scale, long bits) {
  mag_zero(out);
  if (std::isfinite(scale) && scale > 0) {
    mag_set_d(out, scale);
    mag_mul_2exp_si(out, out, -bits);
  }
}

// ---- Results --------------------------------------------------------------

/// The midpoint in binary128 (three doubles hold it to 159 bits).
extended midpoint(const arb_t x) {
  arf_t rest, part;
  arf_init(rest);
  arf_init(part);
  arf_set(rest, mid_of(x));
  extended out = 0;
  for (int k = 0; k < 3; ++k) {
    const double d = arf_get_d(rest, ARF_RND_NEAR);
    out += extended(d);
    arf_set_d(part, d);
    arf_sub(rest, rest, part, ARF_PREC_EXACT, ARF_RND_NEAR);
  }
  arf_clear(rest);
  arf_clear(part);
  return out;
}

double lower_abs(const arb_t x) {
  arf_t bound;
  arf_init(bound);
  arb_get_abs_lbound_arf(bound, x, 64);
  const double out = arf_get_d(bound, ARF_RND_DOWN);
  arf_clear(bound);
  return out;
}

/// Upward rounding of the double arithmetic on the bounds themselves.
constexpr double bound_rounding = 1 + 0x1p-50;

CertifiedField make_result(const arb_t f, const BallVec& grad) {
  CertifiedField out;
  if (!arb_is_finite(f) || !arb_is_finite(grad[0]) || !arb_is_finite(grad[1]) || !arb_is_finite(grad[2])) {
    out.why = "an enclosure is not finite (an integral did not converge or an integrand was not analytic)";
    return out;
  }
  out.f = midpoint(f);
  for (int c = 0; c < 3; ++c) out.grad[c] = midpoint(grad[c]);
  const double f_lower = lower_abs(f);
  out.f_bound = f_lower > 0 ? mag_get_d(rad_of(f)) / f_lower * bound_rounding
                            : std::numeric_limits<double>::infinity();
  double radius2 = 0, lower2 = 0;
  for (int c = 0; c < 3; ++c) {
    const double r = mag_get_d(rad_of(grad[c])), l = lower_abs(grad[c]);
    radius2 += r * r;
    lower2 += l * l;
  }
  out.grad_bound = lower2 > 0 ? std::sqrt(radius2 / lower2) * bound_rounding
                              : std::numeric_limits<double>::infinity();
  out.certified = true;
  return out;
}

CertifiedField refused(std::string why) {
  CertifiedField out;
  out.why = std::move(why);
  return out;
}

CertifiedField exactly_zero() {
  CertifiedField out;
  out.certified = out.zero = true;
  return out;
}

// ---- The support of k_R^i on a line --------------------------------------

/// Where |X0 − t E|² < R² on [0, 1], X0 = P − (start of the segment or edge).
struct SupportPiece {
  enum class Kind { empty, piece, undecided } kind = Kind::undecided;
  Ball t_minus, t_plus;        ///< the roots of |X0 − t E|² = R² (kind piece)
  bool starts_at_root = false;  ///< t₋ > 0 (else the piece starts at t = 0)
  bool ends_at_root = false;    ///< t₊ < 1 (else it ends at t = 1)
};

SupportPiece empty_piece() {
  SupportPiece out;
  out.kind = SupportPiece::Kind::empty;
  return out;
}

SupportPiece support_piece(const BallVec& x0, const BallVec& e, const arb_t R2, slong prec) {
  SupportPiece out;
  Ball a, b, c, disc, root, term;
  dot(a, e, e, prec);
  dot(b, e, x0, prec);
  dot(c, x0, x0, prec);
  arb_sub(c, c, R2, prec);  // c − R²
  arb_sqr(disc, b, prec);
  arb_mul(term, a, c, prec);
  arb_sub(disc, disc, term, prec);  // b² − a(c − R²)
  if (arb_is_nonpositive(disc)) return empty_piece();
  if (!arb_is_positive(disc)) return out;  // undecided: tangent to the sphere within the balls
  arb_sqrt(root, disc, prec);
  arb_sub(out.t_minus, b, root, prec);
  arb_div(out.t_minus, out.t_minus, a, prec);
  arb_add(out.t_plus, b, root, prec);
  arb_div(out.t_plus, out.t_plus, a, prec);
  Ball one(1.0);
  if (arb_is_nonpositive(out.t_plus) || arb_ge(out.t_minus, one)) return empty_piece();
  const bool minus_decided = arb_is_positive(out.t_minus) || arb_is_negative(out.t_minus);
  const bool plus_decided = arb_lt(out.t_plus, one) || arb_gt(out.t_plus, one);
  if (!arb_is_positive(out.t_plus) || !arb_lt(out.t_minus, one) || !minus_decided || !plus_decided) return out;
  out.starts_at_root = arb_is_positive(out.t_minus);
  out.ends_at_root = arb_lt(out.t_plus, one);
  out.kind = SupportPiece::Kind::piece;
  return out;
}

// ---- Segments -------------------------------------------------------------

struct SegmentData {
  BallVec pa, d;  ///< P − A, B − A
  BallVec ad;     ///< A − B = −d
  Ball length;    ///< |AB|
  std::vector<Ball> w;
  KernelFamily family = KernelFamily::inverse;
  int degree = 1;
  Ball s, R2;
  bool angular = false;  ///< compact: the variable is φ, t = m + h sin φ
  Ball m, h, kappa;      ///< kappa = √a / R
};

/// |AB| w(t) × (K, or K'/r X_c for component c = 1..3) at t (or at φ).
class SegmentIntegrand : public Integrand {
 public:
  SegmentIntegrand(const SegmentData& data, int component) : data_(data), component_(component) {}

  void evaluate(acb_t out, const acb_t x, bool analytic, slong prec) const override {
    const SegmentData& g = data_;
    const int i = g.degree;
    Complex t, jacobian, weight, value, r2, base;
    if (g.angular) {
      Complex sine, cosine;
      acb_sin_cos(sine, cosine, x, prec);
      acb_mul_arb(t, sine, g.h, prec);
      acb_add_arb(t, t, g.m, prec);
      acb_mul_arb(jacobian, cosine, g.h, prec);  // dt/dφ = h cos φ
    } else {
      acb_set(t, x);
      acb_one(jacobian);
    }
    acb_zero(weight);  // Horner: w(t) = Σ w_k t^k
    for (auto k = g.w.size(); k-- > 0;) {
      acb_mul(weight, weight, t, prec);
      acb_add_arb(weight, weight, g.w[k], prec);
    }
    switch (g.family) {
      case KernelFamily::inverse:
      case KernelFamily::cauchy: {
        squared_norm_along(r2, g.pa, g.ad, t, prec);  // |(P − A) − t(B − A)|²
        if (g.family == KernelFamily::cauchy) {
          acb_mul_arb(base, r2, g.s, prec);
          acb_add_ui(base, base, 1, prec);
        } else {
          acb_set(base, r2);
        }
        if (component_ == 0) {
          half_power(value, base, -i, analytic, prec);
        } else {
          half_power(value, base, -i - 2, analytic, prec);
          acb_mul_si(value, value, -i, prec);
          if (g.family == KernelFamily::cauchy) acb_mul_arb(value, value, g.s, prec);
        }
        break;
      }
      default: {  // compact, in φ: √q = kappa h cos φ
        acb_mul_arb(base, jacobian, g.kappa, prec);
        if (component_ == 0) {
          acb_pow_si(value, base, i, prec);
        } else {
          acb_pow_si(value, base, i - 2, prec);
          acb_mul_si(value, value, -i, prec);
          acb_div_arb(value, value, g.R2, prec);
        }
        break;
      }
    }
    if (component_ > 0) {  // × X_c(t) = (P − A)_c − t (B − A)_c
      Complex xc;
      acb_mul_arb(xc, t, g.d[component_ - 1], prec);
      acb_neg(xc, xc);
      acb_add_arb(xc, xc, g.pa[component_ - 1], prec);
      acb_mul(value, value, xc, prec);
    }
    acb_mul(value, value, weight, prec);
    acb_mul(value, value, jacobian, prec);
    acb_mul_arb(out, value, g.length, prec);
  }

 private:
  const SegmentData& data_;
  int component_;
};

using Interval = std::pair<Ball, Ball>;

/// The integration pieces of a compact segment, in φ; empty when the support
/// misses [0, 1]; nullopt-like `false` when it cannot be decided.
bool compact_segment_pieces(SegmentData& g, std::vector<Interval>& pieces, bool& empty, slong prec) {
  const SupportPiece piece = support_piece(g.pa, g.d, g.R2, prec);  // |(P − A) − t(B − A)|² = R²
  if (piece.kind == SupportPiece::Kind::undecided) return false;
  empty = piece.kind == SupportPiece::Kind::empty;
  if (empty) return true;
  g.angular = true;
  arb_add(g.m, piece.t_minus, piece.t_plus, prec);
  arb_mul_2exp_si(g.m, g.m, -1);
  arb_sub(g.h, piece.t_plus, piece.t_minus, prec);
  arb_mul_2exp_si(g.h, g.h, -1);
  Ball a;
  dot(a, g.d, g.d, prec);
  arb_sqrt(g.kappa, a, prec);
  Ball R;
  arb_sqrt(R, g.R2, prec);
  arb_div(g.kappa, g.kappa, R, prec);
  Ball lo, hi, half_pi;
  arb_const_pi(half_pi, prec);
  arb_mul_2exp_si(half_pi, half_pi, -1);
  const auto angle_of = [&](arb_t out, double t) {
    Ball x(t);
    arb_sub(x, x, g.m, prec);
    arb_div(x, x, g.h, prec);
    arb_asin(out, x, prec);
  };
  if (piece.starts_at_root) arb_neg(lo, half_pi);
  else angle_of(lo, 0.0);
  if (piece.ends_at_root) arb_set(hi, half_pi);
  else angle_of(hi, 1.0);
  pieces.emplace_back(lo, hi);
  return true;
}

}  // namespace

CertifiedField certified_segment_field(const SweepProblem& pb, int weight_degree, const ArbSettings& settings) {
  const slong prec = settings.precision_bits;
  SegmentData g;
  g.family = pb.family;
  g.degree = pb.degree;
  if (pb.family != KernelFamily::inverse && pb.family != KernelFamily::cauchy && pb.family != KernelFamily::compact)
    return refused("family not covered by the certified reference");
  if (pb.family == KernelFamily::compact && pb.degree < 2) return refused("compact degree below 2");
  const BallVec a = exact_vector(pb.a), b = exact_vector(pb.b), p = exact_vector(pb.p);
  g.pa = difference(p, a, prec);
  g.d = difference(b, a, prec);
  g.ad = difference(a, b, prec);
  dot(g.length, g.d, g.d, prec);
  arb_sqrt(g.length, g.length, prec);
  for (int k = 0; k <= weight_degree; ++k) g.w.emplace_back(pb.w[k]);
  arb_set_d(g.s, pb.s);
  arb_set_d(g.R2, pb.R);
  arb_sqr(g.R2, g.R2, prec);

  std::vector<Interval> pieces;
  if (pb.family == KernelFamily::compact) {
    bool empty = false;
    if (!compact_segment_pieces(g, pieces, empty, prec))
      return refused("the support sphere's crossings with the segment are not separated from its ends");
    if (empty) return exactly_zero();
  } else {
    // Split at the double nearest to the foot of P, where the peak is.
    const Vec3<double> d = sub(pb.b, pb.a), pa = sub(pb.p, pb.a);
    const double foot = std::clamp(dot(d, pa) / dot(d, d), 0.0, 1.0);
    if (foot > 0) pieces.emplace_back(Ball(0.0), Ball(foot));
    if (foot < 1) pieces.emplace_back(Ball(foot), Ball(1.0));
  }
  mag_t tol;
  mag_init(tol);
  Ball f;
  for (const auto& [lo, hi] : pieces) add_integral(f, SegmentIntegrand(g, 0), lo, hi, tol, settings);
  // ∇f's components change sign along the segment: an absolute tolerance
  // relative to |f|/distance (≈ |∇f|/i) lets the subdivision stop; it only
  // sets the effort, the enclosure is rigorous whatever it is.
  tolerance(tol, std::abs(arf_get_d(mid_of(f), ARF_RND_NEAR)) / distance_to_segment(pb.a, pb.b, pb.p),
            settings.goal_bits + 10);
  BallVec grad;
  for (int c = 0; c < 3; ++c)
    for (const auto& [lo, hi] : pieces) add_integral(grad[c], SegmentIntegrand(g, c + 1), lo, hi, tol, settings);
  mag_clear(tol);
  return make_result(f, grad);
}

// ---- Polygons -------------------------------------------------------------

namespace {

struct PolygonData {
  KernelFamily family = KernelFamily::inverse;
  int degree = 3;
  Ball s, R2;
  Ball z2;  ///< z²
};

/// F(x) (want_f) or K(x) of the file comment ("Polygons"), x = r² complex.
void polygon_kernel(acb_t out, const PolygonData& g, const acb_t x, bool want_f, bool analytic, slong prec) {
  const int i = g.degree;
  Complex base;
  switch (g.family) {
    case KernelFamily::inverse:  // F = x^(1−i/2)/(2 − i), K = x^(−i/2)
      half_power(out, x, want_f ? 2 - i : -i, analytic, prec);
      if (want_f) acb_div_si(out, out, 2 - i, prec);
      break;
    case KernelFamily::cauchy:  // F = (1 + s x)^(1−i/2)/(s (2 − i)), K = (1 + s x)^(−i/2)
      acb_mul_arb(base, x, g.s, prec);
      acb_add_ui(base, base, 1, prec);
      half_power(out, base, want_f ? 2 - i : -i, analytic, prec);
      if (want_f) {
        acb_div_si(out, out, 2 - i, prec);
        acb_div_arb(out, out, g.s, prec);
      }
      break;
    default:  // compact, even i, x < R²: F = −R²/(i + 2) (1 − x/R²)^(1+i/2), K = (1 − x/R²)^(i/2)
      acb_div_arb(base, x, g.R2, prec);
      acb_neg(base, base);
      acb_add_ui(base, base, 1, prec);
      acb_pow_si(out, base, want_f ? 1 + i / 2 : i / 2, prec);
      if (want_f) {
        acb_mul_arb(out, out, g.R2, prec);
        acb_div_si(out, out, -(i + 2), prec);
      }
      break;
  }
}

/// The three edge integrands of "Polygons" (file comment), at edge offset
/// a = Q_m − P̄ and direction E: F(r²)/ρ², K(r²)/ρ² and K(r²), r² = z² + ρ².
class PolygonEdgeIntegrand : public Integrand {
 public:
  enum class Part { fan_f, fan_normal, edge_k };
  PolygonEdgeIntegrand(const PolygonData& data, const BallVec& a, const BallVec& e, Part part)
      : data_(data), a_(a), e_(e), part_(part) {}

  void evaluate(acb_t out, const acb_t t, bool analytic, slong prec) const override {
    Complex rho2, r2;
    squared_norm_along(rho2, a_, e_, t, prec);
    acb_add_arb(r2, rho2, data_.z2, prec);
    polygon_kernel(out, data_, r2, part_ == Part::fan_f, analytic, prec);
    if (part_ != Part::edge_k) acb_div(out, out, rho2, prec);
  }

 private:
  const PolygonData& data_;
  const BallVec& a_;
  const BallVec& e_;
  Part part_;
};

/// F(z²) or K(z²), real.
void kernel_at_height(arb_t out, const PolygonData& g, bool want_f, slong prec) {
  Complex x, value;
  acb_set_arb(x, g.z2);
  polygon_kernel(value, g, x, want_f, false, prec);
  arb_set(out, value.real());
}

/// The t-intervals of edge [0, 1] to integrate: split at the double nearest
/// to P̄'s foot (the 1/ρ² peak); compact: only the part inside the support.
bool edge_pieces(const PolygonData& g, const BallVec& pq, const BallVec& e, const Vec3<double>& foot_data,
                 std::vector<Interval>& pieces, slong prec) {
  Ball lo(0.0), hi(1.0);
  if (g.family == KernelFamily::compact) {
    const SupportPiece piece = support_piece(pq, e, g.R2, prec);
    if (piece.kind == SupportPiece::Kind::undecided) return false;
    if (piece.kind == SupportPiece::Kind::empty) return true;
    if (piece.starts_at_root) lo = piece.t_minus;
    if (piece.ends_at_root) hi = piece.t_plus;
  }
  // foot_data: (E·(P − Q_m), |E|², unused) in double, for the split only.
  const double foot = std::clamp(foot_data[0] / foot_data[1], 0.0, 1.0);
  Ball split(foot);
  if (arb_lt(lo, split) && arb_lt(split, hi)) {
    pieces.emplace_back(lo, split);
    pieces.emplace_back(split, hi);
  } else {
    pieces.emplace_back(lo, hi);
  }
  return true;
}

/// The exact plane and the fan about P̄ (file comment, "Polygons").
struct PolygonGeometry {
  BallVec n;                    ///< unit normal
  BallVec P;                    ///< the point
  Ball z;                       ///< (P − Q₀)·n
  std::vector<BallVec> q;       ///< vertices
  std::vector<BallVec> offset;  ///< Q_m − P̄
  std::vector<BallVec> edge;    ///< E_m = Q_{m+1} − Q_m
  std::vector<Ball> sigma;      ///< σ_m = ((Q_m − P̄) × (Q_{m+1} − P̄))·n
};

PolygonGeometry polygon_geometry(const ExactPolygon& polygon, const Vec3<double>& p, slong prec) {
  PolygonGeometry geo;
  const std::size_t count = polygon.vertices.size();
  geo.n = exact_vector(polygon.normal_direction);
  Ball length;
  dot(length, geo.n, geo.n, prec);
  arb_sqrt(length, length, prec);
  for (auto& c : geo.n) arb_div(c, c, length, prec);
  geo.P = exact_vector(p);
  for (const auto& v : polygon.vertices) geo.q.push_back(exact_vector(v));
  dot(geo.z, difference(geo.P, geo.q[0], prec), geo.n, prec);
  BallVec foot;  // P̄ = P − z n
  for (int c = 0; c < 3; ++c) {
    arb_mul(foot[c], geo.z, geo.n[c], prec);
    arb_sub(foot[c], geo.P[c], foot[c], prec);
  }
  for (std::size_t m = 0; m < count; ++m) geo.offset.push_back(difference(geo.q[m], foot, prec));
  geo.sigma.resize(count);
  for (std::size_t m = 0; m < count; ++m) {
    const std::size_t next = (m + 1) % count;
    geo.edge.push_back(difference(geo.q[next], geo.q[m], prec));
    dot(geo.sigma[m], cross(geo.offset[m], geo.offset[next], prec), geo.n, prec);
  }
  return geo;
}

/// The winding number of the boundary about P̄ (Θ = 2π × it); false, with
/// `why`, when P̄ may be on an edge or Θ's ball is not around one multiple
/// of 2π.
bool winding_number(const PolygonGeometry& geo, long& winding, std::string& why, slong prec) {
  const std::size_t count = geo.q.size();
  Ball theta_sum, theta, along;
  for (std::size_t m = 0; m < count; ++m) {
    dot(along, geo.offset[m], geo.offset[(m + 1) % count], prec);
    if (arb_contains_zero(geo.sigma[m]) && !arb_is_positive(along)) {
      why = "P's foot on the plane is on (or within the balls of) an edge";
      return false;
    }
    arb_atan2(theta, geo.sigma[m], along, prec);  // the angle the edge subtends at P̄
    arb_add(theta_sum, theta_sum, theta, prec);
  }
  Ball two_pi;
  arb_const_pi(two_pi, prec);
  arb_mul_2exp_si(two_pi, two_pi, 1);
  arb_div(theta_sum, theta_sum, two_pi, prec);
  winding = std::lround(arf_get_d(mid_of(theta_sum), ARF_RND_NEAR));
  if (!arb_contains_si(theta_sum, winding) || mag_cmp_2exp_si(rad_of(theta_sum), -2) > 0) {
    why = "the winding number is not decided";
    return false;
  }
  return true;
}

/// Σ_m σ_m ∫F/ρ², Σ_m σ_m ∫K/ρ² and −Σ_m (E_m × n) ∫K over the edges.
struct EdgeSums {
  Ball fan_f, fan_normal;
  BallVec in_plane;
  bool any_piece = false;  ///< compact: does the support reach any edge?
};

bool edge_sums(EdgeSums& sums, const PolygonData& g, const PolygonGeometry& geo, const ExactPolygon& polygon,
               const Vec3<double>& p, const ArbSettings& settings) {
  const slong prec = settings.precision_bits;
  const std::size_t count = geo.q.size();
  mag_t tol;
  mag_init(tol);  // 0: every edge integrand is sign-definite, the relative goal decides
  for (std::size_t m = 0; m < count; ++m) {
    const BallVec pq = difference(geo.P, geo.q[m], prec);
    const Vec3<double> e_double = sub(polygon.vertices[(m + 1) % count], polygon.vertices[m]);
    const Vec3<double> foot_data{verify::dot<double>(e_double, sub(p, polygon.vertices[m])),
                                 verify::dot<double>(e_double, e_double), 0};
    std::vector<Interval> pieces;
    if (!edge_pieces(g, pq, geo.edge[m], foot_data, pieces, prec)) {
      mag_clear(tol);
      return false;
    }
    sums.any_piece = sums.any_piece || !pieces.empty();
    using Part = PolygonEdgeIntegrand::Part;
    const PolygonEdgeIntegrand f_part(g, geo.offset[m], geo.edge[m], Part::fan_f);
    const PolygonEdgeIntegrand normal_part(g, geo.offset[m], geo.edge[m], Part::fan_normal);
    const PolygonEdgeIntegrand k_part(g, geo.offset[m], geo.edge[m], Part::edge_k);
    Ball f_edge, normal_edge, k_edge;
    for (const auto& [lo, hi] : pieces) {
      add_integral(f_edge, f_part, lo, hi, tol, settings);
      add_integral(normal_edge, normal_part, lo, hi, tol, settings);
      add_integral(k_edge, k_part, lo, hi, tol, settings);
    }
    arb_addmul(sums.fan_f, geo.sigma[m], f_edge, prec);
    arb_addmul(sums.fan_normal, geo.sigma[m], normal_edge, prec);
    const BallVec outward = cross(geo.edge[m], geo.n, prec);  // E × n
    for (int c = 0; c < 3; ++c) arb_submul(sums.in_plane[c], outward[c], k_edge, prec);
  }
  mag_clear(tol);
  return true;
}

}  // namespace

CertifiedField certified_polygon_field(const ExactPolygon& polygon, const Vec3<double>& p, KernelFamily family,
                                       int degree, double s, double R, const ArbSettings& settings) {
  const slong prec = settings.precision_bits;
  if (family != KernelFamily::inverse && family != KernelFamily::cauchy && family != KernelFamily::compact)
    return refused("family not covered by the certified reference");
  if (family == KernelFamily::compact ? (degree < 2 || degree % 2 != 0) : degree < 3)
    return refused("degree not covered (compact: even ≥ 2; others ≥ 3)");
  PolygonData g;
  g.family = family;
  g.degree = degree;
  arb_set_d(g.s, s);
  arb_set_d(g.R2, R);
  arb_sqr(g.R2, g.R2, prec);
  const PolygonGeometry geo = polygon_geometry(polygon, p, prec);
  arb_sqr(g.z2, geo.z, prec);
  if (family == KernelFamily::compact) {
    if (arb_ge(g.z2, g.R2)) return exactly_zero();
    if (!arb_lt(g.z2, g.R2)) return refused("|z| = R within the balls");
  }
  long winding = 0;
  std::string why;
  if (!winding_number(geo, winding, why, prec)) return refused(why);
  if (winding != 0 && family == KernelFamily::inverse && arb_contains_zero(geo.z))
    return refused("P in the closed polygon: the inverse field is infinite");
  EdgeSums sums;
  if (!edge_sums(sums, g, geo, polygon, p, settings))
    return refused("an edge's crossing with the support sphere is not separated from its ends");
  // No edge reaches into the support and P̄ is outside: the support disc
  // misses Ω, f = 0 and ∇f = 0 exactly.
  if (!sums.any_piece && winding == 0) return exactly_zero();

  // f = Σ σ ∫F/ρ² − Θ F(z²); ∂f/∂z = z (Σ σ ∫K/ρ² − Θ K(z²)); ∇f = n ∂f/∂z + in-plane part.
  Ball f, dfdz, theta, term;
  arb_set(f, sums.fan_f);
  arb_set(dfdz, sums.fan_normal);
  if (winding != 0) {
    arb_const_pi(theta, prec);
    arb_mul_si(theta, theta, 2 * winding, prec);  // Θ, exactly 2π × winding
    kernel_at_height(term, g, true, prec);
    arb_submul(f, theta, term, prec);
    kernel_at_height(term, g, false, prec);
    arb_submul(dfdz, theta, term, prec);
  }
  arb_mul(dfdz, dfdz, geo.z, prec);
  BallVec grad;
  for (int c = 0; c < 3; ++c) {
    arb_mul(grad[c], geo.n[c], dfdz, prec);
    arb_add(grad[c], grad[c], sums.in_plane[c], prec);
  }
  return make_result(f, grad);
}

}  // namespace skelconv::verify
