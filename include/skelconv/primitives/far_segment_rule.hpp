// skelconv/primitives/far_segment_rule.hpp — a Cauchy segment, classical or
// SCALIS, far from P, evaluated to a given absolute error by a short
// Gauss–Legendre rule whose length an a-priori bound chooses (docs/field.md,
// "Tolerance").
//
// Both kinds integrate, with L = |AB|, m = i/2 (i the kernel's degree),
//
//     f(P) = L ∫_0^1 ω(t) Q(t)^(−m) dt,   Q(t) = |P − Γ(t)|² + c(t)²,
//
// c linear in t and ω ≥ 0 on [0, 1]:
//   - classical (segment.hpp): q = 1 + s |P − Γ|² = s Q with c ≡ 1/√s, and
//     ω(t) = s^(−m) w(t), w the weight polynomial;
//   - SCALIS (scalis_segment.hpp): K(r/(στ))/τ = σ^i τ^(i−1) Q^(−m) with
//     c(t) = σ τ(t), so ω(t) = (iso/h) σ c(t)^(i−1): a polynomial (i ≥ 1),
//     no pole where τ vanishes, and ≥ 0 on [0, 1] for radii > 0.
// Q is the squared distance in ℝ⁴ from P' = (P, 0) to the segment
// Γ'(t) = (Γ(t), c(t)) of length L' = √(L² + c'²) (L' = L for classical
// segments), so its zeros are t'* ± i d'/L' (t'* P''s projection parameter,
// d' its distance to that line in ℝ⁴). On [−1, 1] (t = (1 + x)/2) they lie
// on the Bernstein ellipse whose focal sum is
//
//     S = |x − 1| + |x + 1| = 2 (√(|PA|² + c(0)²) + √(|PB|² + c(1)²)) / L',
//
// and the n-point Gauss–Legendre rule errs by at most
// (64/15) M ρ^(2−2n) / (ρ² − 1) for any smaller ellipse E_ρ (focal sum
// S_ρ = ρ + 1/ρ) on which the integrand is at most M (Trefethen,
// Approximation Theory and Approximation Practice, Thm 19.3, whose I_n is
// the (n + 1)-point rule, exact to degree 2n + 1: the Chebyshev terms it
// misses start at T_(2n+2), |a_k| ≤ 2 M ρ^(−k)). On E_ρ every
// t is at least δ = (S − S_ρ)/4 from both zeros (confocal ellipses are that
// far apart at least, on the major axis), so |Q| ≥ L'² δ²; each component
// of P − Γ(t) is at most |PA| + L |t| ≤ L' (3 S + S_ρ)/4 (|PA| ≤ L' S/2,
// |t| ≤ 1/2 + S_ρ/4 ≤ S/4 + S_ρ/4); and |ω| ≤ Ω W(S), with Ω the constant
// factor of ω and W = Σ w_k r^k (classical) or (c_min + |c'| r)^(i−1)
// (SCALIS; c_min the smaller end's c), r = 1/2 + S/4 (|t| ≤ r and
// |t − 1/2| ≤ S/4 on E_ρ). Hence
//   f:   |error| ≤ L Ω W L'^(−2m) · (32/15) δ^(−2m) ρ^(2−2n) / (ρ² − 1),
//   ∇f:  |error of a component| ≤ L Ω W m L'^(−2m−1) · (64/15) δ^(−2m−2)
//        ((3 S + S_ρ)/4) ρ^(2−2n) / (ρ² − 1).
// The factors in front depend on the segment only; the rest, minimised over
// ρ, on S, m and n only: a table per degree (FarRuleBin, built once from
// arithmetic and square roots alone, so the same on every machine), read at
// the bin of S just below it (the bound decreases as S grows). Each segment
// may err by `budget` in f and by m g · budget in each component of ∇f,
// where m g bounds |∇f|/f for that segment's kernel: g = √s (classical,
// |∂K/∂r| ≤ (i/2) √s K) or 1/(σ min τ) (SCALIS, since
// |∇_P (σ²τ² + r²)^(−m)| ≤ (i/2) (σ²τ² + r²)^(−m) / (σ τ) at every t).
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <emmintrin.h>
#include <limits>
#include <optional>
#include <span>

#include "skelconv/geometry.hpp"

namespace skelconv {

namespace detail::far_rule {
/// The n-node Gauss–Legendre rule on [0, 1] (weights summing to 1), n ≤
/// FarSegmentRule::max_nodes (far_segment_rule.cpp builds them).
struct Rule {
  std::array<double, 20> t{}, g{};
};
/// The n-node rule, 1 ≤ n ≤ FarSegmentRule::max_nodes.
const Rule& gauss_legendre_rule(int n);
/// Σ_j g_j ω̂(t_j) Q̂_j^(−i/2) and, with the gradient, Σ_j g_j ω̂(t_j)
/// Q̂_j^(−i/2−1) (P − Γ(t_j)) (FarSegmentRule::front_).
struct NodeSums {
  double f = 0;
  std::array<double, 3> g{};
};
}  // namespace detail::far_rule

namespace detail {
/// The rules of a list of one kind and degree, chosen and summed many
/// segments at a time (the runtime's, src/detail/far_rule_batch.hpp).
class FarRuleBatch;
}  // namespace detail

/// The bounds of one bin of S for the even rules n = 2, 4, …, max_nodes (at
/// index n/2 − 1; the rules run two nodes at a time), for f and for ∇f
/// (far_segment_rule.cpp builds them).
struct FarRuleBin {
  std::array<double, 10> f, gradient;
};

class FarSegmentRule {
 public:
  /// Longest rule of each kind (even): beyond it the exact function is
  /// about as cheap. The generated classical functions (a far rule of
  /// 7–20 nodes, or a closed form) cost about 10 nodes; the SCALIS ones
  /// take 1.1 Gauss panels of 7–20 nodes each besides their frame and
  /// checks, about 20 nodes (docs/field.md, "Tolerance").
  static constexpr int max_classical_nodes = 10, max_scalis_nodes = 20;
  static constexpr int max_nodes = std::max(max_classical_nodes, max_scalis_nodes);
  static_assert(max_nodes / 2 == std::tuple_size_v<decltype(FarRuleBin::f)>);
  static_assert(max_nodes == std::tuple_size_v<decltype(detail::far_rule::Rule::t)>);
  /// The table's bins: 8 per octave of S from 2, the last one open.
  static constexpr int bins_per_octave = 8;  ///< the top 3 bits of S's mantissa
  static constexpr int max_exponent = 30;    ///< S up to 2^31: P ~10^9 |AB| away
  static constexpr int bin_count = max_exponent * bins_per_octave;

  /// The rule of a classical Cauchy segment of degree `degree` and
  /// sharpness `s` with weight coefficients `weight` (all ≥ 0), or nothing
  /// where it does not apply (another kernel, a negative weight coefficient,
  /// constants outside the range of normal doubles).
  static std::optional<FarSegmentRule> make(const Vec3& a, const Vec3& b, int degree, double s,
                                            std::span<const double> weight);
  /// The rule of a SCALIS Cauchy segment of degree `degree`, scale `sigma`
  /// and radii `tau0`, `tau1` (both > 0) whose field is `field_scale` · F
  /// (iso/h, scalis_segment.hpp), or nothing where it does not apply (a
  /// radius 0, a degree without a rule, constants outside the range of
  /// normal doubles).
  static std::optional<FarSegmentRule> make_scalis(const Vec3& a, const Vec3& b, int degree, double sigma,
                                                   double tau0, double tau1, double field_scale);

  /// What the rule's nodes sum, besides P and the segment (file comment):
  /// classical q = 1 + s |P − Γ|² with the weight w; SCALIS
  /// Q = |P − Γ|² + c(t)², c(t) = c0 + c1 t, with the weight c(t)^(i−1).
  struct Integrand {
    bool scalis = false;
    double s = 0;         ///< classical
    double c0 = 0, c1 = 0;  ///< SCALIS
    static constexpr std::size_t weight_count = 4;  ///< w_0 … w_3, as segments (segment.hpp)
    std::array<double, weight_count> w{};  ///< classical; {1} for SCALIS
    int weight_degree = 0;
  };

  int degree() const { return degree_; }
  bool scalis() const { return integrand_.scalis; }

  /// Q at the segment's ends, Q(0) = |P − A|² + c(0)² and Q(1): all that
  /// nodes reads of P.
  struct EndSquares {
    double a = 0, b = 0;
  };
  EndSquares end_squares(const Vec3& p) const {
    const Vec3 pa = p - a_;
    const Vec3 pb = pa - ab_;
    return {pa.squaredNorm() + offset_a_, pb.squaredNorm() + offset_b_};
  }

  /// Q's mean over the segment weighted by ω, E[Q] = ∫ω Q / ∫ω: since Q is
  /// quadratic in t, |P − Γ(t̄)|² + L² Var(t) + E[c²] (t̄, Var and E[c²]
  /// under the weight ω/∫ω, computed once per segment).
  double mean_square(const Vec3& p) const { return (p - centroid_).squaredNorm() + spread_; }
  /// The largest mean_square over the ball of `radius` around `centre`.
  double ball_mean_square(const Vec3& centre, double radius) const {
    const double far = (centre - centroid_).norm() + radius;
    return far * far + spread_;
  }

  /// A lower bound of f(P) from Q's mean (mean_square): x^(−m) is convex
  /// and ω/∫ω a probability density on [0, 1], so by Jensen's inequality
  /// f = L ∫ω · E[Q^(−m)] ≥ L ∫ω · E[Q]^(−m); E[Q] ≤ max(Q(0), Q(1)) (Q is
  /// convex in t), so this is never below the bound from the ends. As
  /// L ∫ω q_unit^(−m) · (q_unit / E[Q])^m so that neither factor leaves
  /// the double range for moderate inputs. Rounded like any f; 0 where it
  /// underflows. `Degree`: the rule's degree when the caller knows it at
  /// compile time (the same operations, with the loop unrolled), 0 to read it.
  template <int Degree = 0>
  double lower_bound(double mean_square) const {
    const int degree = Degree > 0 ? Degree : degree_;
    const double inverse = q_unit_ / mean_square;
    double power = 1;
    for (int k = 0; k < degree / 2; ++k) power *= inverse;
    if (degree % 2 == 1) power *= std::sqrt(inverse);
    return lower_front_ * power;
  }
  double lower_bound(const Vec3& p) const { return lower_bound(mean_square(p)); }

  /// The nodes n of the shortest rule with an even n (the rules run two
  /// nodes at a time) whose bound is at most `budget` for f and
  /// m g · budget for each component of ∇f; 0 where that takes more than
  /// the longest rule of its kind (or S is not finite). `Degree` and
  /// `Scalis` (1 SCALIS, 0 classical): the rule's, when the caller knows
  /// them at compile time (the same operations), else 0 and −1.
  template <int Degree = 0, int Scalis = -1>
  int nodes(const EndSquares& q, double budget) const {
    const double focal_sum = (std::sqrt(q.a) + std::sqrt(q.b)) * two_over_length_;
    return nodes_between<Degree, Scalis>(focal_sum, focal_sum, budget);
  }
  int nodes(const Vec3& p, double budget) const { return nodes(end_squares(p), budget); }

  /// The square roots of Q at the ends (what nodes() takes of them), and
  /// nodes() for every point within `radius` of P: each √Q(end) moves by
  /// at most `radius` with P (√(x² + c²) is 1-Lipschitz in x), so S by at
  /// most 4 radius / L'; the table's bound decreases as S grows and W
  /// grows with it, so the table is read at the least S and W taken at the
  /// largest. lower_bound of ball_mean_square bounds f over the ball.
  struct EndRoots {
    double a = 0, b = 0;
  };
  EndRoots end_roots(const EndSquares& q) const { return {std::sqrt(q.a), std::sqrt(q.b)}; }
  template <int Degree = 0, int Scalis = -1>
  int ball_nodes(const EndRoots& roots, double radius, double budget) const {
    const double sum = roots.a + roots.b;
    return nodes_between<Degree, Scalis>((sum - 2 * radius) * two_over_length_, (sum + 2 * radius) * two_over_length_,
                                         budget);
  }

  /// nodes() with S at least `focal_sum` for the table and at most
  /// `focal_sum_weight` for W (the same S at a point).
  template <int Degree = 0, int Scalis = -1>
  int nodes_between(double focal_sum, double focal_sum_weight, double budget) const {
    if (!(focal_sum > 2.0 && focal_sum_weight <= std::numeric_limits<double>::max())) return 0;
    double f_allowed = budget * f_factor_;
    if (weight_varies_) f_allowed /= weight_bound<Degree, Scalis>(focal_sum_weight);
    const int longest = Scalis < 0 ? longest_ : Scalis == 1 ? max_scalis_nodes : max_classical_nodes;
    return table_nodes(bins_[bin_of(focal_sum)], f_allowed, f_allowed * gradient_factor_, longest);
  }

  /// The n of nodes_between from the table's bin of S and the bounds
  /// allowed for f and for ∇f: the shortest even rule that fits both, 0
  /// past `longest`.
  static int table_nodes(const FarRuleBin& bound, double f_allowed, double gradient_allowed, int longest) {
    // The bounds decrease with n, so the rules that fit are the even n from
    // some 2 j on, and j − 1 is the number of even rules that do not fit:
    // counted, without a branch (a search's branches depend on the data),
    // over the entries up to the longest rule of this kind rounded up to a
    // pair of entries (n ≤ 4 ⌈longest/4⌉). Where none of them fits, the
    // count says n past the longest, as the whole table's count would.
    const __m128d f_limit = _mm_set1_pd(f_allowed), gradient_limit = _mm_set1_pd(gradient_allowed);
    const std::size_t entries = std::min(bound.f.size(), std::size_t(4 * ((longest + 3) / 4) / 2));
    int fitting = 0;
    for (std::size_t k = 0; k < entries; k += 2) {
      const __m128d fits = _mm_and_pd(_mm_cmple_pd(_mm_loadu_pd(&bound.f[k]), f_limit),
                                      _mm_cmple_pd(_mm_loadu_pd(&bound.gradient[k]), gradient_limit));
      const int mask = _mm_movemask_pd(fits);  // bit k: lane k fits
      fitting += (mask & 1) + (mask >> 1);
    }
    const int n = 2 * (1 + int(entries) - fitting);
    return n > longest ? 0 : n;
  }

  /// The n-node sum of rules of one kind and degree (n even, 2 … the
  /// longest of the kind), looked up once for a group of segments that
  /// take the same n (Skeleton's tolerance mode evaluates them so).
  struct NodeRule {
    detail::far_rule::NodeSums (*sum)(const detail::far_rule::Rule&, const Vec3& pa, const Vec3& ab,
                              const Integrand& integrand) = nullptr;
    const detail::far_rule::Rule* nodes = nullptr;
  };
  static NodeRule node_rule(bool scalis, int degree, int n, bool gradient);
  NodeRule node_rule(int n, bool gradient) const { return node_rule(integrand_.scalis, degree_, n, gradient); }
  /// evaluate_nodes with the n-node sum looked up already (node_rule of
  /// this rule's kind and degree).
  bool evaluate_with(const NodeRule& rule, const Vec3& p, bool gradient, FieldSample& out) const {
    const detail::far_rule::NodeSums sums = rule.sum(*rule.nodes, p - a_, ab_, integrand_);
    const double f = front_ * sums.f;
    if (!(f >= std::numeric_limits<double>::min() && f < std::numeric_limits<double>::infinity())) return false;
    out.value = f;
    if (gradient) {
      const double factor = gradient_front_ * front_;
      out.gradient = Vec3(factor * sums.g[0], factor * sums.g[1], factor * sums.g[2]);
      if (!out.gradient.allFinite()) return false;
    } else {
      out.gradient = Vec3::Zero();
    }
    return true;
  }

  /// f(P) and, with `gradient`, ∇f(P) by the n-node rule (n from nodes());
  /// false (`out` unspecified) where the result would not be a normal double
  /// (the exact path then decides).
  bool evaluate_nodes(const Vec3& p, int n, bool gradient, FieldSample& out) const;

 private:
  /// Copies these rules' constants side by side and chooses and sums them
  /// with the same operations (src/detail/far_rule_batch.hpp).
  friend class detail::FarRuleBatch;
  FarSegmentRule() = default;
  /// What make and make_scalis share once the integrand is set: the
  /// constants of the bound and of the lower bound, the table; false where
  /// one of them is not a normal double.
  bool finish(const Vec3& a, const Vec3& b, int degree);
  /// W(S) (file comment): |ω| ≤ Ω W on the ellipse.
  /// `Degree`, `Scalis` as in nodes(): a SCALIS weight is the power
  /// (weight_degree 0, w_0 = 1, bound_power_ = i − 1), a classical one the
  /// polynomial (bound_power_ = 0).
  template <int Degree = 0, int Scalis = -1>
  double weight_bound(double focal_sum) const {
    const double radius = 0.5 + 0.25 * focal_sum;
    const int weight_degree = Scalis == 1 ? 0 : integrand_.weight_degree;
    double w = integrand_.w[std::size_t(weight_degree)];
    for (int k = weight_degree - 1; k >= 0; --k) w = w * radius + integrand_.w[std::size_t(k)];
    const double linear = bound_base_ + bound_slope_ * radius;
    const int bound_power = Scalis == 0 ? 0 : Scalis == 1 && Degree > 0 ? Degree - 1 : bound_power_;
    for (int k = 0; k < bound_power; ++k) w *= linear;
    return w;
  }
  /// The bin whose lower edge is the largest at or below S (S > 2, finite).
  static int bin_of(double focal_sum) {
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(focal_sum);
    const int exponent = int((bits >> 52) & 0x7ff) - 1023;
    if (exponent > max_exponent) return bin_count - 1;
    return (exponent - 1) * bins_per_octave + int((bits >> 49) & 7);
  }
  Vec3 a_, ab_;
  Integrand integrand_;
  int degree_ = 0;  ///< i: Q^(−i/2)
  int longest_ = 0;  ///< max_classical_nodes or max_scalis_nodes
  double offset_a_ = 0, offset_b_ = 0;  ///< c(0)², c(1)²
  double two_over_length_ = 0;  ///< 2 / L'
  /// The unit of Q in lower_bound: 1/s (classical), c_max² (SCALIS, c_max
  /// the larger end's c). Below, Ω is ω's constant factor: s^(−m) (times
  /// w_0 where w is that constant; classical), (iso/h) σ c_max^(i−1) (SCALIS).
  double q_unit_ = 0;
  /// L Ω ∫_0^1 (ω/Ω) dt · q_unit^(−m): lower_bound's factor.
  double lower_front_ = 0;
  /// Γ(t̄) and L² Var(t) + E[c²] under the weight ω/∫ω (mean_square).
  Vec3 centroid_ = Vec3::Zero();
  double spread_ = 0;
  /// W(S) = Σ w_k r^k · (bound_base_ + bound_slope_ r)^bound_power_: the
  /// polynomial is the classical weight (where it is not constant), the power
  /// SCALIS (c_min/c_max, |c1|/c_max, i − 1: W relative to c_max^(i−1)).
  double bound_base_ = 1, bound_slope_ = 0;
  int bound_power_ = 0;
  /// W varies with S (else it is 1: its constant is in Ω).
  bool weight_varies_ = false;
  /// L'^(2m) / (L Ω): the f budget times this (over W) is what the table's
  /// f bound must not exceed; g L' times that is what its ∇f bound must not.
  double f_factor_ = 0, gradient_factor_ = 0;
  /// f = front · Σ_j g_j ω̂(t_j) Q̂_j^(−m) and ∇f = front · gradient_front ·
  /// Σ_j g_j ω̂(t_j) Q̂_j^(−m−1) (P − Γ(t_j)), in what sum_nodes computes:
  /// classical Q̂ = q, ω̂ = w (1 where constant); SCALIS Q̂ = Q, ω̂ = c^(i−1).
  double front_ = 0, gradient_front_ = 0;
  /// The table of this degree (built once per degree, never freed).
  const FarRuleBin* bins_ = nullptr;
};

}  // namespace skelconv
