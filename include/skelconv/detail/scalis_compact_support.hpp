// skelconv/detail/scalis_compact_support.hpp — the compact SCALIS
// segment's support and its Gauss panels (docs/mathematics.md §4, Zanni et al. 2013 §4.3):
// everything scalis_compact_F (skelconv/primitives/scalis_compact.hpp, whose
// header comment explains the method) does before and around the integral,
// and the panels. Apart from scalis_compact.hpp so that the generator can
// count these operations (codegen/helper_costs.cpp) without the generated
// closed forms that scalis_compact.hpp includes.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>

#include <boost/math/quadrature/gauss.hpp>

#include "skelconv/detail/double_word.hpp"
#include "skelconv/detail/integer_power.hpp"
#include "skelconv/not_converged.hpp"
#include "skelconv/primitives/scalis_compact_closed_form_input.hpp"
#include "skelconv/primitives/scalis_segment_input.hpp"

namespace skelconv {

namespace detail {

/// Multiplication by 2^−e, the scale of the frame: x · 2^−e is correctly
/// rounded like ldexp(x, −e), so the two give the same bits, and the product
/// avoids ldexp's library call (measured: ~40 instructions each, a third of
/// the support's cost). 2^−e itself must be a finite T, which holds with a
/// margin for e > min_exponent + 3 (−1018 in double); below, ldexp.
template <class T>
struct DownScale {
  int e = 0;
  T unit = T(1);  ///< 2^−e, or 0 where it is not finite
  explicit DownScale(int exponent) : e(exponent) {
    using std::ldexp;
    unit = e > std::numeric_limits<T>::min_exponent + 3 ? ldexp(T(1), -e) : T(0);
  }
  T operator()(const T& x) const {
    using std::ldexp;
    return unit != T(0) ? x * unit : ldexp(x, -e);
  }
};

/// Gauss–Legendre points for the precision of T (see the bound above).
template <class T>
constexpr unsigned gauss_points() {
  constexpr int digits = std::numeric_limits<T>::digits;
  return digits <= 53 ? 25u : digits <= 64 ? 30u : 40u;
}

/// Bernstein-ellipse parameters below which a panel is bisected: 4 for the
/// pole of 1/τ^(i+1) (order up to 11, and the numerator grows off the
/// interval), 3 for a square-root branch point of √Q (a bounded singularity:
/// the rule's error there is ~3^(−2N), 1e-24 for N = 25).
template <class T>
T rho_min_pole() {
  return T(4);
}
template <class T>
T rho_min_branch() {
  return T(3);
}

/// A singular point of the integrand in the complex plane of a panel variable.
template <class T>
struct Singularity {
  T re;
  T im;
  T rho_min;  ///< the Bernstein parameter a panel must keep it outside of
};

/// ρ(z) of the Bernstein ellipse of [a, b] through z.
template <class T>
T bernstein_rho(const T& a, const T& b, const Singularity<T>& z) {
  using std::sqrt;
  const T half = (b - a) / 2;
  const T xr = (z.re - (a + b) / 2) / half;
  const T xi = z.im / half;
  const T s = (sqrt((xr - 1) * (xr - 1) + xi * xi) + sqrt((xr + 1) * (xr + 1) + xi * xi)) / 2;
  return s + sqrt(std::max(T(0), s * s - 1));
}

/// One piece of the support: t = origin + dir·v (linear) or origin + dir·v²
/// (square, origin a root of Q), v ∈ [0, extent]. Q is evaluated as
/// s (α s + slope) with s = t − ρ = (origin − ρ) + dir·v (linear) or dir·v²
/// (square), ρ a root of Q and slope = Q'(ρ).
template <class T>
struct Piece {
  bool square;
  T origin;
  int dir;
  T extent;
  T origin_minus_root;  ///< origin − ρ, formed from offsets (0 for square pieces)
  T slope;              ///< Q'(ρ)
};

/// A parameter t as an end of the segment (0 or 1) plus an offset, t = end +
/// offset: differences of two such points keep the offsets' relative
/// accuracy when both are near the same end.
template <class T>
struct EndOffset {
  T end;
  T offset;
};
template <class T>
T operator-(const EndOffset<T>& x, const EndOffset<T>& y) {
  return (x.end - y.end) + (x.offset - y.offset);
}

/// Everything the integrand needs, in the translated, scaled, oriented frame.
template <class T>
struct Frame {
  int degree = 0;
  T tau0, dtau;          ///< τ(t) = τ0 + Δτ t, Δτ ≥ 0
  T sigma, sigma2;       ///< σ, σ²
  T alpha;               ///< leading coefficient of Q
  T t_star;              ///< parameter of the point of the line nearest to P
  std::array<T, 3> h;    ///< P − Γ(t*)
  std::array<T, 3> ab;   ///< B − A
};

/// Running sums of the three integrals: ∫ ξ^(i/2)/τ, ∫ ξ^((i−2)/2)/τ³ and
/// ∫ (t − t*) ξ^((i−2)/2)/τ³.
template <class T>
struct Sums {
  T f = T(0);
  T g0 = T(0);
  T g1 = T(0);
};

/// Adds the Gauss–Legendre rule on [a, b] (panel variable v) to sums.
template <class T>
void add_panel(const Frame<T>& fr, const Piece<T>& pc, const T& a, const T& b, bool with_grad, Sums<T>& sums) {
  using std::abs;
  using std::sqrt;
  using Rule = boost::math::quadrature::gauss<T, gauss_points<T>()>;
  const T half = (b - a) / 2;
  const T mid = (a + b) / 2;
  const bool odd = fr.degree % 2 == 1;
  const int i = fr.degree;
  auto node = [&](const T& x, const T& weight) {
    const T v = mid + half * x;
    T t, s, jac;
    if (pc.square) {
      const T v2 = v * v;
      t = pc.origin + T(pc.dir) * v2;
      s = T(pc.dir) * v2;
      jac = 2 * v;
    } else {
      t = pc.origin + T(pc.dir) * v;
      s = pc.origin_minus_root + T(pc.dir) * v;
      jac = T(1);
    }
    const T g = fr.alpha * s + pc.slope;
    const T tau = fr.tau0 + fr.dtau * t;
    // ξ = Q/(σ²τ²) as (s/τ)(g/τ)/σ²: near a cone tip s, g and τ are all small
    // and τ² alone would underflow first.
    const T inv_tau = T(1) / tau;
    const T xi = std::max(T(0), (s * inv_tau) * (g * inv_tau) / fr.sigma2);
    // ξ^(i/2) and ξ^((i−2)/2): integer powers of ξ, times √ξ for odd i.
    T xi_half_power, xi_grad_power;
    if (!odd) {
      xi_grad_power = integer_power(xi, (i - 2) / 2);
      xi_half_power = xi_grad_power * xi;
    } else {
      // √Q = v √|g| on a square piece (s = dir v², Q > 0 ⇒ dir·g > 0).
      const T root_xi = pc.square ? v * sqrt(abs(g)) * inv_tau / fr.sigma : sqrt(xi);
      xi_grad_power = integer_power(xi, (i - 3) / 2) * root_xi;
      xi_half_power = xi_grad_power * xi;
    }
    const T w = weight * half * jac;
    const T w_tau = w * inv_tau;
    sums.f += w_tau * xi_half_power;
    if (with_grad) {
      const T gw = w_tau * inv_tau * inv_tau * xi_grad_power;
      sums.g0 += gw;
      sums.g1 += gw * (t - fr.t_star);
    }
  };
  const auto& xs = Rule::abscissa();
  const auto& ws = Rule::weights();
  unsigned first = 0;
  if (gauss_points<T>() % 2 == 1) {
    node(T(0), ws[0]);
    first = 1;
  }
  for (unsigned j = first; j < xs.size(); ++j) {
    node(xs[j], ws[j]);
    node(-xs[j], ws[j]);
  }
}

/// How deep P is inside the support, from the exact inputs: Q(0) = σ²τ0² −
/// |AP|², Q(1) = σ²τ1² − |BP|² and the discriminant β² − αγ = σ²|W|² − |X|²
/// (W = Δτ AP + τ0 AB, X = AB × AP), each formed in double-word arithmetic
/// (skelconv/detail/double_word.hpp) and rounded once, in the frame scaled by 2^−e.
/// From the rounded AP, AB × AP and W, each carried an error ~ε of its
/// larger term (σ²τ², σ²|W|²): a relative error ε/η at relative depth η of
/// P inside the support, which F ~ η^((i+1)/2) multiplies by (i + 1)/2
/// (measured 1e-8 at η = 1e-7). A, B, P are the caller's points and τa, τb
/// its radii at A and B.
template <class T>
struct SupportDepths {
  T q_at_a;         ///< Q(0) = γ
  T q_at_b;         ///< Q(1)
  T disc;           ///< β² − αγ
  T ab_bp = T(0);   ///< AB·BP from the rounded vectors (support_depths; Q'(1)/2 = σ²Δτ τ1 + AB·BP)
};
template <class T>
SupportDepths<T> exact_support_depths(const std::array<T, 3>& A, const std::array<T, 3>& B,
                                      const std::array<T, 3>& P, const T& tau_a, const T& tau_b, const T& sigma,
                                      int e) {
  using std::ldexp;
  using detail::DoubleWord;
  using detail::word_add;
  using detail::word_multiply;
  using detail::word_negate;
  using detail::word_norm2;
  auto scaled_difference = [&](const T& x, const T& y) {
    const DoubleWord<T> d = detail::exact_word_difference(x, y);
    return DoubleWord<T>{ldexp(d.hi, -e), ldexp(d.lo, -e)};
  };
  auto rounded = [](const DoubleWord<T>& x) { return x.hi + x.lo; };
  DoubleWord<T> ab[3], ap[3], bp[3];
  for (int c = 0; c < 3; ++c) {
    ab[c] = scaled_difference(B[c], A[c]);
    ap[c] = scaled_difference(P[c], A[c]);
    bp[c] = scaled_difference(P[c], B[c]);
  }
  const DoubleWord<T> s{sigma, T(0)}, tau0{ldexp(tau_a, -e), T(0)}, tau1{ldexp(tau_b, -e), T(0)};
  const DoubleWord<T> dtau = scaled_difference(tau_b, tau_a);
  auto reach2 = [&](const DoubleWord<T>& tau) {  // σ²τ²
    const DoubleWord<T> r = word_multiply(s, tau);
    return word_multiply(r, r);
  };
  DoubleWord<T> w[3], x[3];
  for (int c = 0; c < 3; ++c) {
    const int j = (c + 1) % 3, k = (c + 2) % 3;
    w[c] = word_add(word_multiply(dtau, ap[c]), word_multiply(tau0, ab[c]));
    x[c] = word_add(word_multiply(ab[j], ap[k]), word_negate(word_multiply(ab[k], ap[j])));
  }
  SupportDepths<T> out;
  out.q_at_a = rounded(word_add(reach2(tau0), word_negate(word_norm2(ap))));
  out.q_at_b = rounded(word_add(reach2(tau1), word_negate(word_norm2(bp))));
  out.disc = rounded(word_add(word_multiply(word_multiply(s, s), word_norm2(w)), word_negate(word_norm2(x))));
  return out;
}

/// The three depths of exact_support_depths, from the rounded AB, AP, BP
/// (frame of scalis_compact_F) where that is accurate: each is a difference
/// of squares (x − y)(x + y) of two nonnegative terms known to a few ε, so
/// its relative error is a few ε (x + y)/|x − y|. Where any is below 1/32 of
/// its terms' sum (P near the support boundary), all three come from
/// exact_support_depths instead (~5 times the operations: always taken,
/// they tripled F's operation count at generic points, 238 → 777 additions
/// for degree 4, bench/results/scalis_compact_opcounts.md).
template <class T>
SupportDepths<T> support_depths(const std::array<T, 3>& A, const std::array<T, 3>& B, const std::array<T, 3>& P,
                                const T& tau_a, const T& tau_b, const T& sigma, const DownScale<T>& down,
                                const std::array<T, 3>& ab, const std::array<T, 3>& ap, const T& tau0,
                                const T& dtau) {
  using std::abs;
  using std::sqrt;
  auto length = [](const std::array<T, 3>& v) { return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); };
  bool shallow = false;
  auto difference_of_squares = [&shallow](const T& x, const T& y) {
    if (!(T(32) * abs(x - y) >= x + y)) shallow = true;
    return (x - y) * (x + y);
  };
  std::array<T, 3> bp, w, x;
  for (int c = 0; c < 3; ++c) {
    bp[c] = down(P[c] - B[c]);
    w[c] = dtau * ap[c] + tau0 * ab[c];
  }
  x = {ab[1] * ap[2] - ab[2] * ap[1], ab[2] * ap[0] - ab[0] * ap[2], ab[0] * ap[1] - ab[1] * ap[0]};
  SupportDepths<T> out;
  out.q_at_a = difference_of_squares(sigma * tau0, length(ap));
  out.q_at_b = difference_of_squares(sigma * down(tau_b), length(bp));
  out.disc = difference_of_squares(sigma * length(w), length(x));
  out.ab_bp = ab[0] * bp[0] + ab[1] * bp[1] + ab[2] * bp[2];
  if (!shallow) return out;
  SupportDepths<T> exact = exact_support_depths(A, B, P, tau_a, tau_b, sigma, down.e);
  exact.ab_bp = out.ab_bp;
  return exact;
}

/// Integrates one piece on Bernstein-graded panels.
/// t_sing[0 .. n_poles−1] are poles, the rest branch points.
template <class T>
void add_piece(const Frame<T>& fr, const Piece<T>& pc, const T* t_sing, int n_sing, int n_poles, bool with_grad,
               Sums<T>& sums) {
  using std::abs;
  using std::sqrt;
  // Singularities in the v plane.
  Singularity<T> z[8];
  int nz = 0;
  for (int k = 0; k < n_sing; ++k) {
    const T need = k < n_poles ? rho_min_pole<T>() : rho_min_branch<T>();
    const T w = T(pc.dir) * (t_sing[k] - pc.origin);  // v (linear) or v² (square)
    if (!pc.square) {
      z[nz++] = {w, T(0), need};
    } else if (w >= 0) {
      z[nz++] = {sqrt(w), T(0), need};
      z[nz++] = {-sqrt(w), T(0), need};
    } else {
      z[nz++] = {T(0), sqrt(-w), need};
      z[nz++] = {T(0), -sqrt(-w), need};
    }
  }
  // Bisections toward a singularity at distance δ: ~log2(ℓ/δ); δ ≥ 1e-308 ℓ
  // in double (P 1e-300 from a cone tip needs ~1000). A panel that still
  // fails the Bernstein test at this depth is not accurate: NotConvergedError
  // (wider exponent ranges, long double or binary128, can get there). A span
  // too short to split in T (its midpoint rounds to an end) is integrated as
  // it is: it is then within rounding of the singularity, and any finer
  // panel would be empty.
  constexpr int max_depth = 1100;
  struct Span {
    T a, b;
    int depth;
  };
  Span stack[max_depth + 2];
  int top = 0;
  stack[top++] = {T(0), pc.extent, 0};
  while (top > 0) {
    const Span sp = stack[--top];
    bool ok = true;
    for (int k = 0; k < nz && ok; ++k) ok = !(bernstein_rho(sp.a, sp.b, z[k]) < z[k].rho_min);
    const T m = (sp.a + sp.b) / 2;
    const bool splittable = sp.a < m && m < sp.b;
    if (!ok && splittable && sp.depth >= max_depth)
      throw NotConvergedError("compact SCALIS segment: Gauss panel bisection reached its maximum depth of " +
                              std::to_string(max_depth) + " levels before a panel passed the Bernstein test");
    if (ok || !splittable) {
      add_panel(fr, pc, sp.a, sp.b, with_grad, sums);
    } else {
      stack[top++] = {m, sp.b, sp.depth + 1};
      stack[top++] = {sp.a, m, sp.depth + 1};
    }
  }
}

/// What the evaluation reads of the segment alone: the segment oriented so
/// that Δτ ≥ 0 (the tip, if any, at t ≤ 0: F is symmetric in A ↔ B),
/// translated to A and scaled by 2^−e (exact) so that τ_max ∈ [1/2, 1), and
/// the coefficients of Q, ∇F and the closed forms that do not depend on P.
/// prepare_segment computes it once per segment (ScalisSegment's
/// constructor; scalis_compact_F of a whole ScalisSegmentInput at each call).
template <class T>
struct CompactSegment {
  int degree = 0;
  std::array<T, 3> A{}, B{};  ///< the caller's ends at t = 0 and t = 1 after orienting
  T tau_a, tau_b;             ///< the caller's radii at A and B
  DownScale<T> down{0};       ///< the scale 2^−e
  std::array<T, 3> ab;        ///< B − A, scaled
  T tau0, tau1, dtau;         ///< τ(0), τ(1) and τ(1) − τ(0), scaled
  T a2, length;               ///< |AB|², |AB|
  T sigma, sigma2, inv_sigma2;  ///< σ, σ², 1/σ²
  T alpha;                    ///< σ²Δτ² − |AB|², the leading coefficient of Q
  T sigma2_dtau;              ///< σ²Δτ: β = σ²Δτ τ0 + AB·AP, Q'(1)/2 = σ²Δτ τ1 + AB·BP
  T gradient_factor;          ///< −i |AB|/σ² (finish)
};
template <class T>
CompactSegment<T> prepare_segment(int degree, const ScalisSegmentInput<T>& in) {
  using std::frexp;
  using std::sqrt;
  const bool swap = in.tau1 < in.tau0;
  CompactSegment<T> s;
  s.degree = degree;
  s.A = swap ? in.b : in.a;
  s.B = swap ? in.a : in.b;
  s.tau_a = swap ? in.tau1 : in.tau0;
  s.tau_b = swap ? in.tau0 : in.tau1;
  int e = 0;
  (void)frexp(s.tau_b, &e);
  s.down = DownScale<T>(e);
  for (int c = 0; c < 3; ++c) s.ab[c] = s.down(s.B[c] - s.A[c]);
  s.tau0 = s.down(s.tau_a);
  s.tau1 = s.down(s.tau_b);
  s.dtau = s.tau1 - s.tau0;
  s.a2 = s.ab[0] * s.ab[0] + s.ab[1] * s.ab[1] + s.ab[2] * s.ab[2];
  s.length = sqrt(s.a2);
  s.sigma = in.sigma;
  s.sigma2 = in.sigma * in.sigma;
  s.inv_sigma2 = T(1) / s.sigma2;
  s.alpha = (in.sigma * s.dtau - s.length) * (in.sigma * s.dtau + s.length);
  s.sigma2_dtau = s.sigma2 * s.dtau;
  s.gradient_factor = -T(degree) * s.length / s.sigma2;
  return s;
}

/// The real roots of Q on the segment's line (the support's boundary),
/// ascending, each with Q'(root) and its offset from the segment end nearer
/// to it.
template <class T>
struct QRoots {
  int n = 0;
  T at[2];
  T slope[2];
  EndOffset<T> offset[2];
  T half_slope_at_b = T(0);  ///< Q'(1)/2 = α + β, from BP
};

/// Roots with Q'(root): r = γ/q has Q'(r) = 2 sign(β)√disc, r' = q/α has
/// −that (q = −(β + sign(β)√disc) ≠ 0, the stable quadratic formula).
///
/// Each root is then held as its offset from the segment end nearer to it,
/// t = end + offset. A root ρ near t = 1 held as the double ρ is off by ~ε
/// in absolute terms, which is a relative error ε/(1 − ρ) in s = t − ρ over a
/// support [ρ, 1] of width 1 − ρ (measured: 2.5e-13 in F, i = 10, a support
/// 0.01 long at B). Centred at B, Q(1 − u) = α u² − 2(α + β) u + Q(1), with
/// Q(1) = σ²τ1² − |BP|² and α + β = σ²Δτ τ1 + AB·BP formed from BP itself,
/// and the same stable formula gives u to the relative accuracy of Q(1).
/// (Near t = 0 the root itself is its offset.)
template <class T>
QRoots<T> support_roots(const Frame<T>& fr, const SupportDepths<T>& depths, const T& q, const T& sign_beta,
                        const T& sd, const T& sigma2_dtau, const T& tau1) {
  using std::abs;
  QRoots<T> r;
  r.at[r.n] = depths.q_at_a / q;
  r.slope[r.n++] = 2 * sign_beta * sd;
  if (fr.alpha != T(0)) {
    r.at[r.n] = q / fr.alpha;
    r.slope[r.n++] = -2 * sign_beta * sd;
  }
  if (r.n == 2 && r.at[1] < r.at[0]) {
    std::swap(r.at[0], r.at[1]);
    std::swap(r.slope[0], r.slope[1]);
  }
  const T half_slope_at_b = r.half_slope_at_b = sigma2_dtau * tau1 + depths.ab_bp;  // α + β
  const T q_b = half_slope_at_b + (half_slope_at_b < T(0) ? -sd : sd);
  for (int k = 0; k < r.n; ++k) {
    r.offset[k] = {T(0), r.at[k]};
    if (!(r.at[k] >= T(0.5)) || q_b == T(0)) continue;
    // u of the two roots (u = Q(1)/q_b and q_b/α): the one matching ρ_k.
    T u = depths.q_at_b / q_b;
    if (fr.alpha != T(0)) {
      const T other = q_b / fr.alpha;
      if (abs((T(1) - other) - r.at[k]) < abs((T(1) - u) - r.at[k])) u = other;
    }
    r.offset[k] = {T(1), -u};
  }
  return r;
}

/// The support [t1, t2] within [0, 1] and which of its ends are roots of Q.
template <class T>
struct Support {
  T t1 = T(0), t2 = T(1);
  EndOffset<T> end1{T(0), T(0)}, end2{T(1), T(0)};  ///< t1, t2 as offsets from an end
  int root_at_t1 = -1, root_at_t2 = -1;             ///< index into the roots, −1: a segment end
};
/// Q > 0 between the roots when α < 0, above the larger root when α > 0
/// (Δτ > 0), and on one side of the single root when α = 0 (Q = 2βt + γ).
template <class T>
Support<T> clip_to_support(const QRoots<T>& r, const T& alpha, const T& beta) {
  Support<T> s;
  auto clip_low = [&](int k) {
    if (r.at[k] > T(0)) {
      s.t1 = r.at[k];
      s.end1 = r.offset[k];
      s.root_at_t1 = k;
    }
  };
  auto clip_high = [&](int k) {
    if (r.at[k] < T(1)) {
      s.t2 = r.at[k];
      s.end2 = r.offset[k];
      s.root_at_t2 = k;
    }
  };
  if (r.n == 2 && alpha < T(0)) {
    clip_low(0);
    clip_high(1);
  } else if (r.n == 2) {
    clip_low(1);
  } else if (beta > T(0)) {
    clip_low(0);
  } else {
    clip_high(0);
  }
  return s;
}

/// t2 − t1: between two roots 2√disc/|α| (exact to rounding however close
/// they are), else from the offsets.
template <class T>
T support_width(const Frame<T>& fr, const Support<T>& s, const T& sd) {
  using std::abs;
  return s.root_at_t1 >= 0 && s.root_at_t2 >= 0 ? T(2) * sd / abs(fr.alpha) : s.end2 - s.end1;
}

/// The three integrals over the support, by pieces: one linear piece for
/// even i or a support bounded by segment ends; for odd i, two halves, each
/// a square piece (t = ρ ± v², removing the branch point of √Q) at an end
/// that is a root of Q, a linear one otherwise. Each piece's Gauss panels
/// are graded towards the singular points it still sees: the pole of 1/τ
/// and, for odd i, the other branch points.
template <class T>
Sums<T> integrate_support(const Frame<T>& fr, const QRoots<T>& r, const Support<T>& s, const T& sd,
                          bool with_grad) {
  using std::abs;
  using std::sqrt;
  const bool odd = fr.degree % 2 == 1;
  T t_sing[3]{};
  int n_sing = 0;
  if (fr.dtau > T(0)) t_sing[n_sing++] = -fr.tau0 / fr.dtau;
  const int n_poles = n_sing;
  if (odd)
    for (int k = 0; k < r.n; ++k) t_sing[n_sing++] = r.at[k];

  // For Q: the root nearest to a t range (any root works algebraically).
  auto nearest_root = [&](const T& lo, const T& hi) {
    int nearest = 0;
    T best = std::numeric_limits<T>::infinity();
    for (int k = 0; k < r.n; ++k) {
      const T d = r.at[k] < lo ? lo - r.at[k] : r.at[k] > hi ? r.at[k] - hi : T(0);
      if (d < best) {
        best = d;
        nearest = k;
      }
    }
    return nearest;
  };
  // A piece from the support end `origin` (`from` as offsets) towards the
  // other end, of t extent `extent`.
  auto linear_piece = [&](const T& origin, const EndOffset<T>& from, int dir, const T& extent) {
    const T lo = dir > 0 ? origin : origin - extent;
    const int k = nearest_root(lo, lo + extent);
    return Piece<T>{false, origin, dir, extent, from - r.offset[k], r.slope[k]};
  };
  auto square_piece = [&](int k, int dir, const T& extent) {
    return Piece<T>{true, r.at[k], dir, sqrt(extent), T(0), r.slope[k]};
  };
  // The singular points a square piece from root k still sees: its own
  // root's branch point is removed by the substitution.
  auto sing_without = [&](int k, T* out) {
    int n = 0;
    if (fr.dtau > T(0)) out[n++] = -fr.tau0 / fr.dtau;
    if (odd)
      for (int j = 0; j < r.n; ++j)
        if (j != k) out[n++] = r.at[j];
    return n;
  };

  Sums<T> sums;
  const T width = support_width(fr, s, sd);
  if (!odd || (s.root_at_t1 < 0 && s.root_at_t2 < 0)) {
    add_piece(fr, linear_piece(s.t1, s.end1, +1, width), t_sing, n_sing, n_poles, with_grad, sums);
    return sums;
  }
  const T half_width = width / 2;
  T sing[3];
  if (s.root_at_t1 >= 0) {
    add_piece(fr, square_piece(s.root_at_t1, +1, half_width), sing, sing_without(s.root_at_t1, sing), n_poles,
              with_grad, sums);
  } else {
    add_piece(fr, linear_piece(s.t1, s.end1, +1, half_width), t_sing, n_sing, n_poles, with_grad, sums);
  }
  if (s.root_at_t2 >= 0) {
    add_piece(fr, square_piece(s.root_at_t2, -1, half_width), sing, sing_without(s.root_at_t2, sing), n_poles,
              with_grad, sums);
  } else {
    add_piece(fr, linear_piece(s.t2, s.end2, -1, half_width), t_sing, n_sing, n_poles, with_grad, sums);
  }
  return sums;
}


/// What scalis_compact_F knows before the integral: the segment, the frame,
/// the roots of Q and the support; or, where no integral is needed (an empty
/// support, P at a cone tip), the answer itself.
template <class T>
struct Prepared {
  bool done = false;     ///< F is `value` (0, or +∞ at a cone tip), ∇F is 0 or NaN
  T value = T(0);
  bool grad_nan = false;  ///< with done: ∇F is NaN (F = +∞ at a cone tip)
  const CompactSegment<T>* segment = nullptr;
  Frame<T> fr;
  T beta = T(0);        ///< Q'(0)/2
  SupportDepths<T> depths{};
  T sd = T(0);          ///< √disc
  QRoots<T> roots;
  Support<T> support;
};

/// Everything before the integral at P (header comment of scalis_compact.hpp,
/// sections 1 and 4), from the segment's preparation.
template <class T>
Prepared<T> prepare(const CompactSegment<T>& sg, const std::array<T, 3>& p) {
  using std::sqrt;
  Prepared<T> pr;
  pr.segment = &sg;
  const std::array<T, 3>& ab = sg.ab;
  std::array<T, 3> ap;
  for (int c = 0; c < 3; ++c) ap[c] = sg.down(p[c] - sg.A[c]);
  const T a2 = sg.a2;
  pr.done = true;
  if (!(a2 > T(0))) return pr;
  const T b = ab[0] * ap[0] + ab[1] * ap[1] + ab[2] * ap[2];
  const T c2 = ap[0] * ap[0] + ap[1] * ap[1] + ap[2] * ap[2];  // |AP|²

  Frame<T>& fr = pr.fr;
  fr.degree = sg.degree;
  fr.tau0 = sg.tau0;
  fr.dtau = sg.dtau;
  fr.sigma = sg.sigma;
  fr.sigma2 = sg.sigma2;
  fr.alpha = sg.alpha;
  fr.t_star = b / a2;
  fr.ab = ab;
  for (int c = 0; c < 3; ++c) fr.h[c] = ap[c] - fr.t_star * ab[c];
  const T& alpha = fr.alpha;

  // P exactly at the cone tip: F = 0 (α ≤ 0) or +∞ (α > 0), see the header.
  // (c2 == 0 with AP ≠ 0: |AP|² underflowed, P within ~1e-154 τ_max of A in
  // double; treated as the tip, see the header.)
  const auto at_tip = [&]() {
    if (alpha > T(0)) {
      pr.value = std::numeric_limits<T>::infinity();
      pr.grad_nan = true;
    }
    return pr;
  };
  if (sg.tau0 == T(0) && c2 == T(0)) return at_tip();

  const T beta = pr.beta = sg.sigma2_dtau * sg.tau0 + b;
  pr.depths = support_depths(sg.A, sg.B, p, sg.tau_a, sg.tau_b, sg.sigma, sg.down, ab, ap, sg.tau0, sg.dtau);
  T disc = pr.depths.disc;
  if (!(disc > T(0))) {
    // α ≤ 0: Q ≤ 0 everywhere (empty support, or a tangent point).
    // α > 0: then disc ≥ 0 (the tip is between the roots); disc = 0 is P on
    // the apex of the extended cone, a double root at t_tip ≤ 0.
    if (!(alpha > T(0))) return pr;
    disc = T(0);
  }
  const T sd = pr.sd = sqrt(disc);
  const T sign_beta = beta < T(0) ? T(-1) : T(1);
  const T q = -(beta + sign_beta * sd);
  // q = 0 means β = 0 and disc = 0: a double root of Q at t = −β/α = 0. With
  // Q(t_tip) ≤ 0 that root is the tip (τ0 = 0, P = A: handled above unless
  // rounded), or Q ≤ 0 throughout (α ≤ 0); α = 0 as well would make Q ≡ γ,
  // which Q(t_tip) ≤ 0 excludes unless γ ≤ 0.
  if (q == T(0)) return alpha > T(0) && sg.tau0 == T(0) ? at_tip() : pr;

  pr.roots = support_roots(fr, pr.depths, q, sign_beta, sd, sg.sigma2_dtau, sg.tau1);
  pr.support = clip_to_support(pr.roots, alpha, beta);
  if (!(pr.support.t1 < pr.support.t2)) return pr;
  pr.done = false;
  return pr;
}

/// The support of a prepared evaluation in the form the generated closed
/// forms read (skelconv/primitives/scalis_compact_closed_form_input.hpp).
/// Q's Bernstein coefficients are b0 = Q(t1), b2 = Q(t2) (0 at a root, else
/// Q(0) or Q(1) from the exact inputs) and b1 = Q(t1) + Q'(t1) w/2 =
/// Q(t2) − Q'(t2) w/2, taken from the end where it is a sum of nonnegative
/// terms: Q'(t1) ≥ 0, or else Q'(t2) ≤ Q'(t1) < 0 (Q is convex only when
/// α > 0, and then Q' ≥ 0 on the support, which lies above the larger root).
/// τ(t1) is τ at t1's end plus Δτ times t1's offset from it.
template <class T>
ScalisCompactSupport<T> closed_form_input(const Prepared<T>& pr) {
  const Frame<T>& fr = pr.fr;
  const Support<T>& sp = pr.support;
  ScalisCompactSupport<T> s;
  s.width = support_width(fr, sp, pr.sd);
  s.tau_lo = (sp.end1.end == T(0) ? fr.tau0 : pr.segment->tau1) + fr.dtau * sp.end1.offset;
  s.rise = fr.dtau * s.width;
  s.tau_hi = s.tau_lo + s.rise;
  s.b0 = sp.root_at_t1 >= 0 ? T(0) : pr.depths.q_at_a;
  s.b2 = sp.root_at_t2 >= 0 ? T(0) : pr.depths.q_at_b;
  const T half_slope_lo = sp.root_at_t1 >= 0 ? pr.roots.slope[sp.root_at_t1] / 2 : pr.beta;
  const T half_slope_hi = sp.root_at_t2 >= 0 ? pr.roots.slope[sp.root_at_t2] / 2 : pr.roots.half_slope_at_b;
  s.b1 = half_slope_lo >= T(0) ? s.b0 + half_slope_lo * s.width : s.b2 - half_slope_hi * s.width;
  s.e0 = (sp.end1.end - fr.t_star) + sp.end1.offset;
  s.e1 = (sp.end2.end - fr.t_star) + sp.end2.offset;
  s.inv_sigma2 = pr.segment->inv_sigma2;
  return s;
}

/// F, and ∇F into *grad, from the three integrals (header comment of
/// scalis_compact.hpp, section 3): ∇F = −(i|AB|/σ²)(H ∫ ξ^((i−2)/2)/τ³ −
/// AB ∫ (t − t*) ξ^((i−2)/2)/τ³), then the scaling undone (∇F scales as
/// 1/scale).
template <class T>
T finish(const Prepared<T>& pr, const Sums<T>& sums, std::array<T, 3>* grad) {
  const CompactSegment<T>& sg = *pr.segment;
  if (grad != nullptr) {
    for (int c = 0; c < 3; ++c)
      (*grad)[c] = sg.down(sg.gradient_factor * (pr.fr.h[c] * sums.g0 - pr.fr.ab[c] * sums.g1));
  }
  return sg.length * sums.f;
}

}  // namespace detail

}  // namespace skelconv
