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

namespace skelconv {

// Named, so that nothing here meets another file's names in a unity build.
namespace far_rule {
namespace {

constexpr int max_nodes = FarSegmentRule::max_nodes;
constexpr int max_degree = 16;  ///< Cauchy degrees on segments (kernels/cauchy.hpp)

// ---------------------------------------------------------------------------
// Gauss–Legendre rules of 1 … max_nodes nodes on [0, 1] (weights summing to
// 1), from long double bisection on the Legendre recurrence: arithmetic only,
// so the same doubles on every x86-64 machine whatever its libm.

struct Rule {
  std::array<double, max_nodes> t{}, g{};
};

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
  // The roots of P_n (n ≤ 10) are more than 0.02 apart: a scan of 4,095
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
        bound.f[std::size_t(n)] = std::min(bound.f[std::size_t(n)], safety * f_front * decay);
        bound.gradient[std::size_t(n)] = std::min(bound.gradient[std::size_t(n)], safety * gradient_front * decay);
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

/// q^(−i/2) from 1/q, on both lanes.
template <int I>
[[gnu::always_inline]] inline __m128d negative_half_power(__m128d inverse) {
  __m128d result = _mm_set1_pd(1.0);
  for (int k = 0; k < I / 2; ++k) result = _mm_mul_pd(result, inverse);
  if constexpr (I % 2 == 1) result = _mm_mul_pd(result, _mm_sqrt_pd(inverse));
  return result;
}

/// Σ_j g_j w(t_j) q_j^(−i/2) and, with Gradient, Σ_j g_j w(t_j) q_j^(−i/2−1) (P − Γ(t_j)).
struct NodeSums {
  double f = 0;
  std::array<double, 3> g{};
};

/// The N-node rule (N even), two nodes at a time in SSE2 (x86-64's
/// baseline: the same operations, in the same order, on every machine).
/// Lanes are summed apart, then added.
template <int I, bool Gradient, int N>
NodeSums sum_nodes(const Rule& rule, const Vec3& pa, const Vec3& ab, double s, const std::array<double, 4>& w,
                   int weight_degree) {
  const __m128d one = _mm_set1_pd(1.0), sharpness = _mm_set1_pd(s);
  const __m128d pa_x = _mm_set1_pd(pa.x()), pa_y = _mm_set1_pd(pa.y()), pa_z = _mm_set1_pd(pa.z());
  const __m128d ab_x = _mm_set1_pd(ab.x()), ab_y = _mm_set1_pd(ab.y()), ab_z = _mm_set1_pd(ab.z());
  __m128d f = _mm_setzero_pd(), g_x = _mm_setzero_pd(), g_y = _mm_setzero_pd(), g_z = _mm_setzero_pd();
  for (int j = 0; j < N; j += 2) {  // N even, known here: no loop exit to predict
    const __m128d t = _mm_loadu_pd(&rule.t[std::size_t(j)]);
    const __m128d x = _mm_sub_pd(pa_x, _mm_mul_pd(t, ab_x));
    const __m128d y = _mm_sub_pd(pa_y, _mm_mul_pd(t, ab_y));
    const __m128d z = _mm_sub_pd(pa_z, _mm_mul_pd(t, ab_z));
    const __m128d r2 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(x, x), _mm_mul_pd(y, y)), _mm_mul_pd(z, z));
    const __m128d inverse = _mm_div_pd(one, _mm_add_pd(one, _mm_mul_pd(sharpness, r2)));
    __m128d weight = _mm_loadu_pd(&rule.g[std::size_t(j)]);
    if (weight_degree > 0) {
      __m128d polynomial = _mm_set1_pd(w[std::size_t(weight_degree)]);
      for (int k = weight_degree - 1; k >= 0; --k) {
        polynomial = _mm_add_pd(_mm_mul_pd(polynomial, t), _mm_set1_pd(w[std::size_t(k)]));
      }
      weight = _mm_mul_pd(weight, polynomial);
    }
    const __m128d term = _mm_mul_pd(weight, negative_half_power<I>(inverse));
    f = _mm_add_pd(f, term);
    if constexpr (Gradient) {
      const __m128d slope = _mm_mul_pd(term, inverse);
      g_x = _mm_add_pd(g_x, _mm_mul_pd(slope, x));
      g_y = _mm_add_pd(g_y, _mm_mul_pd(slope, y));
      g_z = _mm_add_pd(g_z, _mm_mul_pd(slope, z));
    }
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

using SumNodes = NodeSums (*)(const Rule&, const Vec3&, const Vec3&, double, const std::array<double, 4>&, int);

/// sum_nodes for degree I + 1 and N = 2, 4, …, max_nodes nodes, at [N / 2].
template <bool Gradient, int I, int... Pair>
constexpr std::array<SumNodes, max_nodes / 2 + 1> sum_nodes_of_degree(std::integer_sequence<int, Pair...>) {
  return {nullptr, &sum_nodes<I + 1, Gradient, 2 * (Pair + 1)>...};
}

/// At [i][N / 2]: sum_nodes of degree i, N nodes.
template <bool Gradient, int... I>
constexpr std::array<std::array<SumNodes, max_nodes / 2 + 1>, sizeof...(I) + 1> sum_nodes_table(
    std::integer_sequence<int, I...>) {
  return {std::array<SumNodes, max_nodes / 2 + 1>{},
          sum_nodes_of_degree<Gradient, I>(std::make_integer_sequence<int, max_nodes / 2>{})...};
}

}  // namespace
}  // namespace far_rule

std::optional<FarSegmentRule> FarSegmentRule::make(const Vec3& a, const Vec3& b, int degree, double s,
                                                   std::span<const double> weight) {
  if (degree < 1 || degree > far_rule::max_degree || weight.empty() || weight.size() > rule_weight_count) {
    return std::nullopt;
  }
  for (double w : weight) {
    if (!(w >= 0.0) || !std::isfinite(w)) return std::nullopt;
  }
  FarSegmentRule rule;
  rule.a_ = a;
  rule.ab_ = b - a;
  rule.length_ = rule.ab_.norm();
  rule.s_ = s;
  rule.inverse_s_ = 1 / s;
  rule.degree_ = degree;
  rule.weight_degree_ = int(weight.size()) - 1;
  while (rule.weight_degree_ > 0 && weight[std::size_t(rule.weight_degree_)] == 0.0) --rule.weight_degree_;
  std::copy(weight.begin(), weight.end(), rule.weight_.begin());
  // (s L²)^(i/2) / L, divided by w_0 where w is that constant.
  const double scaled = s * rule.length_ * rule.length_;
  double power = 1;
  for (int k = 0; k < degree / 2; ++k) power *= scaled;
  if (degree % 2 == 1) power *= std::sqrt(scaled);
  rule.f_factor_ = power / rule.length_;
  if (rule.weight_degree_ == 0) rule.f_factor_ /= weight[0];
  rule.gradient_factor_ = std::sqrt(s) * rule.length_;
  rule.two_over_length_ = 2 / rule.length_;
  const auto usable = [](double x) { return std::isnormal(x); };
  if (!usable(rule.length_) || !usable(rule.inverse_s_) || !usable(rule.f_factor_) ||
      !usable(rule.gradient_factor_) || !usable(rule.two_over_length_)) {
    return std::nullopt;
  }
  rule.bins_ = far_rule::table_for(degree).data();  // built here, once per degree, not at the first point
  (void)far_rule::rules();
  return rule;
}

double FarSegmentRule::weight_bound(double focal_sum) const {
  const double radius = 0.5 + 0.25 * focal_sum;
  double w = weight_[std::size_t(weight_degree_)];
  for (int k = weight_degree_ - 1; k >= 0; --k) w = w * radius + weight_[std::size_t(k)];
  return w;
}

bool FarSegmentRule::evaluate_nodes(const Vec3& p, int n, bool gradient, FieldSample& out) const {
  static constexpr auto values = far_rule::sum_nodes_table<false>(std::make_integer_sequence<int, far_rule::max_degree>{});
  static constexpr auto both = far_rule::sum_nodes_table<true>(std::make_integer_sequence<int, far_rule::max_degree>{});
  const far_rule::SumNodes sum = (gradient ? both : values)[std::size_t(degree_)][std::size_t(n / 2)];
  const far_rule::NodeSums sums = sum(far_rule::rules()[std::size_t(n)], p - a_, ab_, s_, weight_, weight_degree_);
  // L, times w_0 where w is that constant (sum_nodes multiplies by w(t) only where it is not).
  const double front = weight_degree_ == 0 ? length_ * weight_[0] : length_;
  const double f = front * sums.f;
  if (!(f >= std::numeric_limits<double>::min() && f < infinity)) return false;
  out.value = f;
  if (gradient) {
    const double factor = -double(degree_) * s_ * front;  // ∂q^(−i/2)/∂P = −i s q^(−i/2−1) (P − Γ)
    out.gradient = Vec3(factor * sums.g[0], factor * sums.g[1], factor * sums.g[2]);
    if (!out.gradient.allFinite()) return false;
  } else {
    out.gradient = Vec3::Zero();
  }
  return true;
}

}  // namespace skelconv
