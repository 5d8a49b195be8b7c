// Implementation of src/detail/far_rule_batch.hpp.
#include "../detail/far_rule_batch.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <emmintrin.h>
#include <immintrin.h>
#include <limits>
#include <utility>

#include <boost/container/small_vector.hpp>

#include "far_rule_node.hpp"

namespace skelconv::detail {

// Named, so that nothing here meets another file's names in a unity build.
namespace far_rule_batch {
namespace {

/// Segments whose scratch (S at both ends of a ball, or at P) lives on the
/// stack; longer lists allocate it.
constexpr std::size_t stack_segments = 1024;
using Scratch = boost::container::small_vector<double, stack_segments>;

/// Lane 0, lane 1.
double low(__m128d v) { return _mm_cvtsd_f64(v); }
double high(__m128d v) { return _mm_cvtsd_f64(_mm_unpackhi_pd(v, v)); }

/// Two segments' values of `v` in lanes 0 and 1 (the same one twice for a
/// list's odd last segment).
__m128d pair(const double* v, std::size_t k0, std::size_t k1) { return _mm_set_pd(v[k1], v[k0]); }

/// The sums of an n-node rule's even and odd nodes (n even) for the two
/// segments in the lanes of `segment`.
struct NodeLaneSums {
  __m128d f_even, f_odd, g_x_even, g_y_even, g_z_even, g_x_odd, g_y_odd, g_z_odd;
};

/// NodeLaneSums on `Lanes` lanes. SSE2's 2: one segment per lane, the even
/// nodes into one sum and the odd ones into another. AVX's 4: the two
/// segments' even nodes in lanes 0 and 1, their odd nodes in lanes 2 and 3,
/// so that each lane does what an SSE2 lane does, in the same order
/// (add_node, without FMA: the same bits), with half the instructions and
/// divisions. No AVX intrinsic here (GCC's vector operators and shuffles):
/// it is inlined into terms_impl_avx, whose code is compiled for AVX.
template <int I, bool Gradient, bool Scalis, int Lanes>
[[gnu::always_inline]] inline NodeLaneSums sum_nodes(const far_rule::Rule& rule, int n,
                                                     const far_rule::NodeSegment& segment) {
  using far_rule::add_node;
  NodeLaneSums sums{};
  if constexpr (Lanes == 2) {
    for (int node = 0; node < n; node += 2) {  // n even
      const std::size_t even = std::size_t(node), odd = even + 1;
      add_node<I, Gradient, Scalis>(_mm_set1_pd(rule.t[even]), _mm_set1_pd(rule.g[even]), segment, sums.f_even,
                                    sums.g_x_even, sums.g_y_even, sums.g_z_even);
      add_node<I, Gradient, Scalis>(_mm_set1_pd(rule.t[odd]), _mm_set1_pd(rule.g[odd]), segment, sums.f_odd,
                                    sums.g_x_odd, sums.g_y_odd, sums.g_z_odd);
    }
  } else {
    static_assert(Lanes == 4);
    using Wide = far_rule::LaneVector<4>::type;
    // Both segments twice: lanes 0, 1 and again 2, 3.
    const auto twice = [](__m128d v) -> Wide { return __builtin_shufflevector(v, v, 0, 1, 0, 1); };
    Wide w[FarSegmentRule::Integrand::weight_count];
    for (std::size_t d = 0; d < FarSegmentRule::Integrand::weight_count; ++d) w[d] = twice(segment.w[d]);
    const far_rule::NodeSegmentOf<4> wide{twice(segment.pa_x),      twice(segment.pa_y), twice(segment.pa_z),
                                          twice(segment.ab_x),      twice(segment.ab_y), twice(segment.ab_z),
                                          twice(segment.sharpness), twice(segment.c0),   twice(segment.c1),
                                          w,                        segment.weight_degree};
    Wide f{}, g_x{}, g_y{}, g_z{};
    for (std::size_t even = 0; even < std::size_t(n); even += 2) {
      const std::size_t odd = even + 1;
      // The even node's t (and g) in lanes 0, 1, the odd node's in 2, 3.
      const Wide t = __builtin_shufflevector(_mm_set1_pd(rule.t[even]), _mm_set1_pd(rule.t[odd]), 0, 1, 2, 3);
      const Wide g = __builtin_shufflevector(_mm_set1_pd(rule.g[even]), _mm_set1_pd(rule.g[odd]), 0, 1, 2, 3);
      add_node<I, Gradient, Scalis>(t, g, wide, f, g_x, g_y, g_z);
    }
    const auto even = [](Wide v) -> __m128d { return __builtin_shufflevector(v, v, 0, 1); };
    const auto odd = [](Wide v) -> __m128d { return __builtin_shufflevector(v, v, 2, 3); };
    sums = {even(f), odd(f), even(g_x), even(g_y), even(g_z), odd(g_x), odd(g_y), odd(g_z)};
  }
  return sums;
}

/// Whether this processor (and the system, which must save the ymm
/// registers) runs AVX: the build targets plain x86-64, so terms_impl_avx
/// is taken only where it can run.
bool has_avx() {
  static const bool avx = __builtin_cpu_supports("avx");
  return avx;
}

/// 4 lanes only where the processor runs them; anything else is SSE2's 2.
bool on_avx(int lanes) { return lanes == 4 && has_avx(); }

}  // namespace
}  // namespace far_rule_batch

std::optional<FarRuleBatch> FarRuleBatch::make(std::span<const FarSegmentRule> rules) {
  if (rules.empty()) return std::nullopt;
  const FarSegmentRule& first = rules.front();
  for (const FarSegmentRule& rule : rules) {
    if (rule.degree_ != first.degree_ || rule.integrand_.scalis != first.integrand_.scalis ||
        rule.integrand_.weight_degree != first.integrand_.weight_degree) {
      return std::nullopt;
    }
  }
  FarRuleBatch batch;
  batch.rules_.assign(rules.begin(), rules.end());
  batch.degree_ = first.degree_;
  batch.scalis_ = first.integrand_.scalis;
  batch.weight_degree_ = first.integrand_.weight_degree;
  for (const FarSegmentRule& rule : rules) {
    batch.a_x_.push_back(rule.a_.x());
    batch.a_y_.push_back(rule.a_.y());
    batch.a_z_.push_back(rule.a_.z());
    batch.ab_x_.push_back(rule.ab_.x());
    batch.ab_y_.push_back(rule.ab_.y());
    batch.ab_z_.push_back(rule.ab_.z());
    batch.offset_a_.push_back(rule.offset_a_);
    batch.offset_b_.push_back(rule.offset_b_);
    batch.two_over_length_.push_back(rule.two_over_length_);
    batch.centroid_x_.push_back(rule.centroid_.x());
    batch.centroid_y_.push_back(rule.centroid_.y());
    batch.centroid_z_.push_back(rule.centroid_.z());
    batch.spread_.push_back(rule.spread_);
    batch.q_unit_.push_back(rule.q_unit_);
    batch.lower_front_.push_back(rule.lower_front_);
    batch.s_.push_back(rule.integrand_.s);
    batch.c0_.push_back(rule.integrand_.c0);
    batch.c1_.push_back(rule.integrand_.c1);
    batch.f_factor_.push_back(rule.f_factor_);
    batch.gradient_factor_.push_back(rule.gradient_factor_);
    batch.weight_varies_.push_back(rule.weight_varies_);
    batch.front_.push_back(rule.front_);
    batch.gradient_front_.push_back(rule.gradient_front_);
    for (std::size_t j = 0; j < batch.w_.size(); ++j) batch.w_[j].push_back(rule.integrand_.w[j]);
  }
  return batch;
}

template <int I, bool Scalis, bool Ball, int Lanes>
[[gnu::always_inline]] inline void FarRuleBatch::choose_lanes(const Vec3& p, double radius, double tolerance,
                                                              std::uint8_t* nodes) const {
  using namespace far_rule_batch;
  using far_rule::lanes_of;
  using far_rule::lanes_sqrt;
  const std::size_t count = rules_.size();
  // Per segment, `Lanes` at a time: Q at the ends, S (at P, or its least
  // and largest over the ball) and the lower bound, added to f̲ in order.
  Scratch least(count), largest(Ball ? count : 0);
  // The columns' addresses in locals: the stores below (bytes) could alias
  // any member as far as the compiler knows, which would reload them.
  const double *a_x = a_x_.data(), *a_y = a_y_.data(), *a_z = a_z_.data(), *ab_x = ab_x_.data(),
               *ab_y = ab_y_.data(), *ab_z = ab_z_.data(), *offset_a = offset_a_.data(), *offset_b = offset_b_.data(),
               *centroid_x = centroid_x_.data(), *centroid_y = centroid_y_.data(), *centroid_z = centroid_z_.data(),
               *spread = spread_.data(), *q_unit = q_unit_.data(), *lower_front = lower_front_.data(),
               *two_over_length = two_over_length_.data(), *f_factor = f_factor_.data(),
               *gradient_factor = gradient_factor_.data();
  const std::uint8_t* weight_varies = weight_varies_.data();
  const FarSegmentRule* rules = rules_.data();
  double lower = 0;
  // Segments k … k + used − 1, one per lane of the vector `load` returns (a
  // column's values from k on, or segment k in every lane when used = 1):
  // each lane does the same operations in the same order whatever the
  // vector's width (2 or 4), hence the same bits.
  const auto segments = [&](std::size_t k, std::size_t used, auto load) __attribute__((always_inline)) {
    using V = decltype(load(a_x));
    const V pa_x = lanes_of<V>(p.x()) - load(a_x), pa_y = lanes_of<V>(p.y()) - load(a_y),
            pa_z = lanes_of<V>(p.z()) - load(a_z);
    const V pb_x = pa_x - load(ab_x), pb_y = pa_y - load(ab_y), pb_z = pa_z - load(ab_z);
    // (x² + y²) + z², as Eigen's squaredNorm of a Vec3 adds them.
    const V q_a = ((pa_x * pa_x + pa_y * pa_y) + pa_z * pa_z) + load(offset_a);
    const V q_b = ((pb_x * pb_x + pb_y * pb_y) + pb_z * pb_z) + load(offset_b);
    const V c_x = lanes_of<V>(p.x()) - load(centroid_x), c_y = lanes_of<V>(p.y()) - load(centroid_y),
            c_z = lanes_of<V>(p.z()) - load(centroid_z);
    const V to_centroid = (c_x * c_x + c_y * c_y) + c_z * c_z;
    V mean_square;
    if constexpr (Ball) {  // ball_mean_square
      const V far = lanes_sqrt(to_centroid) + lanes_of<V>(radius);
      mean_square = far * far + load(spread);
    } else {  // mean_square
      mean_square = to_centroid + load(spread);
    }
    const V term = load(lower_front) * far_rule::lanes_half_power<I>(load(q_unit) / mean_square);
    const V roots = lanes_sqrt(q_a) + lanes_sqrt(q_b);
    const V scale = load(two_over_length);
    V s_least = roots * scale, s_largest{};
    if constexpr (Ball) {  // ball_nodes: S over the ball
      s_least = (roots - lanes_of<V>(2 * radius)) * scale;
      s_largest = (roots + lanes_of<V>(2 * radius)) * scale;
    }
    for (std::size_t lane = 0; lane < used; ++lane) {
      if constexpr (Ball) largest[k + lane] = s_largest[lane];
      least[k + lane] = s_least[lane];
      lower += term[lane];
    }
  };
  std::size_t k = 0;
  if constexpr (Lanes == 4) {
    using Wide = far_rule::LaneVector<4>::type;
    for (; k + 3 < count; k += 4) {
      segments(k, 4, [k](const double* column) __attribute__((always_inline)) {
        Wide v;
        std::memcpy(&v, column + k, sizeof v);
        return v;
      });
    }
  }
  for (; k + 1 < count; k += 2) {
    segments(k, 2, [k](const double* column) __attribute__((always_inline)) { return _mm_loadu_pd(column + k); });
  }
  if (k < count) {
    segments(k, 1, [k](const double* column) __attribute__((always_inline)) { return _mm_set1_pd(column[k]); });
  }
  const double budget = tolerance * lower / double(count);
  if (!(budget > 0.0)) {
    std::fill(nodes, nodes + count, std::uint8_t(0));
    return;
  }
  // FarSegmentRule::nodes_between, its constants read side by side (W, for
  // a weight that varies, from the rule itself).
  constexpr int scalis = Scalis ? 1 : 0;
  constexpr int longest = Scalis ? FarSegmentRule::max_scalis_nodes : FarSegmentRule::max_classical_nodes;
  const FarRuleBin* bins = rules_.front().bins_;
  for (std::size_t k = 0; k < count; ++k) {
    const double focal_sum = least[k], focal_sum_weight = Ball ? largest[k] : least[k];
    if (!(focal_sum > 2.0 && focal_sum_weight <= std::numeric_limits<double>::max())) {
      nodes[k] = 0;
      continue;
    }
    double f_allowed = budget * f_factor[k];
    if (weight_varies[k]) f_allowed /= rules[k].template weight_bound<I, scalis>(focal_sum_weight);
    nodes[k] = std::uint8_t(FarSegmentRule::table_nodes(bins[FarSegmentRule::bin_of(focal_sum)], f_allowed,
                                                        f_allowed * gradient_factor[k], longest));
  }
}

template <int I, bool Scalis, bool Ball>
void FarRuleBatch::choose_impl(const Vec3& p, double radius, double tolerance, std::uint8_t* nodes) const {
  choose_lanes<I, Scalis, Ball, 2>(p, radius, tolerance, nodes);
}

template <int I, bool Scalis, bool Ball>
[[gnu::target("avx")]] void FarRuleBatch::choose_impl_avx(const Vec3& p, double radius, double tolerance,
                                                          std::uint8_t* nodes) const {
  choose_lanes<I, Scalis, Ball, 4>(p, radius, tolerance, nodes);
}

template <int I, bool Scalis, bool Gradient, int Lanes>
[[gnu::always_inline]] inline void FarRuleBatch::terms_lanes(const Vec3& p, std::size_t first,
                                                             const std::uint8_t* nodes, Terms& out) const {
  using namespace far_rule_batch;
  using detail::far_rule::NodeSegment;
  const std::size_t size = std::min(chunk, rules_.size() - first);
  out.size = size;
  // Grouped by n (0, the exact function, first), in order within a group:
  // the order Skeleton's tolerance mode adds the terms in.
  // Each group's members as the bits of one word, found 16 segments at a
  // time, then read off in order: no counter in memory that consecutive
  // segments of one group would increment one after the other.
  // 0 (exact), 2, 4, …, the longest rule of the kind.
  constexpr std::size_t groups =
      (Scalis ? FarSegmentRule::max_scalis_nodes : FarSegmentRule::max_classical_nodes) / 2 + 1;
  static_assert(chunk == 64, "one bit of a 64-bit word per segment of a chunk");
  alignas(16) std::array<std::uint8_t, chunk> padded;
  padded.fill(0xff);  // no n: past the list's end
  std::copy(nodes + first, nodes + first + size, padded.begin());
  std::array<std::size_t, groups + 1> begin{};
  std::size_t filled = 0;
  for (std::size_t g = 0; g < groups; ++g) {
    const __m128i n = _mm_set1_epi8(char(2 * g));
    std::uint64_t members = 0;
    for (std::size_t q = 0; q < chunk; q += 16) {
      const __m128i bytes = _mm_load_si128(reinterpret_cast<const __m128i*>(&padded[q]));
      members |= std::uint64_t(std::uint16_t(_mm_movemask_epi8(_mm_cmpeq_epi8(bytes, n)))) << q;
    }
    begin[g] = filled;
    for (; members != 0; members &= members - 1) out.order[filled++] = std::uint8_t(std::countr_zero(members));
  }
  begin[groups] = filled;
  for (std::size_t j = 0; j < begin[1]; ++j) out.exact[j] = true;
  const __m128d p_x = _mm_set1_pd(p.x()), p_y = _mm_set1_pd(p.y()), p_z = _mm_set1_pd(p.z());
  const __m128d one = _mm_set1_pd(1.0);
  // The columns' addresses and the weight degree in locals: the stores to
  // `out` could alias any member as far as the compiler knows.
  const double *a_x_at = a_x_.data(), *a_y_at = a_y_.data(), *a_z_at = a_z_.data(), *ab_x_at = ab_x_.data(),
               *ab_y_at = ab_y_.data(), *ab_z_at = ab_z_.data(), *s_at = s_.data(), *c0_at = c0_.data(),
               *c1_at = c1_.data(), *front_at = front_.data(), *gradient_front_at = gradient_front_.data();
  std::array<const double*, FarSegmentRule::Integrand::weight_count> w_columns;
  for (std::size_t d = 0; d < w_columns.size(); ++d) w_columns[d] = w_[d].data();
  const int weight_degree = weight_degree_;
  for (std::size_t g = 1; g < groups; ++g) {
    if (begin[g] == begin[g + 1]) continue;
    const int n = int(2 * g);
    const detail::far_rule::Rule& rule = detail::far_rule::gauss_legendre_rule(n);
    // Two segments of this group at a time, one per lane.
    for (std::size_t j = begin[g]; j < begin[g + 1]; j += 2) {
      const std::size_t j1 = std::min(j + 1, begin[g + 1] - 1);
      const std::size_t k0 = first + out.order[j], k1 = first + out.order[j1];
      const __m128d pa_x = _mm_sub_pd(p_x, pair(a_x_at, k0, k1)), pa_y = _mm_sub_pd(p_y, pair(a_y_at, k0, k1)),
                    pa_z = _mm_sub_pd(p_z, pair(a_z_at, k0, k1));
      const __m128d ab_x = pair(ab_x_at, k0, k1), ab_y = pair(ab_y_at, k0, k1), ab_z = pair(ab_z_at, k0, k1);
      __m128d w[FarSegmentRule::Integrand::weight_count] = {};
      NodeSegment segment{pa_x, pa_y, pa_z, ab_x, ab_y, ab_z, one, one, one, w, weight_degree};
      if constexpr (Scalis) {
        segment.c0 = pair(c0_at, k0, k1);
        segment.c1 = pair(c1_at, k0, k1);
      } else {
        segment.sharpness = pair(s_at, k0, k1);
        for (int d = 0; d <= weight_degree; ++d) w[std::size_t(d)] = pair(w_columns[std::size_t(d)], k0, k1);
      }
      // Each rule's even and odd nodes summed apart (the lanes of sum_nodes).
      const NodeLaneSums sums = sum_nodes<I, Gradient, Scalis, Lanes>(rule, n, segment);
      const auto [f_even, f_odd, g_x_even, g_y_even, g_z_even, g_x_odd, g_y_odd, g_z_odd] = sums;
      // FarSegmentRule::evaluate_with, per lane.
      const __m128d front = pair(front_at, k0, k1);
      const __m128d value = _mm_mul_pd(front, _mm_add_pd(f_even, f_odd));
      __m128d gradient_x = _mm_setzero_pd(), gradient_y = gradient_x, gradient_z = gradient_x;
      if constexpr (Gradient) {
        const __m128d factor = _mm_mul_pd(pair(gradient_front_at, k0, k1), front);
        gradient_x = _mm_mul_pd(factor, _mm_add_pd(g_x_even, g_x_odd));
        gradient_y = _mm_mul_pd(factor, _mm_add_pd(g_y_even, g_y_odd));
        gradient_z = _mm_mul_pd(factor, _mm_add_pd(g_z_even, g_z_odd));
      }
      const auto store = [&](std::size_t at, double f_value, double x, double y, double z) {
        bool usable = f_value >= std::numeric_limits<double>::min() && f_value < std::numeric_limits<double>::infinity();
        if (Gradient) usable = usable && std::isfinite(x) && std::isfinite(y) && std::isfinite(z);
        out.exact[at] = !usable;
        out.value[at] = f_value;
        out.gradient_x[at] = x;
        out.gradient_y[at] = y;
        out.gradient_z[at] = z;
      };
      store(j, low(value), low(gradient_x), low(gradient_y), low(gradient_z));
      if (j1 != j) store(j1, high(value), high(gradient_x), high(gradient_y), high(gradient_z));
    }
  }
}

template <int I, bool Scalis, bool Gradient>
void FarRuleBatch::terms_impl(const Vec3& p, std::size_t first, const std::uint8_t* nodes, Terms& out) const {
  terms_lanes<I, Scalis, Gradient, 2>(p, first, nodes, out);
}

template <int I, bool Scalis, bool Gradient>
[[gnu::target("avx")]] void FarRuleBatch::terms_impl_avx(const Vec3& p, std::size_t first, const std::uint8_t* nodes,
                                                         Terms& out) const {
  terms_lanes<I, Scalis, Gradient, 4>(p, first, nodes, out);
}

namespace {

using ChooseImpl = void (FarRuleBatch::*)(const Vec3&, double, double, std::uint8_t*) const;
using TermsImpl = void (FarRuleBatch::*)(const Vec3&, std::size_t, const std::uint8_t*, FarRuleBatch::Terms&) const;

}  // namespace

// The passes' instantiations, per kind at [degree] (classical 1–16, SCALIS
// 1–10: FarSegmentRule's degrees).
template <bool Scalis, bool Ball, bool Avx, int... I>
constexpr auto FarRuleBatch::choose_table(std::integer_sequence<int, I...>) {
  if constexpr (Avx) {
    return std::array<ChooseImpl, sizeof...(I) + 1>{nullptr, &FarRuleBatch::choose_impl_avx<I + 1, Scalis, Ball>...};
  } else {
    return std::array<ChooseImpl, sizeof...(I) + 1>{nullptr, &FarRuleBatch::choose_impl<I + 1, Scalis, Ball>...};
  }
}
template <bool Scalis, bool Gradient, bool Avx, int... I>
constexpr auto FarRuleBatch::terms_table(std::integer_sequence<int, I...>) {
  if constexpr (Avx) {
    return std::array<TermsImpl, sizeof...(I) + 1>{nullptr, &FarRuleBatch::terms_impl_avx<I + 1, Scalis, Gradient>...};
  } else {
    return std::array<TermsImpl, sizeof...(I) + 1>{nullptr, &FarRuleBatch::terms_impl<I + 1, Scalis, Gradient>...};
  }
}

int FarRuleBatch::widest_lanes() { return far_rule_batch::has_avx() ? 4 : 2; }

template <bool Scalis, bool Ball, int Degrees>
constexpr auto FarRuleBatch::choose_tables() {
  constexpr auto degrees = std::make_integer_sequence<int, Degrees>{};
  return std::array{choose_table<Scalis, Ball, false>(degrees), choose_table<Scalis, Ball, true>(degrees)};
}
template <bool Scalis, int Degrees>
constexpr auto FarRuleBatch::terms_tables() {
  constexpr auto degrees = std::make_integer_sequence<int, Degrees>{};
  return std::array{std::array{terms_table<Scalis, false, false>(degrees), terms_table<Scalis, true, false>(degrees)},
                    std::array{terms_table<Scalis, false, true>(degrees), terms_table<Scalis, true, true>(degrees)}};
}

// The tables below: [AVX] or [AVX][∇f], then [degree] (classical 1–16,
// SCALIS 1–10: FarSegmentRule's degrees).
void FarRuleBatch::choose(const Vec3& p, double tolerance, std::uint8_t* nodes, int lanes) const {
  static constexpr auto classical = choose_tables<false, false, 16>();
  static constexpr auto scalis = choose_tables<true, false, 10>();
  const std::size_t avx = far_rule_batch::on_avx(lanes) ? 1 : 0, at = std::size_t(degree_);
  (this->*(scalis_ ? scalis[avx][at] : classical[avx][at]))(p, 0.0, tolerance, nodes);
}

void FarRuleBatch::choose_near(const Vec3& centre, double radius, double tolerance, std::uint8_t* nodes,
                               int lanes) const {
  static constexpr auto classical = choose_tables<false, true, 16>();
  static constexpr auto scalis = choose_tables<true, true, 10>();
  const std::size_t avx = far_rule_batch::on_avx(lanes) ? 1 : 0, at = std::size_t(degree_);
  (this->*(scalis_ ? scalis[avx][at] : classical[avx][at]))(centre, radius, tolerance, nodes);
}

void FarRuleBatch::terms(const Vec3& p, std::size_t first, const std::uint8_t* nodes, bool gradient, Terms& out,
                         int lanes) const {
  static constexpr auto classical = terms_tables<false, 16>();
  static constexpr auto scalis = terms_tables<true, 10>();
  const std::size_t avx = far_rule_batch::on_avx(lanes) ? 1 : 0, with_gradient = gradient ? 1 : 0;
  const std::size_t at = std::size_t(degree_);
  const TermsImpl impl = scalis_ ? scalis[avx][with_gradient][at] : classical[avx][with_gradient][at];
  (this->*impl)(p, first, nodes, out);
}

}  // namespace skelconv::detail
