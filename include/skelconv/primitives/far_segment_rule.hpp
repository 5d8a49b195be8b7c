// skelconv/primitives/far_segment_rule.hpp — a Cauchy segment far from P,
// evaluated to a given absolute error by a short Gauss–Legendre rule whose
// length an a-priori bound chooses (docs/field.md, "Tolerance").
//
// The segment's field is f(P) = L ∫_0^1 w(t) q(t)^(−m) dt with L = |AB|,
// q(t) = 1 + s |P − Γ(t)|², m = i/2 (segment.hpp). In t, q has the complex
// zeros t* ± i a, where t* is P's projection parameter and
// L² a² = d² + 1/s (d: P's distance to the line). On [−1, 1]
// (t = (1 + x)/2) they lie on the Bernstein ellipse whose focal sum is
//
//     S = |x − 1| + |x + 1| = 2 (√(|PA|² + 1/s) + √(|PB|² + 1/s)) / L,
//
// and the n-point Gauss–Legendre rule errs by at most
// (64/15) M ρ^(2−2n) / (ρ² − 1) for any smaller ellipse E_ρ (focal sum
// S_ρ = ρ + 1/ρ) on which the integrand is at most M (Trefethen,
// Approximation Theory and Approximation Practice, Thm 19.3, whose I_n is
// the (n + 1)-point rule, exact to degree 2n + 1: the Chebyshev terms it
// misses start at T_(2n+2), |a_k| ≤ 2 M ρ^(−k)). On E_ρ every
// t is at least (S − S_ρ)/4 from both zeros (confocal ellipses are that far
// apart at least, on the major axis), so |q| ≥ s L² ((S − S_ρ)/4)², and
//   f:   |error| ≤ L W (s L²)^(−m) · (32/15) δ^(−2m) ρ^(2−2n) / (ρ² − 1),
//   ∇f:  |error of a component| ≤ W m (s L²)^(−m) · (64/15) δ^(−2m−2)
//        ((3 S + S_ρ)/4) ρ^(2−2n) / (ρ² − 1),
// with δ = (S − S_ρ)/4, |P − Γ(t)| ≤ L (3 S + S_ρ)/4 on E_ρ, and W a bound of
// |w| there (Σ |w_k| (1/2 + S/4)^k). The factors in front depend on the
// segment only; the rest, minimised over ρ, on S, m and n only: a table per
// degree (FarRuleTable, built once from arithmetic and square roots alone,
// so the same on every machine), read at the bin of S just below it (the
// bound decreases as S grows).
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>

#include "skelconv/geometry.hpp"

namespace skelconv {

class FarSegmentRule;

/// The bounds of one bin of S for n = 1 … max_nodes (index n; [0] unused),
/// for f and for ∇f (far_segment_rule.cpp builds them).
struct FarRuleBin {
  std::array<double, 11> f, gradient;
};

class FarSegmentRule {
 public:
  /// Longest rule used (even): beyond it the generated function (its own
  /// far rule of 7–20 nodes, or a closed form) is about as cheap.
  static constexpr int max_nodes = 10;
  static_assert(max_nodes + 1 == std::tuple_size_v<decltype(FarRuleBin::f)>);
  /// The table's bins: 8 per octave of S from 2, the last one open.
  static constexpr int bins_per_octave = 8;  ///< the top 3 bits of S's mantissa
  static constexpr int max_exponent = 30;    ///< S up to 2^31: P ~10^9 |AB| away
  static constexpr int bin_count = max_exponent * bins_per_octave;


  /// The rule of a Cauchy segment of degree `degree` and sharpness `s` with
  /// weight coefficients `weight` (all ≥ 0), or nothing where it does not
  /// apply (another kernel, a negative weight coefficient, constants
  /// outside the range of normal doubles).
  static std::optional<FarSegmentRule> make(const Vec3& a, const Vec3& b, int degree, double s,
                                            std::span<const double> weight);

  /// A lower bound of f(P): L w_0 (1 + s r²)^(−m) with r the farther end's
  /// distance (K decreases, and w ≥ w_0 on [0, 1] since no coefficient is
  /// negative). Rounded like any f; 0 where it underflows.
  double lower_bound(const Vec3& p) const {
    const Vec3 pa = p - a_;
    const Vec3 pb = pa - ab_;
    const double inverse = 1 / (1 + s_ * std::max(pa.squaredNorm(), pb.squaredNorm()));
    double power = 1;
    for (int k = 0; k < degree_ / 2; ++k) power *= inverse;
    if (degree_ % 2 == 1) power *= std::sqrt(inverse);
    return length_ * weight_[0] * power;
  }

  /// The nodes n of the shortest rule with an even n (the rules run two
  /// nodes at a time) whose bound is at most `budget` for f and
  /// m √s · budget for each component of ∇f; 0 where that takes more than
  /// max_nodes nodes (or S is not finite).
  int nodes(const Vec3& p, double budget) const {
    const Vec3 pa = p - a_;
    const Vec3 pb = pa - ab_;
    const double focal_sum =
        (std::sqrt(pa.squaredNorm() + inverse_s_) + std::sqrt(pb.squaredNorm() + inverse_s_)) * two_over_length_;
    if (!(focal_sum > 2.0 && focal_sum <= std::numeric_limits<double>::max())) return 0;
    double f_allowed = budget * f_factor_;
    if (weight_degree_ > 0) f_allowed /= weight_bound(focal_sum);
    const double gradient_allowed = f_allowed * gradient_factor_;
    const FarRuleBin& bound = bins_[bin_of(focal_sum)];
    // The bounds decrease with n: the even rules that fail are 2 … n − 2.
    int n = 2;
    for (std::size_t k = 2; k <= max_nodes; k += 2) {
      n += 2 * int(!(bound.f[k] <= f_allowed) | !(bound.gradient[k] <= gradient_allowed));
    }
    return n > max_nodes ? 0 : n;
  }
  /// f(P) and, with `gradient`, ∇f(P) by the n-node rule (n from nodes());
  /// false (`out` unspecified) where the result would not be a normal double
  /// (the exact path then decides).
  bool evaluate_nodes(const Vec3& p, int n, bool gradient, FieldSample& out) const;

 private:
  FarSegmentRule() = default;
  /// W = Σ w_k (1/2 + S/4)^k: |w| on the ellipse, where |t| ≤ 1/2 + S/4.
  double weight_bound(double focal_sum) const;
  /// The bin whose lower edge is the largest at or below S (S > 2, finite).
  static int bin_of(double focal_sum) {
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(focal_sum);
    const int exponent = int((bits >> 52) & 0x7ff) - 1023;
    if (exponent > max_exponent) return bin_count - 1;
    return (exponent - 1) * bins_per_octave + int((bits >> 49) & 7);
  }
  Vec3 a_, ab_;
  double length_ = 0, s_ = 0, inverse_s_ = 0;
  int degree_ = 0;  ///< i: q^(−i/2)
  int weight_degree_ = 0;
  static constexpr std::size_t rule_weight_count = 4;  ///< w_0 … w_3, as segments (segment.hpp)
  std::array<double, rule_weight_count> weight_{};
  /// (s L²)^m / L, and √s L: the f budget over this is what the table's f
  /// bound must not exceed, and the ∇f one over this times it the table's ∇f
  /// bound (weight W divided out at each point where w is not constant).
  double f_factor_ = 0, gradient_factor_ = 0;
  double two_over_length_ = 0;
  /// The table of this degree (built once per degree, never freed).
  const FarRuleBin* bins_ = nullptr;
};

}  // namespace skelconv
