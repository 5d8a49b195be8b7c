// Implementation of skelconv/primitives/far_segment_rule.hpp.
#include "skelconv/primitives/far_segment_rule.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <emmintrin.h>
#include <limits>
#include <mutex>
#include <utility>
#include <vector>

#include "../detail/infinity.hpp"
#include "far_rule_node.hpp"

namespace skelconv {

// Named, so that nothing here meets another file's names in a unity build.
namespace detail::far_rule {

namespace {

constexpr int max_nodes = FarSegmentRule::max_nodes;
constexpr int max_degree = 16;  ///< Cauchy degrees on segments (kernels/cauchy.hpp)
/// SCALIS Cauchy degrees with a rule: those of the generated table
/// (generated/scalis_segment_table.hpp, 2–10); any other stays exact.
constexpr int max_scalis_degree = 10;

// ---------------------------------------------------------------------------
// Gauss–Legendre rules of 1 … max_nodes nodes on [0, 1] (weights summing to
// 1), from long double bisection on the Legendre recurrence: arithmetic only,
// so the same doubles on every x86-64 machine whatever its libm.

/// P_n(x) and P_n'(x) by the three-term recurrence.
std::pair<long double, long double> legendre(int n, long double x) {
  long double previous = 1, current = x;
  if (n == 0) return {1, 0};
  for (int k = 2; k <= n; ++k) {
    const long double next = ((2 * k - 1) * x * current - (k - 1) * previous) / k;
    previous = current;
    current = next;
  }
  return {current, n * (x * current - previous) / (x * x - 1)};
}

std::array<Rule, max_nodes + 1> make_rules() {
  std::array<Rule, max_nodes + 1> rules{};
  // The roots of P_n (n ≤ 20) are more than 0.02 apart: a scan of 4,095
  // steps over [−1, 1] brackets each one alone, and (an odd count) never
  // lands on one (x = 0 for odd n).
  constexpr int steps = 4095;
  for (int n = 1; n <= max_nodes; ++n) {
    int found = 0;
    long double left = -1, value_left = legendre(n, left).first;
    for (int k = 1; k <= steps && found < n; ++k) {
      const long double right = -1 + 2.0L * k / steps, value_right = legendre(n, right).first;
      if ((value_left < 0) != (value_right < 0)) {
        long double lo = left, hi = right;
        for (int halving = 0; halving < 80; ++halving) {  // 80 halvings reach long double's resolution
          const long double mid = (lo + hi) / 2;
          if ((legendre(n, mid).first < 0) == (value_left < 0)) lo = mid; else hi = mid;
        }
        const long double x = (lo + hi) / 2;
        const long double slope = legendre(n, x).second;
        rules[std::size_t(n)].t[std::size_t(found)] = double((1 + x) / 2);
        // 2/((1 − x²) P_n'(x)²) on [−1, 1], halved for [0, 1].
        rules[std::size_t(n)].g[std::size_t(found)] = double(1 / ((1 - x * x) * slope * slope));
        ++found;
      }
      left = right;
      value_left = value_right;
    }
  }
  return rules;
}

const std::array<Rule, max_nodes + 1>& rules() {
  static const std::array<Rule, max_nodes + 1> table = make_rules();
  return table;
}

// ---------------------------------------------------------------------------
// The bound's part that depends on S, m and n only (file comment of the
// header), per degree, at the lower edge of bins of S: 8 per octave from 2
// to 2^max_exponent (beyond: the last bin, still a valid bound since the
// bound decreases as S grows).

constexpr int bins_per_octave = FarSegmentRule::bins_per_octave;
constexpr int bin_count = FarSegmentRule::bin_count;

/// Rounding of the run-time S, budget and factors (a few units in the last
/// place each) and of the table itself: a factor 2 covers them all.
constexpr double safety = 2.0;
/// Ellipses tried per bin: ρ = 1 + (ρ_S − 1) j / ellipse_steps.
constexpr int ellipse_steps = 64;

std::vector<FarRuleBin> make_table(int degree) {
  std::vector<FarRuleBin> table(bin_count);
  for (int bin = 0; bin < bin_count; ++bin) {
    const int exponent = 1 + bin / bins_per_octave;
    const double focal_sum = std::ldexp(1.0 + double(bin % bins_per_octave) / bins_per_octave, exponent);
    FarRuleBin& bound = table[std::size_t(bin)];
    bound.f.fill(infinity);
    bound.gradient.fill(infinity);
    const double rho_zero = (focal_sum + std::sqrt(focal_sum * focal_sum - 4)) / 2;
    for (int j = 1; j < ellipse_steps; ++j) {
      const double rho = 1 + (rho_zero - 1) * j / ellipse_steps;
      const double focal_rho = rho + 1 / rho;
      const double delta = (focal_sum - focal_rho) / 4;
      if (!(delta > 0) || !(rho > 1)) continue;
      double delta_power = 1;  // δ^i
      for (int k = 0; k < degree; ++k) delta_power *= delta;
      const double f_front = 32.0 / 15 / (delta_power * (rho * rho - 1));
      const double gradient_front =
          64.0 / 15 / (delta_power * delta * delta * (rho * rho - 1)) * ((3 * focal_sum + focal_rho) / 4);
      double decay = 1;  // ρ^(−2(n − 1))
      for (int n = 1; n <= max_nodes; ++n) {
        if (n > 1) decay /= rho * rho;
        if (n % 2 == 1) continue;  // only even rules run
        const std::size_t at = std::size_t(n / 2 - 1);
        bound.f[at] = std::min(bound.f[at], safety * f_front * decay);
        bound.gradient[at] = std::min(bound.gradient[at], safety * gradient_front * decay);
      }
    }
  }
  return table;
}

const std::vector<FarRuleBin>& table_for(int degree) {
  static std::array<std::once_flag, max_degree + 1> once;
  static std::array<std::vector<FarRuleBin>, max_degree + 1> tables;
  std::call_once(once[std::size_t(degree)], [degree] { tables[std::size_t(degree)] = make_table(degree); });
  return tables[std::size_t(degree)];
}

using Integrand = FarSegmentRule::Integrand;

/// The N-node rule (N even), two nodes at a time in SSE2 (x86-64's
/// baseline: the same operations, in the same order, on every machine).
/// Lanes are summed apart, then added. Classical: Q̂ = 1 + s r², ω̂ the
/// weight polynomial; Scalis: Q̂ = r² + c², ω̂ = c^(I−1), c = c0 + c1 t.
template <int I, bool Gradient, int N, bool Scalis>
NodeSums sum_nodes(const Rule& rule, const Vec3& pa, const Vec3& ab, const Integrand& integrand) {
  __m128d w[Integrand::weight_count];
  for (std::size_t k = 0; k < Integrand::weight_count; ++k) w[k] = _mm_set1_pd(integrand.w[k]);
  const NodeSegment segment{_mm_set1_pd(pa.x()),         _mm_set1_pd(pa.y()),  _mm_set1_pd(pa.z()),
                            _mm_set1_pd(ab.x()),         _mm_set1_pd(ab.y()),  _mm_set1_pd(ab.z()),
                            _mm_set1_pd(integrand.s),    _mm_set1_pd(integrand.c0),
                            _mm_set1_pd(integrand.c1),   w,
                            integrand.weight_degree};
  __m128d f = _mm_setzero_pd(), g_x = _mm_setzero_pd(), g_y = _mm_setzero_pd(), g_z = _mm_setzero_pd();
  for (int j = 0; j < N; j += 2) {  // N even, known here: no loop exit to predict
    add_node<I, Gradient, Scalis>(_mm_loadu_pd(&rule.t[std::size_t(j)]), _mm_loadu_pd(&rule.g[std::size_t(j)]),
                                  segment, f, g_x, g_y, g_z);
  }
  const auto lanes = [](__m128d v) {
    alignas(16) double two[2];
    _mm_store_pd(two, v);
    return two[0] + two[1];
  };
  NodeSums sums;
  sums.f = lanes(f);
  if constexpr (Gradient) sums.g = {lanes(g_x), lanes(g_y), lanes(g_z)};
  return sums;
}

using SumNodes = NodeSums (*)(const Rule&, const Vec3&, const Vec3&, const Integrand&);

/// The longest rule of a kind.
constexpr int longest(bool scalis) {
  return scalis ? FarSegmentRule::max_scalis_nodes : FarSegmentRule::max_classical_nodes;
}

/// sum_nodes for degree I + 1 and N = 2, 4, …, longest(Scalis) nodes, at
/// [N / 2] (nullptr beyond).
template <bool Gradient, bool Scalis, int I, int... Pair>
constexpr std::array<SumNodes, max_nodes / 2 + 1> sum_nodes_of_degree(std::integer_sequence<int, Pair...>) {
  return {nullptr, &sum_nodes<I + 1, Gradient, 2 * (Pair + 1), Scalis>...};
}

/// At [i][N / 2]: sum_nodes of degree i, N nodes.
template <bool Gradient, bool Scalis, int... I>
constexpr std::array<std::array<SumNodes, max_nodes / 2 + 1>, sizeof...(I) + 1> sum_nodes_table(
    std::integer_sequence<int, I...>) {
  return {std::array<SumNodes, max_nodes / 2 + 1>{},
          sum_nodes_of_degree<Gradient, Scalis, I>(std::make_integer_sequence<int, longest(Scalis) / 2>{})...};
}

/// x^k for a small non-negative k, by multiplications.
double power(double x, int k) {
  double result = 1;
  for (int j = 0; j < k; ++j) result *= x;
  return result;
}

/// x^(i/2) for i ≥ 0.
double half_power(double x, int i) {
  double result = power(x, i / 2);
  if (i % 2 == 1) result *= std::sqrt(x);
  return result;
}

}  // namespace

const Rule& gauss_legendre_rule(int n) { return rules()[std::size_t(n)]; }

}  // namespace detail::far_rule

std::optional<FarSegmentRule> FarSegmentRule::make(const Vec3& a, const Vec3& b, int degree, double s,
                                                   std::span<const double> weight) {
  if (degree < 1 || degree > detail::far_rule::max_degree || weight.empty() || weight.size() > Integrand::weight_count) {
    return std::nullopt;
  }
  for (double w : weight) {
    if (!(w >= 0.0) || !std::isfinite(w)) return std::nullopt;
  }
  FarSegmentRule rule;
  Integrand& integrand = rule.integrand_;
  integrand.s = s;
  integrand.weight_degree = int(weight.size()) - 1;
  while (integrand.weight_degree > 0 && weight[std::size_t(integrand.weight_degree)] == 0.0) {
    --integrand.weight_degree;
  }
  std::copy(weight.begin(), weight.end(), integrand.w.begin());
  const double length = (b - a).norm();
  rule.offset_a_ = rule.offset_b_ = rule.q_unit_ = 1 / s;
  rule.two_over_length_ = 2 / length;
  // ∫_0^1 w = Σ w_k / (k + 1); Ω q_unit^(−m) = 1 (times w_0 where constant).
  double mean = 0;
  for (int k = 0; k <= integrand.weight_degree; ++k) mean += integrand.w[std::size_t(k)] / (k + 1);
  rule.lower_front_ = length * mean;
  // L'^(2m) / (L Ω) = (s L²)^m / L, divided by w_0 where w is that constant.
  rule.f_factor_ = detail::far_rule::half_power(s * length * length, degree) / length;
  rule.weight_varies_ = integrand.weight_degree > 0;
  if (!rule.weight_varies_) rule.f_factor_ /= weight[0];
  rule.gradient_factor_ = std::sqrt(s) * length;  // g L' = √s L
  rule.front_ = rule.weight_varies_ ? length : length * weight[0];
  rule.gradient_front_ = -double(degree) * s;  // ∂q^(−i/2)/∂P = −i s q^(−i/2−1) (P − Γ)
  rule.longest_ = max_classical_nodes;
  if (!rule.finish(a, b, degree)) return std::nullopt;
  return rule;
}

std::optional<FarSegmentRule> FarSegmentRule::make_scalis(const Vec3& a, const Vec3& b, int degree, double sigma,
                                                          double tau0, double tau1, double field_scale) {
  if (degree < 1 || degree > detail::far_rule::max_scalis_degree || !(tau0 > 0.0) || !(tau1 > 0.0)) return std::nullopt;
  FarSegmentRule rule;
  Integrand& integrand = rule.integrand_;
  integrand.scalis = true;
  integrand.c0 = sigma * tau0;
  const double c_end = sigma * tau1;
  integrand.c1 = c_end - integrand.c0;
  integrand.w = {1.0, 0.0, 0.0, 0.0};
  const double c_max = std::max(integrand.c0, c_end), c_min = std::min(integrand.c0, c_end);
  const Vec3 ab = b - a;
  const double length = ab.norm();
  const double lifted = std::sqrt(ab.squaredNorm() + integrand.c1 * integrand.c1);  // L'
  rule.offset_a_ = integrand.c0 * integrand.c0;
  rule.offset_b_ = c_end * c_end;
  rule.q_unit_ = c_max * c_max;
  rule.two_over_length_ = 2 / lifted;
  // ∫_0^1 (c/c_max)^(i−1) dt = (1/i) Σ_k u0^k u1^(i−1−k), u = c/c_max at the
  // ends: no cancellation when the radii are close.
  const double u0 = integrand.c0 / c_max, u1 = c_end / c_max;
  double mean = 0;
  for (int k = 0; k < degree; ++k) mean += detail::far_rule::power(u0, k) * detail::far_rule::power(u1, degree - 1 - k);
  mean /= degree;
  const double scale = field_scale * sigma;  // Ω = scale c_max^(i−1)
  rule.lower_front_ = length * scale * mean / c_max;  // L Ω ∫(c/c_max)^(i−1) / c_max^i
  // W = ((c_min + |c1| r)/c_max)^(i−1), 1 where the radius is constant.
  rule.bound_base_ = c_min / c_max;
  rule.bound_slope_ = std::abs(integrand.c1) / c_max;
  rule.bound_power_ = degree - 1;
  rule.weight_varies_ = integrand.c1 != 0.0 && degree > 1;
  // L'^(2m) / (L Ω) = (L'/c_max)^(2m) c_max / (L scale).
  rule.f_factor_ = detail::far_rule::half_power(lifted * lifted / rule.q_unit_, degree) * c_max / (length * scale);
  rule.gradient_factor_ = lifted / c_min;  // g L' = L' / (σ min τ)
  rule.front_ = length * scale;
  rule.gradient_front_ = -double(degree);  // ∂Q^(−i/2)/∂P = −i Q^(−i/2−1) (P − Γ)
  rule.longest_ = max_scalis_nodes;
  if (!rule.finish(a, b, degree)) return std::nullopt;
  return rule;
}

bool FarSegmentRule::finish(const Vec3& a, const Vec3& b, int degree) {
  a_ = a;
  ab_ = b - a;
  degree_ = degree;
  // The moments of mean_square under ω/∫ω by the longest Gauss rule, exact
  // for these polynomials (ω t² and ω c² have degree at most 11, the rule
  // 2 max_nodes − 1 = 39); the variance from the mean, a sum of squares.
  {
    const detail::far_rule::Rule& rule = detail::far_rule::rules()[std::size_t(max_nodes)];
    const double c_max = std::sqrt(q_unit_);  // SCALIS: the larger end's c
    std::array<double, max_nodes> weight{};
    double mass = 0, first = 0;
    for (std::size_t j = 0; j < std::size_t(max_nodes); ++j) {
      const double t = rule.t[j];
      double w = 1;
      if (integrand_.scalis) {
        w = detail::far_rule::power((integrand_.c0 + integrand_.c1 * t) / c_max, degree - 1);
      } else {
        w = integrand_.w[std::size_t(integrand_.weight_degree)];
        for (int k = integrand_.weight_degree - 1; k >= 0; --k) w = w * t + integrand_.w[std::size_t(k)];
      }
      weight[j] = rule.g[j] * w;
      mass += weight[j];
      first += weight[j] * t;
    }
    const double mean = first / mass;
    double variance = 0, square = 0;  // E[(t − t̄)²], E[c²]
    for (std::size_t j = 0; j < std::size_t(max_nodes); ++j) {
      const double t = rule.t[j], c = integrand_.scalis ? integrand_.c0 + integrand_.c1 * t : 0.0;
      variance += weight[j] * (t - mean) * (t - mean);
      square += weight[j] * c * c;
    }
    centroid_ = a + mean * ab_;
    spread_ = ab_.squaredNorm() * (variance / mass) + (integrand_.scalis ? square / mass : offset_a_);
    if (!(mass > 0) || !std::isfinite(spread_) || !centroid_.allFinite()) return false;
  }
  const auto usable = [](double x) { return std::isnormal(x); };
  for (double constant : {offset_a_, offset_b_, q_unit_, two_over_length_, lower_front_, f_factor_,
                          gradient_factor_, front_, gradient_front_}) {
    if (!usable(constant)) return false;
  }
  bins_ = detail::far_rule::table_for(degree).data();  // built here, once per degree, not at the first point
  (void)detail::far_rule::rules();
  return true;
}

FarSegmentRule::NodeRule FarSegmentRule::node_rule(bool scalis, int degree, int n, bool gradient) {
  using detail::far_rule::sum_nodes_table;
  static constexpr auto values = sum_nodes_table<false, false>(std::make_integer_sequence<int, detail::far_rule::max_degree>{});
  static constexpr auto both = sum_nodes_table<true, false>(std::make_integer_sequence<int, detail::far_rule::max_degree>{});
  static constexpr auto scalis_values =
      sum_nodes_table<false, true>(std::make_integer_sequence<int, detail::far_rule::max_scalis_degree>{});
  static constexpr auto scalis_both =
      sum_nodes_table<true, true>(std::make_integer_sequence<int, detail::far_rule::max_scalis_degree>{});
  const std::size_t at = std::size_t(degree), pair = std::size_t(n / 2);
  return {scalis ? (gradient ? scalis_both : scalis_values)[at][pair] : (gradient ? both : values)[at][pair],
          &detail::far_rule::rules()[std::size_t(n)]};
}

bool FarSegmentRule::evaluate_nodes(const Vec3& p, int n, bool gradient, FieldSample& out) const {
  return evaluate_with(node_rule(n, gradient), p, gradient, out);
}

}  // namespace skelconv
