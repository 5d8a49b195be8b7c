// verify/reference_quadrature.hpp — the reference value of a segment field and
// its gradient, by adaptive quadrature of the DEFINITION integral (docs/mathematics.md §2)
//
//     f(P)  = |AB| ∫_{t0}^{t1} w(t) K(|P − Γ(t)|) dt,           Γ(t) = A + t AB
//     ∇f(P) = |AB| ∫_{t0}^{t1} w(t) K'(r)/r (P − Γ(t)) dt,       r = |P − Γ(t)|
//
// in binary128, with the kernel of verify/kernel_definitions.hpp. Nothing here
// uses a, b, c or any closed form: the distance is the Euclidean norm of
// P − Γ(t) formed from the coordinates.
//
// Method.
//  * The interval is split at t* = clamp(AB·AP/|AB|², t0, t1), the point of the
//    segment nearest to P, where every kernel peaks; for the compact family
//    [t0, t1] is the part inside the support ball (clip_to_ball in binary128),
//    so the support boundary is an interval end too. Every peak and every
//    kink of the integrand is therefore at an end of a piece, where tanh-sinh
//    clusters its nodes double-exponentially (a peak of width 1e-6 is
//    resolved without any adaptivity in the interior).
//  * We integrate in u = t − t* and keep H = P − Γ(t*), so P − Γ(t) = H − u AB
//    is formed without cancellation near the peak.
//  * Moments, not weighted integrands: on each piece we compute
//        M_j = ∫ u^j φ(t) dt   (j = 0..3),   φ  = K(r)
//        N_j = ∫ u^j φ'(t) dt  (j = 0..4),   φ' = K'(r)/r
//    Each is sign-definite on a piece (u has one sign, K > 0, K' < 0), so its
//    relative error is meaningful. With w(t*+u) = Σ_j v_j u^j (the weight
//    re-expanded about t*, exactly in binary128 arithmetic),
//        f  = |AB| Σ_j v_j M_j
//        ∇f = |AB| (H Σ_j v_j N_j − AB Σ_j v_j N_{j+1}),
//    so one set of moments serves every weight degree 0..3.
//  * The 9 moments of a piece share their nodes: one pass of the tanh-sinh
//    rule (tanh_sinh_moments.hpp) evaluates the kernel once per node and sums
//    all nine.
//  * Error control: the rule stops when two successive levels differ by
//    ≤ tolerance · L1 for every moment and returns that difference as its
//    error estimate (pessimistic: the true error of a double-exponential
//    rule is about its square). We propagate the estimates through the
//    combination above and
//    report a relative error estimate for f and for |∇f|; a reference whose
//    estimate exceeds `flag_threshold` is flagged, and the sweep excludes and
//    counts it instead of trusting it.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "extended_precision.hpp"
#include "kernel_definitions.hpp"
#include "skelconv/detail/clip.hpp"
#include "tanh_sinh_moments.hpp"

namespace skelconv::verify {

/// Accuracy requested from, and demanded of, the reference.
struct ReferenceTolerances {
  /// Requested relative accuracy of every moment (tanh-sinh `tolerance`,
  /// relative to the L1 norm, which equals |moment| since moments are
  /// sign-definite on a piece). binary128 rounding is ~1e-34, so 1e-25 is
  /// reachable and leaves a margin of 9 digits over double's 1e-16.
  double requested = 1e-25;
  /// A reference whose propagated relative error estimate exceeds this is
  /// not used to judge anything (flagged, excluded and counted): 1e-20 still
  /// resolves the double results to ~4 digits of their own error.
  double flag_threshold = 1e-20;
  /// tanh-sinh refinements at most (each halves the step, tanh_sinh_moments.hpp).
  std::size_t max_levels = 15;

  /// The stronger reference a flagged sample is retried with before it is
  /// excluded: 1e-30 requested (four digits above binary128's rounding) and
  /// five more levels (32 times the finest step count). Same flag threshold.
  ReferenceTolerances retry() const {
    ReferenceTolerances stronger = *this;
    stronger.requested = std::min(requested, 1e-30);
    stronger.max_levels = max_levels + 5;
    return stronger;
  }
};

inline constexpr int moment_count_f = 4;     // M_0..M_3: weight degree ≤ 3
inline constexpr int moment_count_grad = 5;  // N_0..N_4: N_{j+1} for ∇f

/// The moments of one problem (kernel, A, B, P, support) about t*.
struct SegmentMoments {
  bool empty = false;  ///< compact family: the support ball misses the segment (f = 0)
  extended length;     ///< |AB|
  extended t_star;     ///< expansion point, peak of the integrand
  Vec3<extended> ab;   ///< B − A
  Vec3<extended> h;    ///< P − Γ(t*)
  std::array<extended, moment_count_f> m{};         ///< ∫ u^j K dt
  std::array<extended, moment_count_f> m_error{};   ///< estimated absolute errors
  std::array<extended, moment_count_grad> n{};      ///< ∫ u^j K'/r dt
  std::array<extended, moment_count_grad> n_error{};
  std::size_t kernel_evaluations = 0;
  std::size_t max_levels_used = 0;
};

/// The reference field for one weight.
struct ReferenceField {
  extended f;
  Vec3<extended> grad;
  extended f_relative_error;     ///< propagated estimate, relative to |f|
  extended grad_relative_error;  ///< propagated estimate, relative to |∇f|
  bool flagged = false;          ///< an estimate exceeds the flag threshold
};

namespace detail {

inline constexpr int moment_count = moment_count_f + moment_count_grad;

/// Width, in units of t, of the peak of u ↦ K(|H − u AB|) at u = 0, where
/// `sigma` = |H|/|AB| is P's distance to Γ(t*) in the same units: the
/// trait's peak width at distance σ|AB|, divided by |AB| (p^i: σ; c_s^i:
/// √(σ² + 1/(sL²)); Gaussian: 1/(√a L); finite-support kernels: +∞, no
/// substitution).
inline extended peak_width(const KernelDefinition<extended>& kernel, const extended& sigma, const extended& length) {
  return kernel.peak_width(sigma * length) / length;
}

/// Variable of integration on one piece u ∈ [0, extent] (or its mirror
/// [−extent, 0] when direction = −1). When the peak at u = 0 is narrower than
/// the piece we substitute u = w sinh(x), w the peak width: the integrand
/// ~ (u² + w²)^(-i/2) becomes ~ cosh(x)^(1-i), smooth and of width O(1), so
/// tanh-sinh needs as few nodes for a peak of width 1e-6 as for a flat
/// integrand (the singularities at u = ±i w move to x = ±iπ/2). Otherwise u = x.
class PieceMap {
 public:
  PieceMap(const extended& extent, int direction, const extended& width)
      : direction_(direction), width_(width), stretched_(width < extent) {
    using std::asinh;
    x_end_ = stretched_ ? asinh(extent / width) : extent;
  }
  extended x_end() const { return x_end_; }
  /// (u, du/dx) at x.
  std::pair<extended, extended> operator()(const extended& x) const {
    using std::exp;
    if (!stretched_) return {direction_ * x, extended(1)};
    // sinh and cosh from one exp. The cancellation in e − 1/e near x = 0
    // costs relative accuracy of u only where |u| ≪ w, i.e. an absolute
    // error ~1e-34 w in u: invisible in r and in the moments.
    const extended e = exp(x);
    const extended inverse_e = 1 / e;
    return {direction_ * width_ * (e - inverse_e) / 2, width_ * (e + inverse_e) / 2};
  }

 private:
  int direction_;
  extended width_;
  bool stretched_;
  extended x_end_;
};

}  // namespace detail

/// Owns the tanh-sinh tables (grown on demand; one per thread).
class ReferenceIntegrator {
 public:
  explicit ReferenceIntegrator(ReferenceTolerances tolerances = {})
      : tolerances_(tolerances), rule_(tolerances.max_levels) {}

  const ReferenceTolerances& tolerances() const { return tolerances_; }
  /// Kernel evaluations so far (cost indicator).
  std::uint64_t kernel_evaluations() const { return total_evaluations_; }

  /// Moments over [t0, t1] (pass 0, 1 for inverse and cauchy). For the
  /// compact family use `moments` below, which clips first.
  SegmentMoments moments_on_interval(const KernelDefinition<extended>& kernel, const Vec3<extended>& a,
                                     const Vec3<extended>& b, const Vec3<extended>& p, const extended& t0,
                                     const extended& t1) {
    SegmentMoments out;
    out.ab = sub(b, a);
    out.length = norm(out.ab);
    const Vec3<extended> ap = sub(p, a);
    const extended t_nearest = dot(out.ab, ap) / dot(out.ab, out.ab);
    out.t_star = std::clamp(t_nearest, t0, t1);
    out.h = axpy(-out.t_star, out.ab, ap);  // P − Γ(t*) = AP − t* AB
    const extended peak_width = detail::peak_width(kernel, norm(out.h) / out.length, out.length);

    // Pieces in u = t − t*: [0, t1 − t*] and [0, t* − t0] mirrored (direction −1).
    const std::array<std::pair<extended, int>, 2> pieces{{{t1 - out.t_star, +1}, {out.t_star - t0, -1}}};
    for (const auto& [extent, direction] : pieces) {
      if (!(extent > 0)) continue;
      const detail::PieceMap map(extent, direction, peak_width);
      const auto integrands = [&](const extended& x) {
        const auto [u, jacobian] = map(x);
        const Vec3<extended> d = axpy(-u, out.ab, out.h);  // P − Γ(t* + u)
        const extended r = norm(d);
        const extended phi = kernel.value(r) * jacobian;
        const extended dphi = kernel.derivative_over_r(r) * jacobian;
        std::array<extended, detail::moment_count> g;  // M_0..M_3 then N_0..N_4
        extended u_power(1);
        for (int j = 0; j < moment_count_grad; ++j) {
          if (j < moment_count_f) g[j] = u_power * phi;
          g[moment_count_f + j] = u_power * dphi;
          u_power *= u;
        }
        return g;
      };
      const SharedIntegrals<detail::moment_count> piece =
          rule_.integrate<detail::moment_count>(integrands, map.x_end(), extended(tolerances_.requested));
      for (int k = 0; k < moment_count_f; ++k) {
        out.m[k] += piece.value[k];
        out.m_error[k] += piece.error[k];
      }
      for (int k = 0; k < moment_count_grad; ++k) {
        out.n[k] += piece.value[moment_count_f + k];
        out.n_error[k] += piece.error[moment_count_f + k];
      }
      out.max_levels_used = std::max(out.max_levels_used, piece.levels);
      out.kernel_evaluations += piece.evaluations;
    }
    total_evaluations_ += out.kernel_evaluations;
    return out;
  }

  /// Moments of the definition integral for any family: a finite-support
  /// family is clipped to its support ball in binary128 first (empty ⇒ f = 0).
  SegmentMoments moments(const KernelDefinition<extended>& kernel, const Vec3<extended>& a, const Vec3<extended>& b,
                         const Vec3<extended>& p) {
    const extended support = kernel.support_radius();
    if (!isfinite(support)) return moments_on_interval(kernel, a, b, p, extended(0), extended(1));
    const auto clip = clip_to_ball(a, b, p, support);
    if (!clip) {
      SegmentMoments empty;
      empty.empty = true;
      empty.ab = sub(b, a);
      empty.length = norm(empty.ab);
      return empty;
    }
    return moments_on_interval(kernel, a, b, p, clip->t0, clip->t1);
  }

  /// Combines moments into f and ∇f for the weight w(t) = Σ_{k≤d} w_k t^k.
  ReferenceField field(const SegmentMoments& mom, const std::array<extended, 4>& w, int weight_degree) const {
    ReferenceField out{};
    if (mom.empty) return out;  // f = 0, ∇f = 0 exactly; nothing estimated
    // v_j = Σ_{k≥j} C(k,j) w_k t*^(k−j): w(t* + u) = Σ_j v_j u^j.
    static constexpr int binomial[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};
    std::array<extended, 4> v{};
    for (int j = 0; j <= weight_degree; ++j)
      for (int k = j; k <= weight_degree; ++k) v[j] += binomial[k][j] * w[k] * integer_power(mom.t_star, k - j);

    extended f = 0, f_abs_error = 0;
    extended along_h = 0, along_h_error = 0, along_ab = 0, along_ab_error = 0;
    for (int j = 0; j <= weight_degree; ++j) {
      f += v[j] * mom.m[j];
      f_abs_error += abs(v[j]) * mom.m_error[j];
      along_h += v[j] * mom.n[j];
      along_h_error += abs(v[j]) * mom.n_error[j];
      along_ab += v[j] * mom.n[j + 1];
      along_ab_error += abs(v[j]) * mom.n_error[j + 1];
    }
    // Rounding of this combination and of the moments themselves: binary128
    // keeps ~113 bits per operation; a few dozen operations per term. This is
    // a floor under the rule's estimate, which can be exactly 0 when two levels
    // agree to the last bit.
    const extended rounding = 64 * std::numeric_limits<extended>::epsilon();
    extended f_terms = 0, h_terms = 0, ab_terms = 0;
    for (int j = 0; j <= weight_degree; ++j) {
      f_terms += abs(v[j] * mom.m[j]);
      h_terms += abs(v[j] * mom.n[j]);
      ab_terms += abs(v[j] * mom.n[j + 1]);
    }
    f_abs_error += rounding * f_terms;
    along_h_error += rounding * h_terms;
    along_ab_error += rounding * ab_terms;
    out.f = mom.length * f;
    for (int c = 0; c < 3; ++c) out.grad[c] = mom.length * (mom.h[c] * along_h - mom.ab[c] * along_ab);
    out.f_relative_error = abs(f_abs_error / f);
    const extended grad_abs_error = norm(mom.h) * along_h_error + mom.length * along_ab_error;
    out.grad_relative_error = grad_abs_error * mom.length / norm(out.grad);
    const extended threshold(tolerances_.flag_threshold);
    out.flagged = !(out.f_relative_error <= threshold) || !(out.grad_relative_error <= threshold);
    return out;
  }

 private:
  ReferenceTolerances tolerances_;
  TanhSinhMoments rule_;
  std::uint64_t total_evaluations_ = 0;
};

}  // namespace skelconv::verify
