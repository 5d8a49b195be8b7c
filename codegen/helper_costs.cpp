// codegen/helper_costs.cpp — see helper_costs.hpp. Each function runs the
// helper once on CountingDouble and returns the tally; the inputs are the
// worst case the generated branch that calls the helper allows.
#include "helper_costs.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <skelconv/detail/exact_cross.hpp>
#include <skelconv/detail/gauss_moments.hpp>
#include <skelconv/detail/polygon_angle_integrals.hpp>
#include <skelconv/detail/stable_recurrence.hpp>
#include <skelconv/detail/support_gap.hpp>
#include <skelconv/detail/scalis_compact_support.hpp>

#include "tools/counting_scalar.hpp"  // the same counting scalar the benchmarks use

namespace skelconv::codegen::helper_costs {
namespace {

using Counted = bench::CountingDouble;

/// Runs `call` on a fresh tally and returns it as an OpCount.
template <class Call>
OpCount tally_of(const Call& call) {
  bench::operation_tally() = bench::OperationTally{};
  call();
  const bench::OperationTally t = bench::operation_tally();
  OpCount out;
  out.add = int(t.add);
  out.mul = int(t.mul);
  out.div = int(t.div);
  out.sqrt = int(t.sqrt);
  out.atan = int(t.atan);
  out.log = int(t.log);
  out.other = int(t.other);
  return out;
}

/// Output array of a helper that fills levels m_lo…m_hi (step 2) × k_max + 1.
std::vector<Counted> moment_array(int m_lo, int m_hi, int k_max) {
  return std::vector<Counted>(static_cast<std::size_t>(((m_hi - m_lo) / 2 + 1) * (k_max + 1)));
}

template <unsigned N>
OpCount gauss_rule_with(int m_lo, int m_hi, int k_max) {
  std::vector<Counted> out = moment_array(m_lo, m_hi, k_max);
  // Any q > 0 on [0, 1]: the rule's cost does not depend on the values.
  return tally_of([&] {
    segment_moments_gauss<Counted, N>(m_lo, m_hi, k_max, Counted(1), Counted(0.25), Counted(2), Counted(0), Counted(1),
                                      out.data());
  });
}

template <unsigned N>
OpCount gauss_sine_rule_with(int m_lo, int m_hi, int k_max) {
  std::vector<Counted> out = moment_array(m_lo, m_hi, k_max);
  auto call = [&] {
    segment_moments_gauss_sine<Counted, N>(m_lo, m_hi, k_max, Counted(-1), Counted(-2), Counted(-2), Counted(0),
                                           Counted(1), out.data());
  };
  call();  // the mapped table is computed once, on the first call: not counted
  return tally_of(call);
}

template <unsigned N, NodeMap map>
OpCount between_roots_with(int m_lo, int m_hi, int k_max) {
  std::vector<Counted> out = moment_array(m_lo, m_hi, k_max);
  auto call = [&] {
    segment_moments_between_roots<Counted, N, map>(m_lo, m_hi, k_max, Counted(1), Counted(0.5), Counted(0.25),
                                                   Counted(0), Counted(0.5), out.data());
  };
  call();  // a mapped table is computed once, on the first call: not counted
  return tally_of(call);
}

}  // namespace

OpCount between_roots(int nodes, bool sine, int m_lo, int m_hi, int k_max) {
  if (sine) {
    if (nodes != 30) throw std::logic_error("helper_costs::between_roots: only the 30-node sine rule is generated");
    return between_roots_with<30, NodeMap::sine>(m_lo, m_hi, k_max);
  }
  switch (nodes) {
    case 7: return between_roots_with<7, NodeMap::linear>(m_lo, m_hi, k_max);
    case 10: return between_roots_with<10, NodeMap::linear>(m_lo, m_hi, k_max);
    case 15: return between_roots_with<15, NodeMap::linear>(m_lo, m_hi, k_max);
    case 20: return between_roots_with<20, NodeMap::linear>(m_lo, m_hi, k_max);
    default:
      throw std::logic_error("helper_costs::between_roots: no generated rule with " + std::to_string(nodes) + " nodes");
  }
}

OpCount point_support_gap() {
  Counted gap[1];
  return tally_of([&] {
    exact_point_support_gap<Counted>(Counted(1.1), Counted(0.7), Counted(0.4), Counted(0.6), Counted(0.45),
                                     Counted(0.35), Counted(0.8), gap);
  });
}

OpCount line_support_gap() {
  Counted gap[1];
  return tally_of([&] {
    exact_line_support_gap<Counted>(Counted(0.1), Counted(0.2), Counted(0.3), Counted(1.1), Counted(0.7), Counted(0.4),
                                    Counted(0.6), Counted(0.45), Counted(0.35), Counted(0.8), gap);
  });
}

OpCount gauss_sine_rule(int nodes, int m_lo, int m_hi, int k_max) {
  if (nodes != 30) throw std::logic_error("helper_costs::gauss_sine_rule: only the 30-node rule is generated");
  return gauss_sine_rule_with<30>(m_lo, m_hi, k_max);
}

OpCount gauss_rule(int nodes, int m_lo, int m_hi, int k_max) {
  switch (nodes) {
    case 7: return gauss_rule_with<7>(m_lo, m_hi, k_max);
    case 10: return gauss_rule_with<10>(m_lo, m_hi, k_max);
    case 15: return gauss_rule_with<15>(m_lo, m_hi, k_max);
    case 20: return gauss_rule_with<20>(m_lo, m_hi, k_max);
    case 25: return gauss_rule_with<25>(m_lo, m_hi, k_max);
    case 30: return gauss_rule_with<30>(m_lo, m_hi, k_max);
    default: throw std::logic_error("helper_costs::gauss_rule: no tabulated rule with " + std::to_string(nodes) + " nodes");
  }
}

OpCount gauss_panels(int m_lo, int m_hi, int k_max) {
  // The panels grade towards the pole at distance δ from the segment's end
  // (in units of |AB|); their number grows like log(1/δ). The deepest δ a
  // double evaluation resolves: q^(−m_hi/2) = δ^(−m_hi) must not overflow
  // (the panels place their nodes by offsets from the end, so rounding of t
  // sets no bound). P on the line beyond B (D = 0), a − b = −δ.
  std::vector<Counted> out = moment_array(m_lo, m_hi, k_max);
  const double delta = std::pow(10.0, -300.0 / m_hi);
  return tally_of([&] {
    segment_moments_gauss_panels<Counted>(m_lo, m_hi, k_max, Counted(1), Counted(1 + delta), Counted(-delta), Counted(0),
                                          out.data());
  });
}

OpCount moments_beyond_end(int m_lo, int m_hi, int k_max) {
  // Beyond B (the t-moments are then recovered by a binomial sum: the costlier
  // end), ρ = D/(a q(1)) = 7/10, the generated code's largest: a = 1,
  // b = 3/2, c = 17/6 give q(1) = 5/6, D = 7/12.
  std::vector<Counted> out = moment_array(m_lo, m_hi, k_max);
  const double a = 1, b = 1.5, c = 17.0 / 6.0;
  return tally_of([&] {
    segment_moments_beyond_end<Counted>(m_lo, m_hi, k_max, Counted(a), Counted(b), Counted(a - b), Counted(a * c - b * b), Counted(c),
                                        Counted(a - 2 * b + c), out.data());
  });
}

OpCount expression_helper(const std::string& function, int n) {
  if (function == "J_downward") {
    // Beyond A with ρ = D/(a q(0)) = 7/10: a = 1, b = −1/2, c = b²/(a·3/10).
    const double a = 1, b = -0.5, c = b * b / (a * 0.3);
    const double D = a * c - b * b;
    return tally_of([&] {
      (void)J_downward<Counted>(n, Counted(a), Counted(D), Counted(-b), Counted(c), Counted(a - b), Counted(a - 2 * b + c));
    });
  }
  if (function == "J_upward_compact") {
    // Compact (a < 0, D < 0), per-step factor a q_e / D = 17/20.
    const double a = -1, D = -1, q_e = 0.85, q_small = 0.5;
    return tally_of([&] {
      (void)J_upward_compact<Counted>(n, Counted(a), Counted(D), Counted(0.3), Counted(q_e), Counted(0.8),
                                      Counted(q_small));
    });
  }
  throw std::logic_error("helper_costs::expression_helper: no cost for helper " + function);
}

OpCount polygon_H_near_plane(int n_lo, int n_hi) {
  std::vector<Counted> out(static_cast<std::size_t>((n_hi - n_lo) / 2 + 1));
  return tally_of([&] {
    polygon_edge_H_near_plane<Counted>(n_lo, n_hi, Counted(1), Counted(1), Counted(0.1), Counted(-1), Counted(1),
                                       out.data());
  });
}

OpCount polygon_G_compact_chord(int p_lo, int p_hi) {
  // The generated code calls it for a chord at d ≥ √w R / 2 from P̄
  // (kChordRimRatio), so |u| ≤ √3: the full range, d²/R² = w/4, takes the
  // most panels (two a side).
  std::vector<Counted> out(static_cast<std::size_t>(p_hi - p_lo + 1));
  const double root3 = std::sqrt(3.0);
  return tally_of([&] {
    polygon_edge_G_compact_chord<Counted>(p_lo, p_hi, Counted(1), Counted(1), Counted(1), Counted(0.25), Counted(-root3),
                                          Counted(root3), Counted(0.25), Counted(0.75), Counted(0), Counted(0),
                                          out.data());
  });
}

OpCount exact_cross() {
  Counted cross[3];
  return tally_of([&] {
    segment_exact_cross<Counted>(Counted(0.1), Counted(0.2), Counted(0.3), Counted(1.1), Counted(0.7), Counted(0.4),
                                 Counted(0.6), Counted(0.45), Counted(0.35), cross);
  });
}

namespace {
// A = 0, B = (1, 0, 0), τ 0.5 → 0.6, σ = 2, P = (0.4, 0.3, 0.1): Q(0) and
// Q(1) > 0, so the support is the whole segment.
ScalisSegmentInput<Counted> scalis_compact_sample() {
  ScalisSegmentInput<Counted> in;
  in.a = {Counted(0), Counted(0), Counted(0)};
  in.b = {Counted(1), Counted(0), Counted(0)};
  in.p = {Counted(0.4), Counted(0.3), Counted(0.1)};
  in.tau0 = Counted(0.5);
  in.tau1 = Counted(0.6);
  in.sigma = Counted(2);
  return in;
}
}  // namespace

OpCount scalis_compact_segment_preparation(int degree) {
  const ScalisSegmentInput<Counted> in = scalis_compact_sample();
  return tally_of([&] { (void)detail::prepare_segment(degree, in); });
}

OpCount scalis_compact_around_closed_form(int degree, bool with_grad) {
  const ScalisSegmentInput<Counted> in = scalis_compact_sample();
  const detail::CompactSegment<Counted> segment = detail::prepare_segment(degree, in);
  return tally_of([&] {
    using namespace detail;
    const Prepared<Counted> pr = prepare(segment, in.p);
    if (pr.done || pr.support.root_at_t1 >= 0 || pr.support.root_at_t2 >= 0)
      throw std::logic_error("scalis_compact_around_closed_form: the sample point is not generic");
    (void)closed_form_input(pr);
    std::array<Counted, 3> grad;
    (void)finish(pr, Sums<Counted>{Counted(1), Counted(1), Counted(1)}, with_grad ? &grad : nullptr);
  });
}

}  // namespace skelconv::codegen::helper_costs
