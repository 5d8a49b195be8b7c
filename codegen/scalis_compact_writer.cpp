// codegen/scalis_compact_writer.cpp — writes generated/scalis_segment_compact.hpp:
// the compact SCALIS segment of even degree i = 2m in closed form over its
// support (docs/mathematics.md §4, Zanni et al. 2013 §4.3), called by scalis_compact_F
// (include/skelconv/primitives/scalis_compact.hpp), which finds the support.
//
// The integrals. On the support [t1, t2], x = (t − t1)/w, Q is a quadratic
// with nonnegative Bernstein coefficients b0, b1, b2 and τ = τ(t1)(1 + λx)
// (skelconv/primitives/scalis_compact_closed_form_input.hpp), so each of the
// three integrals is, up to w/(σ^k τ(t1)^(i+1)),
//     ∫_0^1 p(x) (1 + λx)^−(i+1) dx,   p(x) = Σ_k d_k x^k (1 − x)^(i−k),
// with d the Bernstein coefficients (unnormalised) of Q^m, of Q^(m−1) raised
// to degree i, or of (t − t*) Q^(m−1) raised to degree i. Products and degree
// raising of such coefficients are sums of products of nonnegative numbers
// (t − t* aside): nothing cancels. The substitution y = (1 + λ)x/(1 + λx)
// turns x^k (1 − x)^(i−k) dx / (1 + λx)^(i+1) into ζ^(k+1) y^k (1 − y)^(i−k)
// dy / (1 − κy), with ζ = 1/(1 + λ) = τ(t1)/τ(t2) and κ = λ/(1 + λ) = Δτ w/τ(t2):
//     ∫_0^1 p(x) (1 + λx)^−(i+1) dx = Σ_k d_k ζ^(k+1) K_k,
//     K_k = ∫_0^1 y^k (1 − y)^(i−k) / (1 − κy) dy.
// Since (1 − y) + ζy = 1 − κy, K_k = β_k − ζ K_(k+1) with β_k = k!(i−1−k)!/i!:
// one K_s (a function of one variable κ ∈ [0, 1)) gives the others, downwards
// below s and upwards above. K_i = ∫_0^1 y^i/(1 − κy) dy = Σ_r κ^r/(i+1+r).
// Where κ is near 1 (the
// cone's tip near the support) it has the partial-fraction form of the paper,
// (ln(1 + λ) − Σ_{r=1}^{i} κ^r/r) / κ^(i+1), with its one logarithm; the
// difference cancels as κ decreases (Δτ w → 0), and there K_i is a
// polynomial in κ instead: Chebyshev interpolants on the pieces
// ζ ∈ [2^−p−1, 2^−p] (p = 0, 1, …), each with a proven bound.
//
// Accuracy. A relative error δ in K_s moves the sum Σ d_k ζ^(k+1) K_k by at
// most δ A_s(κ), A_s(κ) = max_k ζ^(s−k) K_s/K_k (the homogeneous solution of
// the recurrence, (−ζ)^(s−k), meets Σ_k d_k (−1)^(i−k), the x^i coefficient
// of p, which is at most Σ_k d_k for nonnegative d). A_i is C(i, m) at κ = 0
// (6 for i = 4, 252 for i = 10) and decreases with κ; each interpolant's s
// is the one of least A_s over its piece (≤ 1.33 for i ≤ 10).
//  * Interpolants: for K_i analytic inside the Bernstein ellipse E_ρ of a
//    piece, the interpolant at R + 1 Chebyshev points errs by at most
//    4Mρ^−R/(ρ − 1) (Trefethen, Approximation Theory and Approximation
//    Practice, Thm 8.2). K_s's only singularity is at κ = 1, and on E_ρ
//    |1 − κy| ≥ 1 − x_max (x_max the ellipse's rightmost point), so M ≤
//    β/(1 − x_max) while K_s ≥ β = ∫ y^s (1 − y)^(i−s) on the piece: R is the
//    smallest degree whose bound, minimised over ρ, is below 2^−56 relative.
//  * Partial fractions: ln and the polynomial are each accurate to rounding,
//    so K_i errs by at most u((ℓ + 2iP)/(ℓ − P) + i + 2) relative (ℓ = ln(1+λ),
//    P = Σ κ^r/r, u = 2^−53, the recurrence's own roundings included); the
//    form is taken from the first piece boundary κ = 1 − 2^−p beyond which
//    this bound times A(κ) stays below 1e-14 (checked on a grid of κ up to
//    1 − 2^−60, where it keeps decreasing).
// Where τ(t1) < 2^−40 τ(t2) or τ(t1) < 2^−60 (P within ~2^−40 of a cone tip,
// in the frame where τ_max ≈ 1), τ(t1)^−(i+1) could leave the double range:
// the functions return false and the runtime's Gauss panels take the point.
//
// Operation counts (opcounts.csv, family scalis_compact): per point, the
// code below, counted on the text written (op_count.hpp's rules), plus the
// runtime's work around it (prepare, closed_form_input, finish), measured on
// the counting scalar (helper_costs.hpp); per primitive, the runtime's
// prepare_segment, once per segment. The generic path is the first piece
// (κ ≤ 1/2, radii varying by less than a factor 2 over the support), the
// longest the partial-fraction form.
#include <algorithm>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include "helper_costs.hpp"
#include "kernel_writer.hpp"

namespace skelconv::codegen {

namespace {

using Real = boost::multiprecision::cpp_bin_float_50;

// ---------------------------------------------------------------- K_i(κ)

/// K_i(κ) = ∫_0^1 y^i/(1 − κy) dy to ~45 digits: the series (positive terms)
/// for κ ≤ 1/2, the partial fractions above (κ^(i+1) ≥ 2^−11: a few digits lost).
Real top_moment(int i, const Real& kappa) {
  if (kappa <= Real(0.5)) {
    Real sum = 0, power = 1;
    for (int r = 0; r < 200; ++r, power *= kappa) sum += power / Real(i + 1 + r);
    return sum;
  }
  Real partial = 0, power = 1;
  for (int r = 1; r <= i; ++r) {
    power *= kappa;
    partial += power / Real(r);
  }
  return (-log(Real(1) - kappa) - partial) / pow(kappa, i + 1);
}

/// β_k = ∫_0^1 y^k (1 − y)^(i−1−k) dy = k!(i−1−k)!/i!.
Real beta(int i, int k) {
  Real b = 1;
  for (int j = 1; j <= k; ++j) b *= Real(j);
  for (int j = 1; j <= i - 1 - k; ++j) b *= Real(j);
  for (int j = 1; j <= i; ++j) b /= Real(j);
  return b;
}

/// K_0 … K_i at κ (downwards from K_i; at most C(i, i/2) = 252 of the ~45
/// digits are lost).
std::vector<Real> all_moments(int i, const Real& kappa) {
  std::vector<Real> K(i + 1);
  K[i] = top_moment(i, kappa);
  for (int k = i - 1; k >= 0; --k) K[k] = beta(i, k) - (Real(1) - kappa) * K[k + 1];
  return K;
}

/// A_s(κ) = max_k ζ^(s−k) K_s/K_k: how much a relative error in K_s moves
/// Σ d_k ζ^(k+1) K_k (file comment) when the others come from K_s by the
/// recurrence, downwards below s and upwards above.
double amplification(int i, int s, const Real& kappa) {
  const std::vector<Real> K = all_moments(i, kappa);
  const Real zeta = Real(1) - kappa;
  Real worst = 0;
  for (int k = 0; k <= i; ++k) worst = std::max(worst, Real(pow(zeta, s - k) * K[s] / K[k]));
  return static_cast<double>(worst);
}

/// The bound of the partial-fraction form at κ (file comment), relative.
double partial_fraction_bound(int i, const Real& kappa) {
  const Real zeta = Real(1) - kappa;
  const Real ell = -log(zeta);
  Real partial = 0, power = 1;
  for (int r = 1; r <= i; ++r) {
    power *= kappa;
    partial += power / Real(r);
  }
  std::vector<Real> K(i + 1);
  K[i] = (ell - partial) / pow(kappa, i + 1);
  for (int k = i - 1; k >= 0; --k) K[k] = beta(i, k) - zeta * K[k + 1];
  Real amplification = 0;
  for (int k = 0; k <= i; ++k) amplification = std::max(amplification, Real(pow(zeta, i - k) * K[i] / K[k]));
  const Real u = pow(Real(2), -53);
  return static_cast<double>(u * ((ell + 2 * i * partial) / (ell - partial) + i + 2) * amplification);
}

constexpr double kPartialFractionTarget = 1e-14;

/// The first piece p whose lower end κ = 1 − 2^−p starts the partial-fraction
/// region: the bound holds there and at every grid point beyond.
int partial_fraction_piece(int i) {
  auto holds_from = [&](int p) {
    for (int q4 = 4 * p; q4 <= 4 * 60; ++q4)
      if (partial_fraction_bound(i, Real(1) - pow(Real(2), -Real(q4) / 4)) > kPartialFractionTarget) return false;
    return true;
  };
  for (int p = 1; p < 30; ++p)
    if (holds_from(p)) return p;
  throw std::logic_error("scalis compact: no partial-fraction region below 1 − 2^−30");
}

// ------------------------------------------------------ Chebyshev pieces

/// K_s on ζ ∈ [2^−p−1, 2^−p], i.e. κ = c + h s, s ∈ [−1, 1], c = 1 − 3h,
/// h = 2^−p−2: K_s ≈ Σ_j a_j s^j, s the start index of least amplification.
struct Piece {
  int p;
  int start;                 ///< s: the interpolant is K_s, the others by the recurrence
  double amplification;      ///< max of A_s over the piece
  double kappa_hi;           ///< 1 − 2^−p−1
  double center, inv_half;   ///< c and 1/h
  int degree;                ///< R
  double bound;              ///< the interpolation bound, relative
  std::vector<double> monomial;  ///< a_0 … a_R
};

/// The interpolation bound of degree R on piece p (file comment), minimised over ρ.
double interpolation_bound(int p, int R) {
  const double h = std::ldexp(1.0, -p - 2);
  const double rho_max = 3 + std::sqrt(8.0);  // the ellipse through κ = 1
  double best = 1e300;
  for (int k = 1; k < 1000; ++k) {
    const double rho = 1 + (rho_max - 1) * k / 1000.0;
    const double gap = h * (3 - (rho + 1 / rho) / 2);  // 1 − x_max
    best = std::min(best, 4 * std::pow(rho, -R) / ((rho - 1) * gap));
  }
  return best;
}

Piece chebyshev_piece(int i, int p) {
  Piece piece;
  piece.p = p;
  const Real h = pow(Real(2), -p - 2);
  const Real c = Real(1) - 3 * h;
  piece.kappa_hi = static_cast<double>(Real(1) - 2 * h);
  piece.center = static_cast<double>(c);
  piece.inv_half = static_cast<double>(Real(1) / h);
  const double target = std::ldexp(1.0, -56);
  int R = 1;
  while (interpolation_bound(p, R) > target) ++R;
  piece.degree = R;
  piece.bound = interpolation_bound(p, R);
  // The start index with the smallest amplification over the piece (on a
  // grid of 17 points): from 252 (i = 10, s = i) down to about 1.3 near κ = 0.
  piece.start = i;
  piece.amplification = 1e300;
  for (int start = 0; start <= i; ++start) {
    double worst = 0;
    for (int g = 0; g <= 16; ++g) worst = std::max(worst, amplification(i, start, c + h * Real(-1 + g / 8.0)));
    if (worst < piece.amplification) {
      piece.amplification = worst;
      piece.start = start;
    }
  }
  // Chebyshev coefficients from the values at the R + 1 points of the first kind.
  const Real pi = boost::math::constants::pi<Real>();
  std::vector<Real> values(R + 1), nodes(R + 1);
  for (int j = 0; j <= R; ++j) {
    nodes[j] = cos(pi * (Real(j) + Real(0.5)) / Real(R + 1));
    values[j] = all_moments(i, c + h * nodes[j])[piece.start];
  }
  std::vector<Real> cheb(R + 1);
  for (int k = 0; k <= R; ++k) {
    Real sum = 0;
    for (int j = 0; j <= R; ++j) sum += values[j] * cos(Real(k) * pi * (Real(j) + Real(0.5)) / Real(R + 1));
    cheb[k] = sum * 2 / Real(R + 1);
  }
  cheb[0] /= 2;
  // To monomials in s: T_0 = 1, T_1 = s, T_(k+1) = 2s T_k − T_(k−1).
  std::vector<Real> mono(R + 1, Real(0)), t_prev(R + 1, Real(0)), t_cur(R + 1, Real(0));
  t_prev[0] = 1;
  mono[0] += cheb[0];
  if (R >= 1) {
    t_cur[1] = 1;
    mono[1] += cheb[1];
  }
  for (int k = 1; k < R; ++k) {
    std::vector<Real> t_next(R + 1, Real(0));
    for (int j = 0; j <= R; ++j) {
      if (j >= 1) t_next[j] += 2 * t_cur[j - 1];
      t_next[j] -= t_prev[j];
    }
    for (int j = 0; j <= R; ++j) mono[j] += cheb[k + 1] * t_next[j];
    t_prev = t_cur;
    t_cur = t_next;
  }
  for (const Real& a : mono) piece.monomial.push_back(static_cast<double>(a));
  // The double Horner form against K_i on a grid: rounding of the
  // coefficients and of Horner's rule, which the bound above leaves out.
  double worst = 0;
  for (int j = 0; j <= 64; ++j) {
    const double s = -1 + j / 32.0;
    double v = piece.monomial[R];
    for (int k = R - 1; k >= 0; --k) v = v * s + piece.monomial[k];
    const Real exact = all_moments(i, c + h * Real(s))[piece.start];
    worst = std::max(worst, static_cast<double>(abs((Real(v) - exact) / exact)));
  }
  if (worst > std::ldexp(1.0, -50))
    throw std::logic_error("scalis compact: the Horner form of piece " + std::to_string(p) + " of degree " +
                           std::to_string(i) + " errs by " + std::to_string(worst));
  return piece;
}

// --------------------------------------------------------- code writing

std::string literal(double x) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", x);
  return std::string("T(") + text + ")";
}

/// C++ statements with their operation count (op_count.hpp's rules), counted
/// on the text: every binary + − × / is written with spaces around it,
/// unary minus without.
class Block {
 public:
  explicit Block(int indent) : indent_(indent) {}
  void line(const std::string& s) {
    text_ += std::string(2 * indent_, ' ') + s + '\n';
    for (const char* op : {" + ", " - "}) ops_.add += occurrences(s, op);
    ops_.mul += occurrences(s, " * ");
    ops_.div += occurrences(s, " / ");
    ops_.log += occurrences(s, "log(");
  }
  /// A line whose operations are not executed (a comment).
  void comment(const std::string& s) { text_ += std::string(2 * indent_, ' ') + "// " + s + '\n'; }
  void append(const Block& b) {
    text_ += b.text_;
    ops_ += b.ops_;
  }
  const std::string& text() const { return text_; }
  const OpCount& ops() const { return ops_; }

 private:
  static int occurrences(const std::string& s, const std::string& what) {
    int n = 0;
    for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
    return n;
  }
  int indent_;
  std::string text_;
  OpCount ops_;
};

/// x^k (k ≥ 1) as `name`, by binary powering from x; returns the name.
std::string power(Block& b, const std::string& x, int k, const std::string& name) {
  if (k == 1) return x;
  std::vector<std::string> bits;  // x^(2^j)
  std::string result;
  std::string square = x;
  int n = k, j = 0;
  while (n > 0) {
    if (n & 1) {
      if (result.empty()) {
        result = square;
      } else {
        const std::string next = name + "_" + std::to_string(j);
        b.line("const T " + next + " = " + result + " * " + square + ";");
        result = next;
      }
    }
    n >>= 1;
    if (n > 0) {
      const std::string next = name + "_sq" + std::to_string(++j);
      b.line("const T " + next + " = " + square + " * " + square + ";");
      square = next;
    }
  }
  b.line("const T " + name + " = " + result + ";");
  return name;
}

/// Names of polynomial coefficients (x^k (1 − x)^(n−k), unnormalised).
using Poly = std::vector<std::string>;

/// r = p · q, written term by term.
Poly multiply(Block& b, const Poly& p, const Poly& q, const std::string& name) {
  Poly r;
  for (std::size_t k = 0; k + 1 < p.size() + q.size(); ++k) {
    std::string sum;
    for (std::size_t a = 0; a < p.size(); ++a) {
      if (k < a || k - a >= q.size()) continue;
      const std::string term = p[a] + " * " + q[k - a];
      sum = sum.empty() ? term : sum + " + " + term;
    }
    r.push_back(name + std::to_string(k));
    b.line("const T " + r.back() + " = " + sum + ";");
  }
  return r;
}

/// p raised by one degree: r_k = p_k + p_(k−1) (times (1 − x) + x = 1).
Poly raise(Block& b, const Poly& p, const std::string& name) {
  Poly r;
  for (std::size_t k = 0; k <= p.size(); ++k) {
    std::string sum;
    if (k < p.size()) sum = p[k];
    if (k >= 1) sum = sum.empty() ? p[k - 1] : sum + " + " + p[k - 1];
    r.push_back(name + std::to_string(k));
    b.line("const T " + r.back() + " = " + sum + ";");
  }
  return r;
}

/// Σ_k d_k ζ^(k+1) K_k by Horner's rule in ζ.
std::string weighted_sum(Block& b, const Poly& d, const std::string& name) {
  const int i = static_cast<int>(d.size()) - 1;
  b.line("T " + name + " = " + d[i] + " * k" + std::to_string(i) + ";");
  for (int k = i - 1; k >= 0; --k)
    b.line(name + " = " + name + " * zeta + " + d[k] + " * k" + std::to_string(k) + ";");
  b.line(name + " = " + name + " * zeta;");
  return name;
}

std::string kernel_name(int i) { return "scalis_segment_compact_i" + std::to_string(i); }

/// One function: `which` 0 f, 1 g0 and g1, 2 all three.
std::string function_text(int i, int which, const std::vector<Piece>& pieces, int closed_piece,
                          SplitKernel& kernel) {
  const int m = i / 2;
  const bool value = which != 1, gradient = which != 0;
  Block common(1);
  common.comment("Near a cone tip τ(t1)^−(i+1) could leave the range of T: the panels take it.");
  common.line("if (!(in.tau_lo >= T(0x1p-40) * in.tau_hi && in.tau_lo >= T(0x1p-60))) return false;");
  common.line("const T inv_tau_hi = T(1) / in.tau_hi;");
  common.line("const T zeta = in.tau_lo * inv_tau_hi;");
  common.line("const T kappa = in.rise * inv_tau_hi;");
  common.line("const T inv_tau_lo = T(1) / in.tau_lo;");
  std::string declared = "T k0";
  for (int k = 1; k <= i; ++k) declared += ", k" + std::to_string(k);
  common.line(declared + ";  // K_k = ∫_0^1 y^k (1 − y)^(i−k)/(1 − κ y) dy");
  // The recurrence from K_start: downwards K_k = β_k − ζ K_(k+1), upwards
  // K_(k+1) = (β_k − K_k)/ζ, 1/ζ = τ(t2)/τ(t1).
  auto recurrence = [&](Block& f, int start) {
    if (start < i) f.line("const T inv_zeta = in.tau_hi * inv_tau_lo;");
    for (int k = start - 1; k >= 0; --k)
      f.line("k" + std::to_string(k) + " = " + literal(static_cast<double>(beta(i, k))) + " - zeta * k" +
             std::to_string(k + 1) + ";");
    for (int k = start; k < i; ++k)
      f.line("k" + std::to_string(k + 1) + " = (" + literal(static_cast<double>(beta(i, k))) + " - k" +
             std::to_string(k) + ") * inv_zeta;");
  };
  // One block per form.
  std::vector<Block> forms;
  for (const Piece& piece : pieces) {
    Block f(2);
    char why[240];
    std::snprintf(why, sizeof why,
                  "κ ≤ %.17g: K_%d by a Chebyshev interpolant of degree %d (bound %.1e relative), the others by "
                  "the recurrence (amplification ≤ %.2f)",
                  piece.kappa_hi, piece.start, piece.degree, piece.bound, piece.amplification);
    f.comment(why);
    const std::string top = "k" + std::to_string(piece.start);
    f.line("const T s = (kappa - " + literal(piece.center) + ") * " + literal(piece.inv_half) + ";");
    f.line(top + " = " + literal(piece.monomial[piece.degree]) + ";");
    for (int k = piece.degree - 1; k >= 0; --k) f.line(top + " = " + top + " * s + " + literal(piece.monomial[k]) + ";");
    recurrence(f, piece.start);
    forms.push_back(f);
  }
  {
    Block f(2);
    char why[200];
    std::snprintf(why, sizeof why,
                  "κ > %.17g: partial fractions, K_%d = (ln(1 + λ) − Σ_{r=1}^{%d} κ^r/r) / κ^%d (bound %.0e with "
                  "the recurrence)",
                  1 - std::ldexp(1.0, -closed_piece), i, i, i + 1, kPartialFractionTarget);
    f.comment(why);
    const std::string top = "k" + std::to_string(i);
    f.line("const T ell = log(in.tau_hi * inv_tau_lo);");
    f.line("T partial = " + literal(1.0 / i) + ";");
    for (int r = i - 1; r >= 1; --r) f.line("partial = partial * kappa + " + literal(1.0 / r) + ";");
    f.line("partial = partial * kappa;");
    const std::string kp = power(f, "kappa", i + 1, "kappa_power");
    f.line(top + " = (ell - partial) / " + kp + ";");
    recurrence(f, i);
    forms.push_back(f);
  }
  Block body(1);
  body.append(common);
  OpCount generic = common.ops(), longest = common.ops();
  OpCount longest_form;
  for (std::size_t f = 0; f < forms.size(); ++f) {
    std::string opening;
    if (f == 0) opening = "if (kappa <= " + literal(pieces[0].kappa_hi) + ") {";
    else if (f + 1 < forms.size()) opening = "} else if (kappa <= " + literal(pieces[f].kappa_hi) + ") {";
    else opening = "} else {";
    body.line(opening);
    body.append(forms[f]);
    if (forms[f].ops().total() > longest_form.total()) longest_form = forms[f].ops();
  }
  body.line("}");
  generic += forms[0].ops();
  longest += longest_form;
  Block rest(1);
  const Poly q = {"in.b0", "q1", "in.b2"};
  // Q is read by f and, from degree 4 on, by ∇f (through Q^(m−1)); the
  // gradient of degree 2 has the constant coefficients d0 below instead.
  if (value || m >= 2) {
    rest.comment("Q's Bernstein coefficients, unnormalised (the 2 of 2 b1 x(1 − x) in q1), and their products");
    rest.line("const T q1 = in.b1 + in.b1;");
  }
  Poly lower = {"T(1)"};  // Q^(m−1)
  if (m >= 2) lower = q;
  for (int j = 2; j <= m - 1; ++j) lower = multiply(rest, lower, q, "qp" + std::to_string(j) + "_");
  rest.comment("1/τ(t1)^(i+1), 1/σ^(i−2)");
  const std::string tau_power = power(rest, "inv_tau_lo", i + 1, "inv_tau_lo_power");
  std::string sigma_lower = "T(1)";
  if (m >= 2) sigma_lower = power(rest, "in.inv_sigma2", m - 1, "inv_sigma_power");
  rest.line("const T scale = in.width * " + tau_power + ";");
  if (value) {
    const Poly top_poly = m == 1 ? q : multiply(rest, lower, q, "qp" + std::to_string(m) + "_");
    const std::string s = weighted_sum(rest, top_poly, "sum_f");
    rest.line("out.f = scale * " + (m >= 2 ? sigma_lower + " * in.inv_sigma2" : std::string("in.inv_sigma2")) +
              " * " + s + ";");
  }
  if (gradient) {
    Poly d0;
    if (m == 1) {
      d0 = {"T(1)", "T(2)", "T(1)"};
    } else {
      d0 = raise(rest, raise(rest, lower, "lower_raised_"), "g0_coefficient");
    }
    const Poly linear = {"in.e0", "in.e1"};
    const Poly d1 = raise(rest, m == 1 ? linear : multiply(rest, lower, linear, "along_"), "g1_coefficient");
    const std::string s0 = weighted_sum(rest, d0, "sum_g0");
    const std::string s1 = weighted_sum(rest, d1, "sum_g1");
    const std::string factor = m >= 2 ? "scale_g" : "scale";
    if (m >= 2) rest.line("const T scale_g = scale * " + sigma_lower + ";");
    rest.line("out.g0 = " + factor + " * " + s0 + ";");
    rest.line("out.g1 = " + factor + " * " + s1 + ";");
  }
  rest.line("return true;");
  generic += rest.ops();
  longest += rest.ops();
  const OpCount around = helper_costs::scalis_compact_around_closed_form(i, gradient);
  kernel.ops[which] = generic + around;
  kernel.ops_longest[which] = longest + around;
  kernel.ops_primitive[which] = helper_costs::scalis_compact_segment_preparation(i);

  static const char* kWhat[] = {"f", "g0 and g1", "f, g0 and g1"};
  std::ostringstream os;
  os << "/// " << kWhat[which] << " of the compact SCALIS segment of degree " << i
     << " over its support (file comment); false where\n"
     << "/// no form is proven accurate (P near a cone tip).\n"
     << "/// Operations here: " << ops_text(generic) << " (generic form), longest " << ops_text(longest)
     << ";\n/// with the runtime's work around it, per point: " << ops_text(kernel.ops[which])
     << ";\n/// once per segment (prepare_segment): " << ops_text(kernel.ops_primitive[which]) << ".\n"
     << "template <class T>\n"
     << "bool " << kernel_name(i) << "_" << kFunctionSuffix[which]
     << "(const ScalisCompactSupport<T>& in, ScalisCompactIntegrals<T>& out) {\n"
     << "  using std::log;\n"
     << body.text() << rest.text() << "}\n\n";
  return os.str();
}

}  // namespace

std::string write_scalis_compact_file(const GeneratorRequest& request, const std::filesystem::path& folder) {
  std::ostringstream body, dispatch, csv;
  for (int i : request.scalis_compact_degrees) {
    if (i < 2 || i % 2 != 0) throw std::logic_error("scalis compact closed forms: even degrees ≥ 2 only");
    const int closed_piece = partial_fraction_piece(i);
    std::vector<Piece> pieces;
    for (int p = 0; p < closed_piece; ++p) pieces.push_back(chebyshev_piece(i, p));
    SplitKernel kernel;
    for (int which = 0; which < 3; ++which) body << function_text(i, which, pieces, closed_piece, kernel);
    dispatch << "    case " << i << ":\n      return which == 0 ? " << kernel_name(i) << "_f(in, out) : which == 1 ? "
             << kernel_name(i) << "_grad(in, out) : " << kernel_name(i) << "_f_and_grad(in, out);\n";
    csv << split_csv_rows(kernel_name(i), "scalis_compact", i, 0, kernel);
  }
  std::ostringstream os;
  os << file_header("scalis_segment_compact.hpp",
                    "the compact SCALIS segment of even degree in closed form over its support.", request)
     << "// Method, bounds and where each form is taken: codegen/scalis_compact_writer.cpp.\n"
     << "// Inputs and outputs: skelconv/primitives/scalis_compact_closed_form_input.hpp.\n"
     << "#pragma once\n\n#include <cmath>\n\n"
     << "#include <skelconv/primitives/scalis_compact_closed_form_input.hpp>\n\n"
     << "namespace skelconv::generated {\n\n"
     << body.str()
     << "/// The closed form of degree `degree` (`which`: 0 f, 1 g0 and g1, 2 all three); false for a\n"
     << "/// degree without one, or where it declines.\n"
     << "template <class T>\n"
     << "bool scalis_segment_compact_closed_form(int degree, int which, const ScalisCompactSupport<T>& in,\n"
     << "                                        ScalisCompactIntegrals<T>& out) {\n"
     << "  switch (degree) {\n"
     << dispatch.str() << "    default:\n      return false;\n  }\n}\n\n"
     << "}  // namespace skelconv::generated\n";
  write_file(folder / "scalis_segment_compact.hpp", os.str());
  return csv.str();
}

}  // namespace skelconv::codegen
