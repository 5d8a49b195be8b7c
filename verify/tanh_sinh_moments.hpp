// verify/tanh_sinh_moments.hpp — several integrals over one interval on shared
// tanh-sinh nodes, in binary128: the quadrature rule of the segment and SCALIS
// references (reference_quadrature.hpp, scalis_reference.hpp).
//
// A reference needs M integrals ∫_0^X g_m(x) dx over one piece whose
// integrands share their expensive part (the kernel at the node; g_m are its
// moments u^j K, u^j K'/r). The double-exponential rule of Takahasi and Mori
// substitutes
//
//     x = X/2 (1 + tanh(π/2 sinh t)),   t ∈ (−∞, ∞),
//
// and applies the trapezoidal rule in t with step h; each level halves h and
// adds the odd multiples of the new step. All M integrals are summed in one
// pass over the nodes: the integrand is evaluated once per node (before, one
// Boost tanh_sinh call per moment replayed the kernel values, and its
// per-node bookkeeping, nine times over, was half of the sweep's time).
//
// Nodes for X = 1, with E = exp(−π sinh|t|) (no cancellation near the ends,
// where the references put their peaks):
//     distance to the nearer end   δ(t) = E / (1 + E)       (x = δ for t < 0, 1 − δ for t > 0)
//     weight                       dx/dt = π cosh t · E / (1 + E)²
// The sum is cut at |t| = t_max = 5, where δ ≈ 1e-101 and the weight ≈ 1e-99:
// an integrand bounded on the piece (the references map their peaks and
// poles to O(1)-wide bumps first) loses nothing there, and an end singularity
// x^(−a) loses δ^(1−a), below 1e-30 for a ≤ 0.7.
//
// Error estimate, per integral, as Boost's tanh_sinh: the difference of the
// last two levels. It is pessimistic (the error of a double-exponential rule
// falls roughly quadratically per level, so the last level is far better than
// the difference says). The rule stops at the first level ≥ min_level at
// which every integral's estimate is ≤ tolerance · its L1 norm ∫|g_m|, or at
// max_levels; an integral whose estimate grows twice after level 4 keeps its
// value and estimate from the level before and no longer holds the others
// back (Boost's "thrash" guard). The caller judges the estimates.
#pragma once

#include <array>
#include <cstddef>
#include <stdexcept>
#include <utility>
#include <vector>

#include <boost/math/constants/constants.hpp>

#include "extended_precision.hpp"

namespace skelconv::verify {

/// M integrals over one piece, with their error estimates.
template <std::size_t M>
struct SharedIntegrals {
  std::array<extended, M> value{};
  std::array<extended, M> error{};  ///< |last level − the one before| (0 for an integrand that is 0 everywhere)
  std::size_t levels = 0;           ///< levels summed (the first is level 0)
  std::size_t evaluations = 0;      ///< integrand evaluations
};

/// The tanh-sinh rule on [0, X] for several integrands at once. Keeps the
/// node tables it has built (grown on demand, level by level): one per thread.
class TanhSinhMoments {
 public:
  /// Levels: level 0 has step 1/2; `max_levels` refinements at most (each
  /// halves the step), never fewer than `min_levels` before the tolerance is
  /// tested (a narrow feature the coarse levels miss would otherwise pass as
  /// converged: Boost's tanh_sinh also sums four levels before testing).
  explicit TanhSinhMoments(std::size_t max_levels, std::size_t min_levels = 3)
      : max_levels_(max_levels), min_levels_(min_levels) {}

  /// ∫_0^X g(x) dx for the M components of g. `integrand(x)` returns the M
  /// values (Jacobians of the caller's own substitutions included) as
  /// std::array<extended, M>. `tolerance`: relative to each integral's L1 norm.
  template <std::size_t M, class Integrand>
  SharedIntegrals<M> integrate(const Integrand& integrand, const extended& x_end, const extended& tolerance) {
    SharedIntegrals<M> out;
    std::array<extended, M> l1{};
    std::array<extended, M> sum{};  // Σ weight · g over every node so far; the integral is h · sum
    std::array<unsigned, M> thrashes{};
    std::array<bool, M> frozen{};
    extended h(initial_step);
    for (std::size_t level = 0; level <= max_levels_; ++level) {
      for (const Node& node : row(level)) {
        const extended weight = x_end * node.weight;
        const extended offset = x_end * node.delta;
        // x = δX and X − δX; a node that rounds onto its end is left out, as
        // Boost's tanh_sinh does (an integrand singular there, e.g. K'/r of
        // k_R^1 at the support boundary, must not be evaluated at the end).
        const extended right_x = x_end - offset;
        if (offset > 0) add(integrand(offset), weight, sum, l1, out.evaluations);
        if (node.mirrored && right_x < x_end) add(integrand(right_x), weight, sum, l1, out.evaluations);
      }
      if (level > 0) h /= 2;
      bool converged = level >= min_levels_;
      for (std::size_t m = 0; m < M; ++m) {
        if (frozen[m]) continue;
        const extended value = h * sum[m];
        if (!isfinite(value)) throw std::domain_error("tanh-sinh: the integrand is not finite at a node");
        const extended error = abs(value - out.value[m]);
        // Boost's guard: once past level 4, an estimate that grows for the
        // second time means the levels no longer converge (an integrand cut
        // off by the nodes left out at an end): keep the level before.
        if (level > 4 && error > out.error[m] && ++thrashes[m] > 1) {
          frozen[m] = true;
          continue;
        }
        out.value[m] = value;
        out.error[m] = error;
        converged = converged && error <= tolerance * h * l1[m];
      }
      out.levels = level + 1;
      if (converged) break;
    }
    return out;
  }

 private:
  /// One abscissa pair ±t of a level, for X = 1.
  struct Node {
    extended delta;   ///< distance of both nodes to their nearer end
    extended weight;  ///< dx/dt at ±t
    bool mirrored;    ///< two nodes (t ≠ 0): x = δ and x = 1 − δ; t = 0 is one node, x = δ = 1/2
  };

  static constexpr double initial_step = 0.5;  // level 0: t = 0, ±1/2, ..., ±t_max
  static constexpr double t_max = 5;           // see the top of this file

  template <std::size_t M>
  static void add(const std::array<extended, M>& g, const extended& weight, std::array<extended, M>& sum,
                  std::array<extended, M>& l1, std::size_t& evaluations) {
    for (std::size_t m = 0; m < M; ++m) {
      const extended term = weight * g[m];  // weight > 0: |term| = weight |g|
      sum[m] += term;
      l1[m] += abs(term);
    }
    ++evaluations;
  }

  static Node node_at(const extended& t) {
    using std::cosh, std::exp, std::sinh;
    const extended pi = boost::math::constants::pi<extended>();
    const extended e = exp(-pi * sinh(abs(t)));
    const extended one_plus_e = 1 + e;
    return {e / one_plus_e, pi * cosh(t) * e / (one_plus_e * one_plus_e), t != 0};
  }

  /// The nodes level `level` adds: every multiple of 1/2 in [0, t_max] for
  /// level 0, the odd multiples of 2^−(level+1) below t_max after that.
  const std::vector<Node>& row(std::size_t level) {
    while (rows_.size() <= level) {
      const std::size_t k = rows_.size();
      std::vector<Node> nodes;
      if (k == 0) {
        for (int j = 0; j * initial_step <= t_max; ++j) nodes.push_back(node_at(extended(j * initial_step)));
      } else {
        const extended step = extended(initial_step) / extended(1ull << k);  // exact: a power of two
        for (std::size_t j = 1; extended(j) * step < t_max; j += 2) nodes.push_back(node_at(extended(j) * step));
      }
      rows_.push_back(std::move(nodes));
    }
    return rows_[level];
  }

  std::size_t max_levels_;
  std::size_t min_levels_;
  std::vector<std::vector<Node>> rows_;
};

}  // namespace skelconv::verify
