// skelconv/detail/gauss_moments.hpp — segment moments by a fixed Gauss–Legendre rule,
// where the recurrences cancel and the rule is exact (to rounding).
//
// Generated segment kernels need M_{k,m} = ∫_{t0}^{t1} t^k q(t)^(−m/2) dt with
// q = a t² − 2 b t + c (docs/mathematics.md §2). Three places where recurrence (1) and the
// moment relations lose digits are better served by an N-point
// Gauss–Legendre rule, whose positive weights and positive integrand leave
// nothing to cancel:
//
//  * compact kernels of even degree i: t^k q^(i/2) is a polynomial of degree
//    ≤ i + k, integrated exactly by N points when 2N − 1 ≥ i + k (the
//    generator takes the smallest of Boost's tabulated N = 7, 10, 15);
//  * inverse and Cauchy kernels with P far from the segment's line compared
//    with its length (D ≥ 2 a², i.e. the complex roots t* ± i√D/a of q at
//    least √2 from the real axis in units of |AB|): the moment relations
//    lose a factor ~ D/a² per step there (the kernel is nearly flat), while
//    the rule's error, for an integrand with a pole of order m/2 outside the
//    Bernstein ellipse of parameter ρ ≥ 5.8, is below 2^−55 of the integral
//    with N = 20 (the N-point rule's bound (64/15) M ρ^(2−2N)/(ρ² − 1) of
//    Trefethen, Approximation Theory and Approximation Practice, Thm 19.3:
//    far_field_min_y_20_nodes below). The verifier checks both claims
//    against quadrature of the definition;
//  * SCALIS segments (weights τ(t)^(i−1), moments up to t^10), wherever P is
//    not near the line beside the segment: segment_moments_gauss_panels
//    below, on panels graded towards the roots of q.
//
// Nodes and weights are Boost.Math's, tabulated to the precision of T
// (double, long double, float128, …).
#pragma once

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>

#include "skelconv/detail/far_field_series.hpp"
#include "skelconv/not_converged.hpp"

namespace skelconv {

/// How the rule's nodes x ∈ [−1, 1] map to [t0, t1].
enum class NodeMap {
  linear,  ///< t = middle + half_width x: Gauss–Legendre itself
  /// t = middle + half_width sin(πx/2), weight × (π/2) cos(πx/2): where q has
  /// a root at an end of [t0, t1] (a compact support clipping the
  /// interval), q^(i/2) ~ (t1 − t)^(i/2) has a branch point there, on which
  /// Gauss–Legendre converges only like N^−(i+2); after the map t1 − t ~
  /// (1 − x)², so q^(i/2) ~ (1 − x)^i is analytic and the rule converges
  /// geometrically again, with ρ set by q's other root.
  sine,
};

/// Boost's N-point Gauss–Legendre table (nonnegative nodes) after the sine
/// map of NodeMap::sine, computed once per table type.
template <class T, unsigned N>
const auto& sine_mapped_rule() {
  using Table = std::decay_t<decltype(boost::math::quadrature::gauss<T, N>::abscissa())>;
  struct Mapped {
    Table abscissa, weights;
  };
  static const Mapped mapped = [] {
    using X = std::decay_t<decltype(boost::math::quadrature::gauss<T, N>::abscissa()[0])>;
    using std::cos, std::sin;
    const X half_pi = boost::math::constants::half_pi<X>();
    Mapped m{boost::math::quadrature::gauss<T, N>::abscissa(), boost::math::quadrature::gauss<T, N>::weights()};
    for (std::size_t j = 0; j < m.abscissa.size(); ++j) {
      const X x = m.abscissa[j];
      m.abscissa[j] = sin(half_pi * x);
      m.weights[j] = m.weights[j] * half_pi * cos(half_pi * x);
    }
    return m;
  }();
  return mapped;
}

/// An N-point rule's nodes x ∈ [−1, 1] and weights g in the order every
/// moment adds them: the middle node (odd N), then +x_j, −x_j for Boost's
/// nonnegative nodes x_j in its order.
template <class T, unsigned N>
struct RuleInNodeOrder {
  std::array<T, N> x, g;
};

/// Boost's N-point Gauss–Legendre table (after the sine map for
/// NodeMap::sine) in node order (RuleInNodeOrder), laid out once per type:
/// one loop over the nodes then places them all alike.
template <class T, unsigned N, NodeMap map>
const RuleInNodeOrder<T, N>& rule_in_node_order() {
  static const RuleInNodeOrder<T, N> rule = [] {
    using Rule = boost::math::quadrature::gauss<T, N>;
    const auto& x = map == NodeMap::linear ? Rule::abscissa() : sine_mapped_rule<T, N>().abscissa;
    const auto& g = map == NodeMap::linear ? Rule::weights() : sine_mapped_rule<T, N>().weights;
    RuleInNodeOrder<T, N> r;
    unsigned n = 0, first = 0;
    if (N % 2 == 1) {
      r.x[n] = T(0);
      r.g[n++] = g[0];
      first = 1;
    }
    for (unsigned j = first; j < x.size(); ++j) {
      r.x[n] = x[j];
      r.g[n++] = g[j];
      r.x[n] = -x[j];
      r.g[n++] = g[j];
    }
    return r;
  }();
  return rule;
}

/// One node of a rule: the parameter t, q(t) ≥ 0 and dt/dx there.
template <class T>
struct MomentNode {
  T t;
  T q;
  T jacobian;
};

/// The moment sums of add_moments_at_nodes for two orders m, m + 2 and
/// weights t^0 … t^K in double (a SCALIS ∇f: m_hi = m_lo + 2), node by node:
/// out[l (K + 1) + k] + term(node 0) + term(node 1) + … in node order, where
/// term = weight · q^(1 − l) · t^k, each power formed by one product per
/// step (weight × q, then × t per k), as add_moments_at_nodes forms every
/// moment (the verifier's baselines). The two orders sit side by side in one
/// SSE2 register, so one addition and one product serve both, and the 2(K +
/// 1) sums stay in registers for the whole pass over the nodes: the same
/// operations on each moment, in the same order, hence the same bits, in
/// half the instructions.
template <unsigned N, int K>
void add_two_order_sums(const std::array<double, N>& t, const std::array<double, N>& q,
                        const std::array<double, N>& weight, double* out) {
  using Pair = double __attribute__((vector_size(16)));  // {order m + 2, order m}
  Pair sums[K + 1];
  for (int k = 0; k <= K; ++k) sums[k] = Pair{out[(K + 1) + k], out[k]};
  // One node per iteration: unrolled over the nodes, the compiler forms
  // every node's terms ahead of the sums and spills them.
#pragma GCC unroll 1
  for (unsigned j = 0; j < N; ++j) {
    Pair term{weight[j], weight[j] * q[j]};
    const Pair tj{t[j], t[j]};
    for (int k = 0; k <= K; ++k) {
      sums[k] += term;
      term *= tj;
    }
  }
  for (int k = 0; k <= K; ++k) {
    out[(K + 1) + k] = sums[k][0];
    out[k] = sums[k][1];
  }
}

/// The same for one order m (f alone): the K + 1 sums in registers for the
/// whole pass over the nodes, each term one product from the last.
template <class T, unsigned N, int K>
void add_one_order_sums(const std::array<T, N>& t, const std::array<T, N>& weight, T* out) {
  T sums[K + 1];
  for (int k = 0; k <= K; ++k) sums[k] = out[k];
#pragma GCC unroll 1
  for (unsigned j = 0; j < N; ++j) {
    T term = weight[j];
    for (int k = 0; k <= K; ++k) {
      sums[k] += term;
      term *= t[j];
    }
  }
  for (int k = 0; k <= K; ++k) out[k] = sums[k];
}

/// The sums of add_moments_at_nodes in registers where the shape allows it:
/// one order (f) or, in double, two (f and ∇f), with weights up to t^4
/// (every inverse and Cauchy kernel up to the SCALIS degree 4); false
/// otherwise, for the caller's moment-by-moment sums.
template <class T, unsigned N>
bool add_sums_in_registers(int levels, int k_max, const std::array<T, N>& t, const std::array<T, N>& q,
                           const std::array<T, N>& weight, T* out) {
  if (levels == 1) {
    switch (k_max) {
      case 0: add_one_order_sums<T, N, 0>(t, weight, out); return true;
      case 1: add_one_order_sums<T, N, 1>(t, weight, out); return true;
      case 2: add_one_order_sums<T, N, 2>(t, weight, out); return true;
      case 3: add_one_order_sums<T, N, 3>(t, weight, out); return true;
      case 4: add_one_order_sums<T, N, 4>(t, weight, out); return true;
      default: return false;
    }
  }
  if constexpr (std::is_same_v<T, double>) {
    if (levels != 2) return false;
    switch (k_max) {
      case 0: add_two_order_sums<N, 0>(t, q, weight, out); return true;
      case 1: add_two_order_sums<N, 1>(t, q, weight, out); return true;
      case 2: add_two_order_sums<N, 2>(t, q, weight, out); return true;
      case 3: add_two_order_sums<N, 3>(t, q, weight, out); return true;
      case 4: add_two_order_sums<N, 4>(t, q, weight, out); return true;
      default: return false;
    }
  }
  return false;
}

/// Adds the N-point Gauss–Legendre rule over x ∈ [−1, 1] (after `map`) for
/// M_{k,m} = ∫ t^k q^(−m/2) dt, k = 0…k_max, m = m_lo, m_lo + 2, …, m_hi
/// (m may be negative: q^(|m|/2) for compact kernels, where q ≥ 0), to
/// out[((m − m_lo)/2)(k_max + 1) + k]; node_at(x) gives the MomentNode at x.
///
/// The nodes are placed first, then each moment is one sum over them: the
/// node loops have a compile-time length and no dependence between nodes,
/// so their divisions and products overlap, and each sum is accumulated in
/// a register rather than in `out`.
template <class T, unsigned N, NodeMap map, class NodeAt>
void add_moments_at_nodes(int m_lo, int m_hi, int k_max, const NodeAt& node_at, T* out) {
  using std::sqrt;
  // t, q and the weight g dt/dx at the nodes, in the rule's node order.
  const RuleInNodeOrder<T, N>& rule = rule_in_node_order<T, N, map>();
  std::array<T, N> t, q, weight;
  for (unsigned n = 0; n < N; ++n) {
    const MomentNode<T> node = node_at(rule.x[n]);
    t[n] = node.t;
    q[n] = node.q;
    weight[n] = node.jacobian * rule.g[n];
  }
  // weight × q^(−m_hi/2) from integer powers of q (even m) or of √q (odd
  // m), then × q per level down to m_lo: no division by a q that may be 0
  // at a clipped end.
  const bool even = m_hi % 2 == 0;
  const int power = (m_hi <= 0 ? -m_hi : m_hi) / (even ? 2 : 1);
  std::array<T, N> base;
  for (unsigned j = 0; j < N; ++j) {
    const T root = even ? q[j] : sqrt(q[j]);
    base[j] = m_hi <= 0 ? root : T(1) / root;
  }
  for (int i = 0; i < power; ++i)
    for (unsigned j = 0; j < N; ++j) weight[j] *= base[j];
  const int levels = (m_hi - m_lo) / 2 + 1;
  if (add_sums_in_registers<T, N>(levels, k_max, t, q, weight, out)) return;
  const int per_level = k_max + 1;
  for (int l = levels - 1; l >= 0; --l) {
    std::array<T, N> term = weight;
    for (int k = 0; k <= k_max; ++k) {
      T sum = out[l * per_level + k];
      for (unsigned j = 0; j < N; ++j) sum += term[j];
      out[l * per_level + k] = sum;
      for (unsigned j = 0; j < N; ++j) term[j] *= t[j];
    }
    for (unsigned j = 0; j < N; ++j) weight[j] *= q[j];
  }
}

/// The node_at of add_moments_at_nodes for x ∈ [−1, 1] mapped linearly
/// onto [t0, t1]; q_at(t) evaluates q ≥ 0.
template <class T, class QuadraticAt>
auto linear_node_map(const QuadraticAt& q_at, const T& t0, const T& t1) {
  const T half_width = (t1 - t0) / 2;
  const T middle = (t0 + t1) / 2;
  return [half_width, middle, &q_at](const T& x) {
    const T t = middle + half_width * x;
    return MomentNode<T>{t, q_at(t), half_width};
  };
}

/// Adds the N-point Gauss–Legendre rule on [t0, t1] for M_{k,m} (as
/// add_moments_at_nodes); q_at(t) evaluates q ≥ 0.
template <class T, unsigned N, class QuadraticAt, NodeMap map = NodeMap::linear>
void add_segment_moments_gauss(int m_lo, int m_hi, int k_max, const QuadraticAt& q_at, const T& t0, const T& t1,
                               T* out) {
  add_moments_at_nodes<T, N, map>(m_lo, m_hi, k_max, linear_node_map(q_at, t0, t1), out);
}

/// Writes M_{k,m} = ∫ t^k q^(−m/2) dt over [middle − half_width, middle +
/// half_width] (k = 0…k_max, m = m_lo, …, m_hi, m ≤ 0: compact kernels) to
/// out[((m − m_lo)/2)(k_max + 1) + k], for q = minus_a (t − r1)(r2 − t)
/// with roots r1 ≤ t ≤ r2 given by their distances from the interval:
/// t − r1 = gap_lo + (t − interval start), r2 − t = gap_hi + (interval end
/// − t), each a sum of nonnegative terms. For the support sphere grazing
/// the segment (codegen/segment_program_builder.hpp,
/// push_support_root_alternatives), where the interval is short and q on
/// it tiny: formed as a difference of numbers ~1, q would lose ~ε/q, and
/// the interval's ends as parameters t lose ε/(its length). Here neither
/// enters: the caller finds middle, half_width and the gaps from R² − d²
/// rounded once (skelconv/detail/support_gap.hpp).
///
/// The rule: for even kernel degrees t^k q^(|m|/2) is a polynomial, exact
/// with 2N − 1 ≥ its degree (NodeMap::linear); for odd degrees q^(|m|/2)
/// has branch points at the roots, removed at a root that is an end of the
/// interval by NodeMap::sine; the generator passes an interval whose other
/// root is at least its length beyond it (ρ ≈ 3 after the map), or the
/// chord between both roots (after the map the integrand is entire). N
/// nodes leave ~1e-21 relative in the worst case the verifier found (a
/// chord, i = 15, k ≤ 4): below rounding for double; wider types take 2N.
template <class T, unsigned N, NodeMap map = NodeMap::linear>
void segment_moments_between_roots(int m_lo, int m_hi, int k_max, const T& minus_a, const T& middle,
                                   const T& half_width, const T& gap_lo, const T& gap_hi, T* out) {
  constexpr unsigned nodes = map == NodeMap::sine && std::numeric_limits<T>::digits > 64 ? 2 * N : N;
  const int count = ((m_hi - m_lo) / 2 + 1) * (k_max + 1);
  for (int i = 0; i < count; ++i) out[i] = T(0);
  add_moments_at_nodes<T, nodes, map>(
      m_lo, m_hi, k_max,
      [&](const T& x) {
        const T from_start = half_width * (T(1) + x);  // t − interval start
        const T to_end = half_width * (T(1) - x);      // interval end − t
        return MomentNode<T>{middle + half_width * x, minus_a * (gap_lo + from_start) * (gap_hi + to_end),
                             half_width};
      },
      out);
}

/// The far-field rule in double (segment_moments_gauss with m_lo > 0): the
/// fewest of Boost's tabulated node counts whose error bound is below
/// rounding, chosen by how far the poles z, z̄ = t* ± i√D/a of q lie from
/// [t0, t1].
///
/// The bound (Trefethen, Approximation Theory and Approximation Practice,
/// Theorem 19.3, whose I_n is the (n + 1)-point rule, exact to degree
/// 2n + 1): on [−1, 1] (x = (2t − t0 − t1)/(t1 − t0)) the N-point rule
/// errs by at most (64/15) M r^(2−2N)/(r² − 1) for an integrand analytic
/// inside the Bernstein ellipse E_r, |integrand| ≤ M there. The
/// poles sit at imaginary distance y = 2√D/(a (t1 − t0)) from the real axis
/// in x, and at any real position x*. For each N the constant below is the
/// smallest y for which that bound, minimised over r (E_r inside the pole's
/// ellipse) and divided by the integral itself, is ≤ 2^−55 (a quarter of
/// double's rounding unit) for every x* in [−6, 6] ∪ {±20, ±100}, every
/// weight t^k, k ≤ 4, and every pole order m/2, m ≤ 18 (the generated
/// kernels' range: k ≤ 4 for weight degree 3 and ∇f, m ≤ i + 2 for i ≤ 16):
/// computed by bench/tools/far_field_bound.cpp (scans ∂E_r at 256 points,
/// r at 40 steps, the integral by 8 panels of the 30-point rule); the
/// minimal y are 41.05 (N = 7), 9.268 (N = 10), 3.357 (N = 15), 2.031
/// (N = 20), rounded up here. The generated far branch starts at D ≥ 2a²,
/// y = 2√2 ≈ 2.83 on [0, 1], inside the 20-node range (the generator
/// checks it against far_field_min_y_20_nodes). D = ac − b² is
/// formed here without the generated code's cross product: its rounding
/// (~ε ac) matters only for a pole more than 100 |AB| along the line, where
/// |z| ≥ 100 puts E_r for any N ≥ 10 far inside the pole's ellipse anyway
/// (|z| ≥ 19.1 suffices for 10 nodes, below).
inline constexpr double far_field_min_y_7_nodes = 41.1;
inline constexpr double far_field_min_y_10_nodes = 9.3;
inline constexpr double far_field_min_y_15_nodes = 3.4;
inline constexpr double far_field_min_y_20_nodes = 2.1;

/// Nodes per panel of segment_moments_gauss_panels: on an accepted panel
/// the rule errs by ~ρ^(−2N) ≤ 4^(−2N) times a factor for the poles' order
/// (up to 6) and the weight t^k (k ≤ 10) growing off the interval;
/// measured: that factor is ~1e9 (ρ = 3.1 left 1e-11 with N = 20), so
/// 4^(−40) ≈ 8e-25 is ~1e-15 in double; N = 25 for long double, 40 for
/// binary128 and wider (4^(−80) ≈ 7e-49).
template <class T>
constexpr unsigned gauss_panel_points() {
  constexpr int digits = std::numeric_limits<T>::digits;
  return digits <= 53 ? 20u : digits <= 64 ? 25u : 40u;
}

namespace detail {
/// The node count for a pole at "distance" x (a squared distance compared
/// with the squared thresholds of the 7-, 10- and 15-node rules): 7, 10, 15,
/// or `most`. More nodes than needed only make the rule more exact.
///
///
template <class T>
int rule_nodes(const T& x, double x7, double x10, double x15, int most) {
  return x >= T(x7) ? 7 : x >= T(x10) ? 10 : x >= T(x15) ? 15 : most;
}

/// add_moments_at_nodes with `nodes` nodes (7, 10, 15, 20) in double; types
/// wider than double keep gauss_panel_points<T>() (the constants are for
/// double's rounding unit).
template <class T, class NodeAt>
void add_moments_with_nodes(int nodes, int m_lo, int m_hi, int k_max, const NodeAt& node_at, T* out) {
  if constexpr (gauss_panel_points<T>() != 20) {
    add_moments_at_nodes<T, gauss_panel_points<T>(), NodeMap::linear>(m_lo, m_hi, k_max, node_at, out);
  } else {
    switch (nodes) {
      case 7: add_moments_at_nodes<T, 7, NodeMap::linear>(m_lo, m_hi, k_max, node_at, out); break;
      case 10: add_moments_at_nodes<T, 10, NodeMap::linear>(m_lo, m_hi, k_max, node_at, out); break;
      case 15: add_moments_at_nodes<T, 15, NodeMap::linear>(m_lo, m_hi, k_max, node_at, out); break;
      default: add_moments_at_nodes<T, 20, NodeMap::linear>(m_lo, m_hi, k_max, node_at, out); break;
    }
  }
}

/// The far-field rule of segment_moments_gauss: N_max nodes, or fewer where
/// the bound above allows it (double only: the constants are for its
/// rounding unit; wider types keep N_max).
template <class T, unsigned N_max, class QuadraticAt>
void add_far_field_moments(int m_lo, int m_hi, int k_max, const QuadraticAt& q_at, const T& a, const T& b,
                           const T& c, const T& t0, const T& t1, T* out) {
  if constexpr (std::numeric_limits<T>::digits <= 53 && N_max == 20) {
    // y² = 4D/(a (t1 − t0))² ≥ y_N²
    const T a_width = a * (t1 - t0);
    const T y2 = T(4) * (a * c - b * b) / (a_width * a_width);
    auto square = [](double y) { return y * y; };
    const int nodes = rule_nodes(y2, square(far_field_min_y_7_nodes), square(far_field_min_y_10_nodes),
                                 square(far_field_min_y_15_nodes), 20);
    add_moments_with_nodes<T>(nodes, m_lo, m_hi, k_max, linear_node_map(q_at, t0, t1), out);
  } else {
    add_segment_moments_gauss<T, N_max>(m_lo, m_hi, k_max, q_at, t0, t1, out);
  }
}
}  // namespace detail

/// P beyond an end of [0, 1] and far from the segment compared with its
/// length (segment_moments_beyond_end, J_downward): the poles z, z̄ at
/// distance |z| from the midpoint in x = 2t − 1, in any direction (on the
/// real axis too). The smallest |z| at which the N-point rule's bound (as
/// above, now over every direction of the pole: bench/tools/
/// far_field_bound.cpp --radius) is ≤ 2^−55: 102.1 (N = 7), 19.09
/// (N = 10), 5.825 (N = 15), 3.29 (N = 20), rounded up here.
/// |z|² = 4 q(½)/a.
inline constexpr double beyond_end_min_z_7_nodes = 102.2;
inline constexpr double beyond_end_min_z_10_nodes = 19.1;
inline constexpr double beyond_end_min_z_15_nodes = 5.9;
inline constexpr double beyond_end_min_z_20_nodes = 3.3;
/// Where the rule is used instead of the recurrence: |z| ≥ 14 (P at least
/// 7 |AB| from the midpoint; 15 nodes up to |z| = 19.1, then 10, then 7),
/// not from 3.3 where the bound first allows it.
/// Between 3.3 and 14 the recurrence's cancellation is below 8e-14 (measured
/// above), and the rule did not do better on f: the verifier's default sweep
/// measured 1.0e-13 for inverse i = 2, weights t³, at |z| ≈ 6.9 (generic
/// region) with the rule, 5.1e-14 with the recurrence, 9.6e-15 with an exact
/// preamble (the error there comes from the rounded q_near, b_near, which
/// both forms inherit). Lower this once the preamble computes them exactly.
inline constexpr double beyond_end_rule_min_z = 14.0;
static_assert(beyond_end_rule_min_z >= beyond_end_min_z_20_nodes, "the rule's bound must hold where it is used");
namespace detail {
/// M_{k,m} on [0, 1] (layout of segment_moments_gauss) for P beyond an end,
/// by the rule with the fewest nodes the bound above allows, when it allows
/// one (|z| ≥ beyond_end_rule_min_z = 14, P at least 7 |AB| from the midpoint); false (out
/// untouched) otherwise. q is formed from the near end, q = q_near + σ(aσ − 2 b_near)
/// with σ the distance in t from that end and b_near < 0 (b beyond A,
/// a − b beyond B): a sum of positive terms.
///
/// Why: beyond an end the downward recurrences are stable, but away from
/// the segment the far end's boundary term (σ = 1) is as large as the near
/// end's and cancels against the k b_near M_{k−1} term: 1.5e-11 measured by
/// the verifier for Cauchy i = 7, weights t³, 30 |AB| beyond B; measured on
/// M_{k,m}, k ≤ 3, m = 7, 9 against long double quadrature: up to 1.1e-10
/// for |z| ≤ 60, and still 8e-14 at |z| ≈ 14, while the recurrence stays at
/// ≤ 5e-15 for |z| < 3.1 and the rule at ≤ 5e-15 beyond. The rule adds
/// positive terms only; it also replaces the recurrence's up to ~110 steps
/// (ρ near 7/10) by 7–20 nodes.
template <class T>
bool beyond_end_moments_gauss(int m_lo, int m_hi, int k_max, const T& a, const T& b_near, const T& q_near,
                              const T& q_far, bool beyond_B, T* out) {
  if constexpr (std::numeric_limits<T>::digits > 53) return false;  // the radii are for double's rounding
  // |z|² = 4 q(½)/a, q(½) = (q(0) + q(1))/2 − a/4
  const T z2 = T(2) * (q_near + q_far) / a - T(1);
  auto square = [](double r) { return r * r; };
  if (!(z2 >= T(square(beyond_end_rule_min_z)))) return false;
  if constexpr (std::is_same_v<T, double>) {
    // The series about the midpoint (far_field_series.hpp) where it applies,
    // from the near end's quantities: Q = q(½) = q_near − b_near + a/4, a sum
    // of positive terms (b_near < 0); P changes sign with the direction of t.
    const double Q = q_near - b_near + 0.25 * a;
    const double P_from_near = 0.5 * (0.5 * a - b_near) / Q;
    if (far_series_moments_about_midpoint(m_lo, m_hi, k_max, Q, beyond_B ? -P_from_near : P_from_near,
                                          0.25 * a / Q, out) != 0)
      return true;
  }
  const int count = ((m_hi - m_lo) / 2 + 1) * (k_max + 1);
  for (int i = 0; i < count; ++i) out[i] = T(0);
  auto q_at = [&](const T& t) {
    const T sigma = beyond_B ? T(1) - t : t;
    return q_near + sigma * (a * sigma - T(2) * b_near);
  };
  const int nodes = rule_nodes(z2, square(beyond_end_min_z_7_nodes), square(beyond_end_min_z_10_nodes),
                               square(beyond_end_min_z_15_nodes), 20);
  add_moments_with_nodes<T>(nodes, m_lo, m_hi, k_max, linear_node_map(q_at, T(0), T(1)), out);
  return true;
}
}  // namespace detail

/// Writes M_{k,m} for k = 0…k_max and m = m_lo, m_lo + 2, …, m_hi to
/// out[((m − m_lo)/2)(k_max + 1) + k] by Gauss–Legendre on [t0, t1]:
///  * m_lo ≤ 0 (compact kernels): the N-point rule, exact for a polynomial
///    integrand (even degrees) and exact to double's rounding for odd
///    degrees where the generator calls it (q's roots at least |AB|/4
///    beyond both ends: 20 nodes, Bernstein ρ ≥ 2.6; or the sine map, 30);
///    types wider than 64 bits take 2N nodes there (N ≥ 20), which their
///    rounding needs (measured: binary128 ∇f 2e-19 with 20 nodes);
///  * m_lo > 0 (inverse and Cauchy kernels in the far field, poles off the
///    interval): at most N nodes, fewer where the poles are far enough for
///    the bound above (detail::add_far_field_moments).
template <class T, unsigned N, NodeMap map = NodeMap::linear>
void segment_moments_gauss(int m_lo, int m_hi, int k_max, const T& a, const T& b, const T& c, const T& t0,
                           const T& t1, T* out) {
  const int count = ((m_hi - m_lo) / 2 + 1) * (k_max + 1);
  for (int i = 0; i < count; ++i) out[i] = T(0);
  auto q_at = [&](const T& t) {
    using std::max;
    return max(T(0), c + t * (a * t - 2 * b));
  };
  if (map == NodeMap::linear && m_lo > 0) {
    detail::add_far_field_moments<T, N>(m_lo, m_hi, k_max, q_at, a, b, c, t0, t1, out);
  } else {
    constexpr unsigned nodes = N >= 20 && std::numeric_limits<T>::digits > 64 ? 2 * N : N;
    add_segment_moments_gauss<T, nodes, decltype(q_at), map>(m_lo, m_hi, k_max, q_at, t0, t1, out);
  }
}

/// M_{k,m} on [0, 1] (layout of segment_moments_gauss, m > 0: inverse and
/// Cauchy kernels, q = α|P − Γ(t)|² + β) far from the segment: in double
/// the series about the midpoint (far_field_series.hpp, remainder bound
/// below 2^−53) where P itself is far enough from the midpoint for it,
/// α|P − M|² = c_minus_beta − b + a/4 ≥ a/(4 ρ²_max) (then ρ² = a/(4 q(½))
/// is smaller still), and where it is the cheaper (far_series_cheaper);
/// else, and in other types, the 20-point far-field rule of
/// segment_moments_gauss. The test is on P's position, not on q(½): a
/// Cauchy kernel wide compared with |AB| (β ≫ α|AB|²) makes ρ small beside
/// the segment too, where the generated ∇f takes the difference
/// Σ w_k (M_{k+1} − t* M_k) of moments, which the rule's moments keep
/// more exact (codegen/segment_program_builder.hpp, push_flat_rule).
template <class T>
void segment_moments_far_field(int m_lo, int m_hi, int k_max, const T& a, const T& b, const T& c,
                               const T& c_minus_beta, T* out) {
  if constexpr (std::is_same_v<T, double>) {
    const double far = c_minus_beta - b + 0.25 * a;  // α|P − M|²
    if (far > 0 && detail::far_series_applies(m_hi, 0.25 * a / far) &&
        detail::segment_moments_far_series(m_lo, m_hi, k_max, a, b, c, out) != 0)
      return;
  }
  segment_moments_gauss<T, 20>(m_lo, m_hi, k_max, a, b, c, T(0), T(1), out);
}

/// M_{k,m} on [t0, t1] (layout of segment_moments_gauss, m ≤ 0: compact
/// kernels) by the N-point rule after the sine map (NodeMap::sine), for an
/// interval that a compact support may clip at an end. Every term is
/// positive, so nothing cancels; the generated compact kernels of odd
/// degree take it where the vertex t* of q lies far outside [0, 1], where
/// the moment relations multiply rounding by ~|t*|/⟨t⟩ per step in k.
template <class T, unsigned N>
void segment_moments_gauss_sine(int m_lo, int m_hi, int k_max, const T& a, const T& b, const T& c, const T& t0,
                                const T& t1, T* out) {
  segment_moments_gauss<T, N, NodeMap::sine>(m_lo, m_hi, k_max, a, b, c, t0, t1, out);
}

namespace detail {
/// segment_moments_gauss_panels with the pole so close to the segment that
/// q underflows there (closer than ~1e-154 |AB|, where the field is far
/// outside the double range anyway): the integral is not resolvable in T.
/// Throws NotConvergedError.
///
template <class T>
void pole_too_close(const T& distance) {
  throw NotConvergedError("Gauss panels: the pole of the kernel is " + std::to_string(static_cast<double>(distance)) +
                          " from the segment (in units of |AB|): q underflows there");
}
}  // namespace detail

/// The SCALIS panels' node counts when the weights go up to t^10
/// (k_max > 4: kernels of degree 6 and above with ∇f), derived as the
/// constants above with weights k ≤ 10 and orders m ≤ 18
/// (bench/tools/far_field_bound.cpp --panels, and --panels --radius):
/// y ≥ 1749 (N = 7), 19.41 (10), 3.836 (15), 2.098 (20); |z| ≥ 6446 (7),
/// 49.39 (10), 7.509 (15), 3.652 (20); rounded up here. With k_max ≤ 4 the
/// classical constants above hold (their weights and orders cover the
/// SCALIS panels' m ≤ 12).
inline constexpr double panel_high_weight_min_y_7_nodes = 1750.0;
inline constexpr double panel_high_weight_min_y_10_nodes = 19.5;
inline constexpr double panel_high_weight_min_y_15_nodes = 3.9;
inline constexpr double panel_high_weight_min_z_7_nodes = 6450.0;
inline constexpr double panel_high_weight_min_z_10_nodes = 49.4;
inline constexpr double panel_high_weight_min_z_15_nodes = 7.6;

/// The SCALIS panels' node counts when the weights go up to t^4 and the
/// orders only up to m = 6 (SCALIS inverse and Cauchy kernels of degree ≤ 4,
/// f and ∇f), derived as the classical constants above with weights
/// k ≤ 4 and orders m ≤ 6 (bench/tools/far_field_bound.cpp --low-order,
/// and --low-order --radius): y ≥ 27.97 (N = 7), 6.626 (10), 2.508 (15),
/// 1.553 (20); |z| ≥ 47.71 (7), 10.06 (10), 3.571 (15), 2.256 (20);
/// rounded up here. A pole of
/// lower order leaves a flatter integrand on the Bernstein ellipses, so the
/// same bound holds with fewer nodes.
inline constexpr double panel_low_order_min_y_7_nodes = 28.0;
inline constexpr double panel_low_order_min_y_10_nodes = 6.7;
inline constexpr double panel_low_order_min_y_15_nodes = 2.6;
inline constexpr double panel_low_order_min_z_7_nodes = 47.8;
inline constexpr double panel_low_order_min_z_10_nodes = 10.1;
inline constexpr double panel_low_order_min_z_15_nodes = 3.6;

namespace detail {
/// The squared thresholds of panel_nodes for one call of
/// segment_moments_gauss_panels: y² (imaginary distance) and |z|²
/// (distance) above which 7, 10 or 15 nodes suffice.
struct PanelNodeThresholds {
  double y7, y10, y15, z7, z10, z15;
};

constexpr double squared(double v) { return v * v; }

/// The thresholds whose derivation covers weights t^k, k ≤ k_max, and pole
/// orders m ≤ m_hi: the high-weight constants (k_max > 4), the low-order
/// ones (m_hi ≤ 6), else the classical far-field and beyond-end constants
/// (k ≤ 4, m ≤ 18).
inline const PanelNodeThresholds& panel_node_thresholds(int k_max, int m_hi) {
  static constexpr PanelNodeThresholds high_weight{
      squared(panel_high_weight_min_y_7_nodes), squared(panel_high_weight_min_y_10_nodes),
      squared(panel_high_weight_min_y_15_nodes), squared(panel_high_weight_min_z_7_nodes),
      squared(panel_high_weight_min_z_10_nodes), squared(panel_high_weight_min_z_15_nodes)};
  static constexpr PanelNodeThresholds low_order{
      squared(panel_low_order_min_y_7_nodes), squared(panel_low_order_min_y_10_nodes),
      squared(panel_low_order_min_y_15_nodes), squared(panel_low_order_min_z_7_nodes),
      squared(panel_low_order_min_z_10_nodes), squared(panel_low_order_min_z_15_nodes)};
  static constexpr PanelNodeThresholds classical{
      squared(far_field_min_y_7_nodes),  squared(far_field_min_y_10_nodes),  squared(far_field_min_y_15_nodes),
      squared(beyond_end_min_z_7_nodes), squared(beyond_end_min_z_10_nodes), squared(beyond_end_min_z_15_nodes)};
  return k_max > 4 ? high_weight : m_hi <= 6 ? low_order : classical;
}

/// The fewest nodes (7, 10, 15, 20) for a Gauss panel whose poles lie at
/// x* ± i y in the panel's own coordinate x ∈ [−1, 1], from x*² and y²: the
/// imaginary-distance bound (valid for |x*| ≤ 6, the positions it was
/// derived for) or the distance bound (any direction), whichever allows
/// fewer. More nodes than needed only make the rule more exact.
///
///
template <class T>
int panel_nodes(const T& x_star2, const T& y2, const PanelNodeThresholds& c) {
  const int by_height = x_star2 <= T(36) ? rule_nodes(y2, c.y7, c.y10, c.y15, 20) : 20;
  const int by_distance = rule_nodes(x_star2 + y2, c.z7, c.z10, c.z15, 20);
  return by_height < by_distance ? by_height : by_distance;
}
}  // namespace detail

/// Writes M_{k,m} = ∫_0^1 t^k q^(−m/2) dt (k = 0…k_max, m = m_lo, …, m_hi,
/// m > 0) to out[((m − m_lo)/2)(k_max + 1) + k] for inverse and Cauchy
/// kernels, by Gauss–Legendre on panels graded towards the roots
/// z = t* ± i√D/a of q (t* = b/a). Inputs: a > 0, b, a − b and D = ac − b²
/// ≥ 0, each formed without cancellation by the caller (a − b = −AB·BP).
///
/// Used where the closed forms cancel for high moments (the SCALIS weights
/// τ(t)^(i−1), k ≤ 10): every node adds positive terms, so nothing cancels,
/// and the panels make the rule exact to rounding by an a-priori bound:
///  * the pivot is the point of [0, 1] nearest to t* (an end, or t*);
///    every node is placed by its offset o = t − pivot, and q = (s² + D)/a
///    with the slope s = a t − b = s_pivot + a o, s_pivot = −b at t = 0,
///    a − b at t = 1 (exact inputs), ≈ 0 at t*: s_pivot and a o have the
///    same sign, so s is a sum of like-signed terms, and the offsets keep
///    their relative precision however small the panels near the pivot
///    get. (Placing nodes by t itself rounds each to ~ε absolute: next to
///    an end, a panel of width δ then integrates a kernel of width δ at
///    nodes displaced by ε/δ of it, 2e-13 for a SCALIS segment of radius
///    1e-3 |AB| seen from just beyond its end.)
///  * the integrand's only singularities are the poles z, z̄ of order m/2;
///    the distance from z to a real t is δ(t) = √(q(t)/a);
///  * a panel [x, y] is accepted when z lies outside its Bernstein ellipse
///    of parameter 4, i.e. s = (δ(x) + δ(y))/|y − x| ≥ (4 + 1/4)/2 = 17/8
///    (Trefethen, Approximation Theory and Approximation Practice, ch. 19);
///  * [0, 1] is one panel when accepted; otherwise panels start at the pivot
///    and go outwards; each takes the rest of its side if that is accepted,
///    else the length 0.9 δ(x) (accepted: δ grows away from t*, so
///    s ≥ 2δ(x)/0.9δ(x));
///  * δ grows by a factor ≥ 1.3 a panel, so a pole at distance ε from the
///    segment costs ~log(1/ε)/log 1.3 panels per side (in practice δ nearly
///    doubles); one or two panels when P is at least |AB|/2 from the line;
///  * an accepted panel takes gauss_panel_points<T>() nodes (20 in
///    double), or in double fewer (15, 10, 7) where the poles lie far
///    enough from that panel for the bound of the far-field rule
///    (detail::panel_nodes): the panels far from the pole, and every
///    panel when P is far from the segment.
/// If P is on the segment (D = 0, t* in [0, 1]) the integral diverges: +∞.
/// If q underflows at the pivot (the pole closer than ~1e-154 |AB|, P on
/// the line beyond an end), NotConvergedError (detail::pole_too_close).
template <class T>
void segment_moments_gauss_panels(int m_lo, int m_hi, int k_max, const T& a, const T& b, const T& a_minus_b,
                                  const T& D, T* out) {
  using std::abs;
  using std::sqrt;
  const int count = ((m_hi - m_lo) / 2 + 1) * (k_max + 1);
  for (int i = 0; i < count; ++i) out[i] = T(0);
  const T zero(0), one(1);
  const T t_star = b / a;
  const bool before_A = t_star <= zero, beyond_B = t_star >= one;
  const T pivot = before_A ? zero : beyond_B ? one : t_star;
  const T slope_pivot = before_A ? -b : beyond_B ? a_minus_b : a * t_star - b;
  // q and δ at the offset o = t − pivot.
  auto q_at = [&](const T& o) {
    const T s = slope_pivot + a * o;
    return (s * s + D) / a;
  };
  auto delta = [&](const T& o) { return sqrt(q_at(o) / a); };
  // The rule on the panel of offsets [lo, hi], with as few nodes as the
  // poles' position relative to the panel allows (detail::panel_nodes).
  const T pole_offset = t_star - pivot;
  const T pole_height2 = D / (a * a);
  const detail::PanelNodeThresholds& thresholds = detail::panel_node_thresholds(k_max, m_hi);
  auto add_panel = [&](const T& lo, const T& hi) {
    const T half_width = (hi - lo) / 2;
    const T middle = (lo + hi) / 2;
    auto node_at = [&](const T& x) {
      const T o = middle + half_width * x;
      return MomentNode<T>{pivot + o, q_at(o), half_width};
    };
    const T width2 = half_width * half_width;
    const T pole_along = pole_offset - middle;
    const int nodes = detail::panel_nodes<T>(pole_along * pole_along / width2, pole_height2 / width2, thresholds);
    detail::add_moments_with_nodes<T>(nodes, m_lo, m_hi, k_max, node_at, out);
  };
  const T offset_A = -pivot, offset_B = one - pivot;  // exact for pivot ≥ 1/2 (Sterbenz), else to ε
  const T s_min = T(17) / T(8);
  // Far from the segment one panel on [0, 1] is accepted: then it is used
  // instead of two that meet at the pivot (half the cost).
  if (!before_A && !beyond_B && delta(offset_A) + delta(offset_B) >= s_min) {
    add_panel(offset_A, offset_B);
    return;
  }
  if (D == zero && !before_A && !beyond_B) {  // P on the segment: the kernel's pole is on the path
    for (int i = 0; i < count; ++i) out[i] = std::numeric_limits<T>::infinity();
    return;
  }
  const T delta_pivot = delta(zero);
  if (!(q_at(zero) >= T(std::numeric_limits<double>::min()))) {
    detail::pole_too_close(delta_pivot);
    return;
  }
  for (int side = 0; side <= 1; ++side) {
    if ((side == 0 && before_A) || (side == 1 && beyond_B)) continue;  // the pivot is that end
    const T end = side == 0 ? offset_A : offset_B;
    const T delta_end = delta(end);
    T x = zero;
    T delta_x = delta_pivot;
    while (x != end) {
      T y = end;
      if (delta_x + delta_end < s_min * abs(end - x)) {
        const T step = T(9) / T(10) * delta_x;
        y = side == 1 ? (x + step < end ? x + step : end) : (x - step > end ? x - step : end);
      }
      if (x < y)
        add_panel(x, y);
      else
        add_panel(y, x);
      x = y;
      if (x != end) delta_x = delta(x);  // for the next panel (none after the end)
    }
  }
}

}  // namespace skelconv
