// codegen/segment_program_builder.hpp — builds the straight-line program of
// one segment kernel (segment_families.hpp). Shared with the polygon edge
// kernels (polygon_families.hpp): a polygon edge is a segment whose quadratic
// has the constant term β + α z² (Hubert 2012 §5), so it reuses the
// geometry, the quadratic and the run-time choice of stable forms here.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "generated_families.hpp"
#include "helper_costs.hpp"
#include "segment_families.hpp"
#include "segment_moments.hpp"
#include "skelconv/detail/far_field_series.hpp"
#include "skelconv/detail/gauss_moments.hpp"

namespace skelconv::codegen {

using GiNaC::ex;
using GiNaC::numeric;
using GiNaC::pow;
using GiNaC::symbol;

/// The κ of the series' condition c − β − b − κ a ≥ 0 for highest pole order
/// m: α|P − M|² ≥ a/(4 ρ²_max), with ρ²_max the largest ρ² at which
/// the far-field series serves order m (far_series_applies), κ rounded up to
/// a sixteenth so that the series applies throughout the branch.
inline ex far_series_flat_kappa(int m) {
  const double rho2_max = std::min(detail::far_series_max_rho2,
                                   detail::far_series_max_rho_m * detail::far_series_max_rho_m / (double(m) * m));
  const double kappa = 1 / (4 * rho2_max) - 0.25;
  return numeric(static_cast<long>(std::ceil(16 * kappa)), 16);
}

inline std::string to_string(const ex& e) {
  std::ostringstream os;
  os << e;
  return os.str();
}

// max(0, x), written as such in C++: q at a clipped end is 0 up to rounding
// and must not go negative under a square root.
DECLARE_FUNCTION_1P(nonnegative_part)
// min(x, y) and max(x, y), written as such in C++.
DECLARE_FUNCTION_2P(minimum)
DECLARE_FUNCTION_2P(maximum)

/// One quantity a kernel reads: Σ_k w_k M_{k+shift,level}, named `name`;
/// or, for `along_line`, Σ_k w_k (M_{k+1,level} − t* M_{k,level}) with
/// t* = b/a (SegmentProgramBuilder::along_line_moment says how).
struct MomentRequest {
  std::string name;
  int shift;
  int level;
  bool along_line = false;
};

// Beyond an end of the segment, with ρ = D / (a q_near) the per-step factor
// of segment_moments.hpp: below kBeyondEndRho the recurrence runs downwards
// (at most ~116 steps reach 1e-18), above it upwards from J_1, J_2, where the
// growth (1/ρ)^((n−1)/2) stays below 21 for n ≤ 18, and the moment formulas
// lose at most a factor ~n·√(1−ρ) each.
inline const ex kBeyondEndRho = numeric(7, 10);
// Compact kernels: J_upward_compact below this q_e/q_max, downwards from
// J_0, J_1 above it, where (q_max/q_e)^((i+d+2)/2) ≤ 1.18^10 ≈ 5.
inline const ex kCompactOutsideRatio = numeric(17, 20);

// What one helper call costs, given the levels m_lo…m_hi and k_max of the
// array it fills (helper_costs.hpp: measured on the helper itself).
using HelperCost = std::function<OpCount(int m_lo, int m_hi, int k_max)>;

// Builds the program step by step; one instance per generated function.
class SegmentProgramBuilder {
 public:
  explicit SegmentProgramBuilder(const SegmentKernelSpec& spec) : spec_(spec) {}

  virtual ~SegmentProgramBuilder() = default;

  StraightLineProgram build(SegmentOutputs outputs) {
    const bool value = outputs != SegmentOutputs::gradient;
    const bool gradient = outputs != SegmentOutputs::value;
    gradient_needs_foot_ = gradient;
    read_inputs();
    define_geometry();
    define_quadratic();
    const int n = kernel_index();
    // What the outputs need: F = Σ w_k M_{k,n} for f = |AB| F, and
    // G_ap = Σ w_k M_{k,n+2}, G_ab = Σ w_k M_{k+1,n+2} for
    // ∇f = −n α |AB| (AP G_ap − AB G_ab) (docs/mathematics.md §2).
    //
    // Written as ∇f = −n α |AB| (H G_ap − AB G_E) with H = AP − t* AB (the
    // foot of P on the line: exact from AB × AP near the line, define_foot)
    // and G_E = G_ab − t* G_ap = Σ w_k (M_{k+1,n+2} − t* M_{k,n+2}), the two
    // parts of ∇f across and along the line. Near the line, AP G_ap and
    // AB G_ab are both ~|AB|/h times |∇f| (h the distance from the line) and
    // their difference loses that factor; G_E by parts
    // (along_line_moment) does not.
    std::vector<MomentRequest> requests;
    if (value) requests.push_back({"F", 0, n});
    if (gradient) {
      requests.push_back({"G_ap", 0, n + 2});
      requests.push_back({"G_E", 1, n + 2, true});
    }
    const std::vector<symbol> targets = choose_moments(requests);
    add_outputs(targets, value, gradient);
    return std::move(program_);
  }

 protected:
  // The run-time choice of stable forms (docs/mathematics.md §2) for the weighted moments
  // Σ_k w_k M_{k+shift,level} of `requests`: one target symbol each. The
  // alternatives are tried in the order pushed, the last is the generic one;
  // the steps below push them in the order of the generated code (GiNaC
  // numbers symbols in creation order, so the order is part of the output).
  std::vector<symbol> choose_moments(const std::vector<MomentRequest>& requests) {
    requests_ = requests;
    std::vector<symbol> targets;
    for (const MomentRequest& r : requests) targets.emplace_back(r.name);
    Choice choice{targets, {}};
    if (generated_family(spec_.family).compact_support) {
      push_compact_alternatives(choice);
    } else {
      push_infinite_support_alternatives(choice);
    }
    choose(std::move(choice));
    return targets;
  }

  // The requested weighted moments (requests_) from `moments`.
  std::vector<ex> moment_values(MomentRecurrence& moments) {
    std::vector<ex> v;
    for (const MomentRequest& r : requests_)
      v.push_back(r.along_line ? along_line_moment(moments, r.level) : weighted_moment(moments, r.shift, r.level));
    return v;
  }

  // Compact kernels: the support-root forms, then an exact Gauss rule (even
  // degree, alone), or the rules and recurrences of odd degrees.
  void push_compact_alternatives(Choice& choice) {
    const MomentSymbols symbols = symbols_ = compact_symbols();
    rule_c_ = support_root_forms_ ? define_rule_constant() : c_;
    if (support_root_forms_) push_support_root_alternatives(choice);
    if (spec_.degree % 2 == 0) {
      push_exact_rule(choice, symbols);
      return;
    }
    push_odd_degree_rules(choice, symbols);
    push_compact_recurrences(choice, symbols);
  }

  void push_exact_rule(Choice& choice, const MomentSymbols& symbols) {
    // t^k q^(i/2) is a polynomial of degree ≤ i + k: an N-point
    // Gauss–Legendre rule with 2N − 1 ≥ i + k is exact and, all terms
    // positive, stable.
    const int polynomial_degree = spec_.degree + highest_moment();
    const int nodes = exact_rule_nodes(polynomial_degree);
    const std::string rule = "segment_moments_gauss<T, " + std::to_string(nodes) + ">";
    push_helper_alternatives(choice, {}, "even degree: the integrand is a polynomial of degree " +
                                 std::to_string(polynomial_degree) + ", integrated exactly by " + rule,
                             "M_exact", rule, {a_, b_, rule_c_, symbols.lo.t, symbols.hi.t}, gauss_rule_cost(nodes));
    choice.generic = choice.alternatives.size() - 1;
  }

  // The constant term of q that the Gauss rules of compact kernels read:
  // c = q(0) = (R² − |AP|²)/R². As 1 − |AP|²/R² it is a difference of
  // rounded numbers, off by ~ε|AP|²/R², i.e. ~ε(1 − c)/c relative, which
  // the rule's q^(i/2) carries i/2 times. Where P is far from the segment
  // compared with |AB|, q ≈ c all along it and that is f's error (measured:
  // 1.4e-14 in f, compact i14, the verifier's far region, c ≈ 0.21). So
  // wherever A and B are inside the ball (no clip) and c ≤ 1/2, where the
  // loss (1 − c)/c exceeds one rounding, c is R² − |AP|² rounded once from
  // the exact inputs (support_gap.hpp), over R². Near the segment the rest
  // of q, −2bt + at², is as large as c and rounds like it: the exact c
  // gains less there. The tests compare with constants (no operation on
  // the generic path).
  //
  // G_E by parts (push_helper_alternatives) adds the rule's moments to
  // boundary terms in q(t0), q(t1), which nearly cancel near the line
  // beside the segment: they must be values of the quadratic the rule
  // integrates, or the two c's rounding differences come back divided by
  // a (measured: ∇f 9e-14 → 2.6e-13, compact i5 w2, near the line). So q
  // and √q at the ends are chosen with c (rule_ends_); with no clip t0 = 0
  // and t1 = 1.
  ex define_rule_constant() {
    const bool odd = spec_.degree % 2 != 0;
    const symbol rule_c("rule_c"), q_lo("rule_q0"), q_hi("rule_q1"), root_lo("rule_r0"), root_hi("rule_r1");
    std::vector<symbol> targets{rule_c, q_lo, q_hi};
    if (odd) targets.insert(targets.end(), {root_lo, root_hi});
    Choice choice{targets, {}};
    Alternative exact{{-symbols_.lo.t, symbols_.hi.t - 1, numeric(1, 2) - c_},
                      "A and B inside the ball, c ≤ 1/2: c = (R² − |AP|²)/R², R² − |AP|² rounded once "
                      "(support_gap.hpp), and q(0) = c, q(1) = c + a − 2b",
                      {}, {}, {}};
    ArrayCall gap = end_gap_call(false);
    const ex c_exact = end_q(gap);
    const ex q1 = nonnegative_part(c_exact + a_ - 2 * b_);
    exact.values = {c_exact, c_exact, q1};
    if (odd) exact.values.insert(exact.values.end(), {pow(c_exact, numeric(1, 2)), pow(q1, numeric(1, 2))});
    exact.calls.push_back(std::move(gap));
    Alternative plain{{}, "c = 1 − |AP|²/R²", {}, {c_, symbols_.lo.q, symbols_.hi.q}, {}};
    if (odd) plain.values.insert(plain.values.end(), {symbols_.lo.root, symbols_.hi.root});
    choice.alternatives.push_back(std::move(exact));
    choice.alternatives.push_back(std::move(plain));
    choice.generic = 1;
    program_.choose(std::move(choice));
    const QuadraticEnd lo{symbols_.lo.t, q_lo, odd ? ex(root_lo) : symbols_.lo.root, symbols_.lo.slope};
    const QuadraticEnd hi{symbols_.hi.t, q_hi, odd ? ex(root_hi) : symbols_.hi.root, symbols_.hi.slope};
    rule_ends_ = PartsEnds{lo, hi};
    return rule_c;
  }

  void push_odd_degree_rules(Choice& choice, const MomentSymbols& symbols) {
    // Odd degree, the sphere crossings t* ± √(−D)/|a| at least |AB|/4
    // beyond both ends (so [t0, t1] = [0, 1]): q^(i/2) is analytic on a
    // Bernstein ellipse of ρ ≥ 2.6 around the segment (2.6^−40 ≈ 2e-17),
    // where the moment relations cancel or, near the line over the
    // segment, carry rounding up through the weight's moments (measured
    // with |AB|/2: ∇f 1.6e-12 per component, compact i13 w3, P 5e-6 |AB|
    // from the line, the roots 0.32 |AB| beyond A); the 20-point
    // Gauss–Legendre rule is exact to rounding
    // (include/skelconv/detail/gauss_moments.hpp).
    const ex t_star = b_ / a_;
    const ex reach = maximum(t_star + numeric(1, 4), numeric(5, 4) - t_star);
    push_helper_alternatives(choice, {-D_ - pow(a_, 2) * pow(reach, 2)},
                             "support sphere at least |AB|/4 beyond both ends: every moment by "
                             "segment_moments_gauss<T, 20>",
                             "M_flat", "segment_moments_gauss<T, 20>", {a_, b_, rule_c_, symbols.lo.t, symbols.hi.t},
                             gauss_rule_cost(20));
    // The moment relations carry rounding up by a factor ~|t*|/⟨t⟩ per
    // step in k where the vertex t* = b/a lies far outside [0, 1]
    // (measured: f 1.1e-13, compact i7 w3, t* ≈ −2.8, a generic point).
    // There the 30-point rule after the sine map of
    // segment_moments_gauss_sine adds positive terms only. q's roots are
    // t* ± h, h = √(−D)/|a|; the far one is at least 2 beyond [0, 1].
    // The near one must be either the clipped end itself (t0 > 0 for t*
    // ≥ 2: the map removes its branch point) or at least |AB|/10 beyond
    // the end: a root just outside an unclipped end leaves a branch
    // point ~√δ from the mapped interval (measured: ∇f 2.9e-11, compact
    // i3, the support 1e-4 |AB| beyond A), and the recurrences keep
    // those points. With the far root 2 away the mapped integrand is
    // analytic on a Bernstein ellipse of ρ ≳ 3 (4.97 at t* = −2.5).
    const ex half_chord = pow(-D_, numeric(1, 2)) / (-a_);
    const ex tiny = numeric(1, 4503599627370496);  // 2^−52: a clip below it counts as none
    // One alternative for both sides (one call of the rule in the code):
    // max(min(x, y), min(u, v)) ≥ 0 ⇔ (x, y ≥ 0) or (u, v ≥ 0).
    const ex beyond_a = minimum(t_star - 2, maximum(symbols.lo.t - tiny, -(t_star - half_chord) - numeric(1, 10)));
    const ex beyond_b =
        minimum(-1 - t_star, maximum(1 - tiny - symbols.hi.t, t_star + half_chord - numeric(11, 10)));
    Alternative far_vertex{{maximum(beyond_a, beyond_b)},
                           "vertex t* ≥ 2 with the support clipping A's side or 1/10 short of it, or t* ≤ −1 "
                           "likewise on B's side: every moment by segment_moments_gauss_sine<T, 30> "
                           "(Gauss–Legendre after a sine map)",
                           {}, {}, {}};
    fill_from_helper(far_vertex, "M_far_vertex", "segment_moments_gauss_sine<T, 30>",
                     {a_, b_, rule_c_, symbols.lo.t, symbols.hi.t},
                     [](int m_lo, int m_hi, int k_max) { return helper_costs::gauss_sine_rule(30, m_lo, m_hi, k_max); });
    choice.alternatives.push_back(std::move(far_vertex));
  }

  void push_compact_recurrences(Choice& choice, const MomentSymbols& symbols) {
    // The lowest J_n the moments reach: M_{k,n} calls M_{k−2,n−2}.
    const int bottom = kernel_index() - 2 * ((spec_.weight_degree + 1) / 2) - 2;
    MomentRecurrence upward(symbols, {RecurrenceDirection::Mode::up_from_bottom, bottom});
    choice.alternatives.push_back(
        {{symbols.lo.slope * symbols.hi.slope, a_ * maximum(symbols.lo.q, symbols.hi.q) - kCompactOutsideRatio * D_},
         "vertex of q outside [t0, t1], q_e < 17/20 q_max: recurrence (1) upwards from J_" +
             std::to_string(bottom) + " = J_upward_compact(…)",
         {},
         moment_values(upward),
         {}});
    MomentRecurrence downward(symbols);
    choice.alternatives.push_back({{}, "recurrence (1) downwards from J_0, J_1", {}, moment_values(downward), {}});
    choice.generic = choice.alternatives.size() - 1;
  }

  // Inverse and Cauchy kernels: Gauss panels (SCALIS high moments, alone), or
  // the flat rule, the beyond-end forms and the upward recurrence.
  void push_infinite_support_alternatives(Choice& choice) {
    const MomentSymbols symbols = symbols_ = infinite_support_symbols();
    const int top_index = highest_level();
    if (high_moments_by_panels_) {
      push_panel_alternatives(choice, symbols);
      return;
    }
    push_flat_rule(choice);
    if (top_index >= 2) push_beyond_end(choice, symbols, top_index);
    MomentRecurrence upward(symbols);
    choice.alternatives.push_back({{}, "recurrence (1) upwards from J_1, J_2", {}, moment_values(upward), {}});
    choice.generic = choice.alternatives.size() - 1;
  }

  void push_panel_alternatives(Choice& choice, const MomentSymbols& symbols) {
    // High moments (SCALIS, k ≤ 10): the moment relations cancel by a
    // factor ~(1 + D/(a² ⟨(t − t*)²⟩)) per step in k, measured up to 4e-8
    // at k = 10, both at moderate distance and beyond an end (where
    // segment_moments_beyond_end's far-end term has the opposite sign
    // once the weight's mass sits at the far end, as for a cone). Gauss
    // panels graded towards the roots of q add positive terms only
    // (include/skelconv/detail/gauss_moments.hpp); the closed forms are kept
    // near the line over the segment, where they are exact.
    const std::string panels = "segment_moments_gauss_panels<T>";
    Alternative away{{4 * D_ - pow(a_, 2)},
                     "P at least |AB|/2 from the line (D ≥ a²/4): every moment by " + panels, {}, {}, {}};
    fill_from_helper(away, "M_panels", panels, {a_, b_, a_minus_b_, D_}, helper_costs::gauss_panels, false);
    choice.alternatives.push_back(std::move(away));
    const ex near_q = minimum(symbols.lo.q, symbols.hi.q);
    // G_E by parts there: the difference Σ w_k (M_{k+1} − t* M_k) loses
    // |t*|/|t − t*| where the weight's mass is (t* just beyond the near
    // end: 4e-13 of ∇f measured 1.3e-3 |AB| beyond B of a segment of
    // radius 5e-4 |AB|), while the parts formula's boundary term at the
    // near end dominates its other terms.
    // Beyond an end the recurrence upwards also cancels where ρ ≥ 7/10
    // but P is not near the line (up to 1.3e-13 measured at D ≈ a²/2,
    // inverse i = 10, a cone seen past its base; ≤ 3e-14 for D < a²/100).
    Alternative beyond{{-b_ * a_minus_b_, maximum(kBeyondEndRho * a_ * near_q - D_, 100 * D_ - pow(a_, 2))},
                       "P beyond an end, D < 7/10 a min(q(0), q(1)) or D ≥ a²/100: every moment by " + panels,
                       {}, {}, {}};
    fill_from_helper(beyond, "M_panels", panels, {a_, b_, a_minus_b_, D_}, helper_costs::gauss_panels, false,
                     GE::by_parts);
    choice.alternatives.push_back(std::move(beyond));
    MomentRecurrence upward(symbols);
    choice.alternatives.push_back(
        {{}, "recurrence (1) upwards from J_1, J_2", {}, moment_values(upward), {}});
    choice.generic = choice.alternatives.size() - 1;
  }

  void push_flat_rule(Choice& choice) {
    // Far from the line compared with |AB| (D ≥ 2a²): the kernel is nearly
    // flat and the moment relations cancel; a 20-point Gauss–Legendre rule
    // is exact to rounding there (include/skelconv/detail/gauss_moments.hpp).
    // The same rule serves P beyond an end by at least 2|AB| along the
    // line (t* = b/a ≥ 3 or ≤ −2): q's complex roots t* ± i√D/a are then
    // at least 2 from [0, 1] (Bernstein ellipse ρ ≥ 5 + √24, so 20 nodes
    // leave ~ρ^−40), while the moment relations there multiply rounding
    // by up to |t*|^k (measured 1.0e-13 in f at t* ≈ 3.9, inverse i2 w3).
    // And P far from the midpoint, wherever the series about the midpoint
    // applies to this kernel's highest pole order (include/skelconv/detail/
    // far_field_series.hpp, far_series_applies: ρ² = a/(4 q(½)) ≤ 1/16 and
    // ρ m ≤ 8/5): α|P − M|² = c − β − b + a/4 ≥ a/(4 ρ²_max), i.e.
    // c − β − b − κ a ≥ 0 (2.2e-14 in f at 2.4 |AB| from M, Cauchy i3 w3,
    // by the moment relations beyond an end). segment_moments_far_field
    // takes the series there, by the same geometric test (it gets c − β),
    // and the rule elsewhere: a Cauchy kernel wide compared with |AB| has
    // D ≥ 2a² beside the segment, where ∇f is its along-line part
    // Σ w_k (M_{k+1} − t* M_k), a difference the series' moments leave 8×
    // less exact than the rule's (3.6e-14 against 4.7e-15, Cauchy i9 w2,
    // 1e-4 |AB| from the line). The test of c − β adds no temporary, so the
    // rest of the generated code keeps its names and GiNaC its order of terms.
    // Where the branch leaves the moments to the 20-point rule, its error
    // bound (gauss_moments.hpp: far_field_min_y_20_nodes, poles at
    // imaginary distance y = 2√D/a; beyond_end_min_z_20_nodes, at distance
    // |z| from the midpoint in any direction) is ≤ 2^−55 of the integral:
    // D ≥ 2a² puts the poles at y² = 4D/a² ≥ 8; t* ≥ 3 or ≤ −2 at |z| ≥ 5;
    // the series' range at |z|² = 1/ρ² ≥ 1/ρ²_max.
    static_assert(8 >= detail::squared(far_field_min_y_20_nodes));
    static_assert(5 >= beyond_end_min_z_20_nodes);
    static_assert(1 / detail::far_series_max_rho2 >= detail::squared(beyond_end_min_z_20_nodes));
    const ex kappa = far_series_flat_kappa(highest_level());
    Alternative flat{{maximum(maximum(D_ - 2 * pow(a_, 2), maximum(b_ - 3 * a_, -b_ - 2 * a_)),
                              c_ - beta_ - b_ - kappa * a_)},
                     "P far from the line (D ≥ 2a²), beyond an end by 2|AB| (t* ≥ 3 or t* ≤ −2) or far from the "
                     "midpoint (|P − M|² ≥ " +
                         to_string(kappa + GiNaC::numeric(1, 4)) +
                         " |AB|²): every moment by segment_moments_far_field<T> (the series about the midpoint, "
                         "or segment_moments_gauss<T, 20>)",
                     {}, {}, {}};
    fill_from_helper(flat, "M_flat", "segment_moments_far_field<T>", {a_, b_, c_, c_ - beta_}, gauss_rule_cost(20));
    choice.alternatives.push_back(std::move(flat));
  }

  void push_beyond_end(Choice& choice, const MomentSymbols& symbols, int top_index) {
    // Beyond an end, with ρ = D/(a min(q(0), q(1))) below `kBeyondEndRho`:
    // recurrence (1) downwards (segment_moments.hpp, stable_recurrence.hpp).
    const ex near_q = minimum(symbols.lo.q, symbols.hi.q);
    Alternative beyond{{-b_ * a_minus_b_, kBeyondEndRho * a_ * near_q - D_}, "", {}, {}, {}};
    if (lowest_level() >= highest_moment() + 2) {
      // Every moment from segment_moments_beyond_end, centred at the near end.
      fill_from_helper(beyond, "M_beyond", "segment_moments_beyond_end<T>",
                       {a_, b_, a_minus_b_, D_, symbols.lo.q, symbols.hi.q},
                       helper_costs::moments_beyond_end, false, GE::by_parts);
      beyond.why = "P beyond an end, D < 7/10 a min(q(0), q(1)): moments centred at the near end, "
                   "recurrence (1) downwards (segment_moments_beyond_end)";
    } else {
      MomentRecurrence downward(symbols, {RecurrenceDirection::Mode::down_from_top, top_index});
      beyond.values = moment_values(downward);
      beyond.why = "P beyond an end, D < 7/10 a min(q(0), q(1)): recurrence (1) downwards from J_" +
                   std::to_string(top_index) + " = J_downward(…)";
    }
    choice.alternatives.push_back(std::move(beyond));
  }

  // f = |AB| F and ∇f = −n α |AB| (AP G_ap − AB G_ab) = −n α |AB| (H G_ap −
  // AB G_E), docs/mathematics.md §2 (build() says why the second form).
  void add_outputs(const std::vector<symbol>& targets, bool value, bool gradient) {
    if (value) program_.add_output("f", output_scale_ * length_ * targets[0]);
    if (gradient) {
      const symbol& g_ap = targets[value ? 1 : 0];
      const symbol& g_e = targets[value ? 2 : 1];
      const std::array<ex, 3> foot = define_foot();
      const ex factor = define("g_factor", -kernel_index() * alpha_ * output_scale_ * length_);
      for (int i = 0; i < 3; ++i)
        program_.add_output("grad[" + std::to_string(i) + "]", factor * (foot[i] * g_ap - ab_[i] * g_e));
    }
  }

  // H = AP − t* AB, t* = b/a. For a segment t* is the foot of P on the line
  // and H = (AB × AP) × AB / |AB|²: from the exactly rounded cross product
  // where P is near the line (define_exact_cross's choice), where AP − t* AB
  // would lose |AP|/h; elsewhere AP − t* AB (error ≤ ε|AP| ≤ 16 ε |H|).
  // Where t* is not the foot t⊥ (SCALIS Cauchy: b, a include σ²τ terms),
  // H = (AP − t⊥ AB) + (t⊥ − t*) AB, the perpendicular part as above and the
  // offset from foot_offset() (the two parts are orthogonal: nothing
  // cancels). Without the cross product's choice, AP − (b/a) AB.
  std::array<ex, 3> define_foot() {
    if (foot_.has_value()) {
      const ex offset = foot_offset();
      if (offset.is_zero()) return *foot_;
      const ex along = define("foot_offset", offset);
      std::array<ex, 3> h;
      for (int i = 0; i < 3; ++i) h[i] = define("foot_h" + std::to_string(i), (*foot_)[i] + along * ab_[i]);
      return h;
    }
    const ex t_star = define("t_star", b_ / a_);
    std::array<ex, 3> h;
    for (int i = 0; i < 3; ++i) h[i] = define("foot" + std::to_string(i), ap_[i] - t_star * ab_[i]);
    return h;
  }

  // Σ_k w_k (M_{k+1,L} − t* M_{k,L}) = Σ_k w_k ∫ t^k (t − t*) q^(−L/2) dt,
  // by parts (with n = L − 2, a(t − t*) = q'/2 and q^(−L/2) q' = −(2/n) d(q^(−n/2))):
  //     = ( ∫ w'(t) q^(−n/2) dt + w(t0) q(t0)^(−n/2) − w(t1) q(t1)^(−n/2) ) / (a n),
  // whose terms do not cancel where P is near the line (the difference of
  // the two moments loses the factor |t*| M / |M_{k+1} − t* M_k| there).
  ex along_line_moment(MomentRecurrence& moments, int level) {
    return along_line_moment([&](int k, int m) { return moments.M(k, m); }, level);
  }
  ex along_line_moment(const std::function<ex(int k, int m)>& M, int level) {
    return along_line_moment(M, level, symbols_.lo, symbols_.hi);
  }
  ex along_line_moment(const std::function<ex(int k, int m)>& M, int level, const QuadraticEnd& lo,
                       const QuadraticEnd& hi) {
    const int n = level - 2;
    ex derivative_part = 0;
    for (int k = 1; k <= spec_.weight_degree; ++k) derivative_part += k * w_[k] * M(k - 1, n);
    auto weight_at = [&](const ex& t) {
      ex w = w_[0];  // (GiNaC leaves 0^0 undefined)
      for (int k = 1; k <= spec_.weight_degree; ++k) w += w_[k] * pow(t, k);
      return w;
    };
    auto q_power = [&](const QuadraticEnd& end) {  // q^(−n/2)
      if (n % 2 == 0) return pow(end.q, numeric(-n, 2));
      // Compact kernels (n < 0): q^((−n−1)/2) √q, so that q is read where it is a symbol of its own.
      return n < 0 ? pow(end.q, numeric(-n - 1, 2)) * end.root : pow(end.root, -n);
    };
    return (derivative_part + weight_at(lo.t) * q_power(lo) - weight_at(hi.t) * q_power(hi)) / (a_ * n);
  }

  // Lowest and highest level m, highest k of the moments M_{k,m} the
  // requests read (segments: F needs m = n, k ≤ d; G_ap, G_ab need
  // m = n + 2, k ≤ d + 1).
  int lowest_level() const {  // along_line requests read level − 2 (by parts)
    int m = requests_.front().level;
    for (const MomentRequest& r : requests_) m = std::min(m, r.along_line ? r.level - 2 : r.level);
    return m;
  }
  int highest_level() const {
    int m = requests_.front().level;
    for (const MomentRequest& r : requests_) m = std::max(m, r.level);
    return m;
  }
  int highest_moment() const {
    int shift = 0;
    for (const MomentRequest& r : requests_) shift = std::max(shift, r.shift);
    return spec_.weight_degree + shift;
  }

  // The cost of segment_moments_gauss<T, nodes>.
  static HelperCost gauss_rule_cost(int nodes) {
    return [nodes](int m_lo, int m_hi, int k_max) { return helper_costs::gauss_rule(nodes, m_lo, m_hi, k_max); };
  }

  // How G_E (along_line requests) is formed from the helper's moments:
  // `by_parts`, along_line_moment's parts formula from the level-n moments,
  // for helpers that run near the line or near an end; `difference`,
  // G_ab − t* G_ap (far from the segment, where the parts formula's boundary
  // terms would cancel instead); `by_parts_near_line`, the difference with
  // a refinement by parts where P is near the line over the segment
  // (push_helper_alternatives says why).
  enum class GE { difference, by_parts, by_parts_near_line };
  // The interval's ends for the parts formula, where they are not the
  // clip's (push_support_root_alternatives).
  struct PartsEnds {
    QuadraticEnd lo, hi;
  };

  // N of the smallest Gauss–Legendre rule Boost tabulates that is exact for
  // polynomials of `degree` (2N − 1 ≥ degree).
  static int exact_rule_nodes(int degree) {
    int nodes = 7;
    for (int tabulated : {7, 10, 15, 20, 25, 30}) {
      nodes = tabulated;
      if (2 * tabulated - 1 >= degree) break;
    }
    return nodes;
  }

  // Compact kernels where the support sphere grazes the segment: the
  // clipped interval's ends, passed as parameters t ∈ [0, 1] (doubles,
  // each off by up to ε/2 absolute), are off by ~ε/(t1 − t0) relative to
  // its length, and q on it is a small difference of numbers ~1: f ~
  // (t1 − t0) q^(i/2) loses (i+2)/2 times that (measured: f 1.4e-8, compact
  // i15, R − |BP| = 1e-6 R). These forms take the interval from the roots
  // r1 < r2 of q instead, found from R² − d² rounded once from the exact
  // inputs (skelconv/detail/support_gap.hpp), and write q = −a (t − r1)(r2 − t) as
  // a product of distances to its roots (segment_moments_between_roots,
  // gauss_moments.hpp; positive terms only), so that no difference of
  // nearly equal numbers remains:
  //  * both ends clipped: the chord (push_chord_alternative);
  //  * one end E inside the ball, the other clipped, the vertex t* inside
  //    the segment: the chord minus its part beyond E
  //    (push_straddle_alternative);
  //  * the same with the vertex beyond E: the part inside the segment,
  //    from E (push_end_alternative).
  // The chord form wherever both ends are clipped (it is exact and cheap);
  // the others where q at the end inside the ball is at most 1/4: above,
  // what the forms below lose, ~(i+2)/2 · ε/q, stays near rounding, and
  // they are cheaper.
  void push_support_root_alternatives(Choice& choice) {
    const SupportRootRule rule = support_root_rule();
    push_chord_alternative(choice, rule);
    for (const bool at_b : {true, false}) push_straddle_alternative(choice, rule, at_b);
    for (const bool at_b : {true, false}) push_end_alternative(choice, rule, at_b);
  }

  // The helper of the support-root forms: N nodes, exact for even degrees
  // (a polynomial), after the sine map for odd ones (q^(i/2) has branch
  // points at the roots).
  struct SupportRootRule {
    std::string function;
    HelperCost cost;
  };
  SupportRootRule support_root_rule() const {
    const bool odd = spec_.degree % 2 != 0;
    const int nodes = odd ? 30 : exact_rule_nodes(spec_.degree + highest_moment());
    return {"segment_moments_between_roots<T, " + std::to_string(nodes) + (odd ? ", NodeMap::sine>" : ">"),
            [nodes, odd](int m_lo, int m_hi, int k_max) {
              return helper_costs::between_roots(nodes, odd, m_lo, m_hi, k_max);
            }};
  }
  std::string support_root_why(const std::string& where, const SupportRootRule& rule) const {
    return where + ", interval from the roots of q (R² − d² rounded once, support_gap.hpp): " + rule.function;
  }
  // 2^−52: a clip below it counts as none.
  static ex clip_tolerance() { return numeric(1, 4503599627370496); }
  // q at the end inside the ball at most this: see push_support_root_alternatives.
  static ex shallow_end() { return numeric(1, 4); }

  // A call of a support_gap.hpp helper on `points` and R: one element.
  ArrayCall support_gap_call(const std::string& array, const std::string& helper, std::vector<ex> points,
                             const OpCount& ops) const {
    points.push_back(radius_);
    return ArrayCall{array, helper, {}, points, {symbol(array + "_0")}, ops, true};
  }
  ArrayCall line_gap_call() const {
    return support_gap_call("line_gap", "exact_line_support_gap<T>",
                            {A_[0], A_[1], A_[2], B_[0], B_[1], B_[2], P_[0], P_[1], P_[2]},
                            helper_costs::line_support_gap());
  }
  ArrayCall end_gap_call(bool at_b) const {
    const std::array<symbol, 3>& end = at_b ? B_ : A_;
    return support_gap_call(at_b ? "gap_B" : "gap_A", "exact_point_support_gap<T>",
                            {end[0], end[1], end[2], P_[0], P_[1], P_[2]}, helper_costs::point_support_gap());
  }
  // h_c = √(R²|AB|² − |AB × AP|²) / |AB|², the chord's half-length in t.
  ex half_chord(const ArrayCall& line_gap) const {
    return pow(nonnegative_part(line_gap.elements[0]), numeric(1, 2)) / ab_ab_;
  }
  // q(E) = (R² − |P − E|²)/R².
  ex end_q(const ArrayCall& end_gap) const { return nonnegative_part(end_gap.elements[0]) * pow(inv_R_, 2); }
  // The parts formula's ends: q = 0 at the clipped root, q(E) at E.
  PartsEnds root_and_end(bool at_b, const ex& q_end) const {
    const QuadraticEnd root{at_b ? symbols_.lo.t : symbols_.hi.t, 0, 0, 0};
    const QuadraticEnd inside{at_b ? ex(1) : ex(0), q_end, pow(q_end, numeric(1, 2)), 0};
    return at_b ? PartsEnds{root, inside} : PartsEnds{inside, root};
  }
  // Conditions: E inside the ball (unclipped), the other end clipped, q(E) ≤ 1/4.
  std::vector<ex> one_end_clipped(bool at_b) const {
    const ex t0 = symbols_.lo.t, t1 = symbols_.hi.t;
    return at_b ? std::vector<ex>{t0 - clip_tolerance(), t1 - 1, shallow_end() - symbols_.hi.q}
                : std::vector<ex>{1 - clip_tolerance() - t1, -t0, shallow_end() - symbols_.lo.q};
  }

  // Both ends clipped: r1,2 = t* ∓ h_c, q = 0 at both ends of the chord.
  void push_chord_alternative(Choice& choice, const SupportRootRule& rule) {
    ArrayCall gap = line_gap_call();
    const ex chord_half = half_chord(gap);
    Alternative chord{{symbols_.lo.t - clip_tolerance(), 1 - clip_tolerance() - symbols_.hi.t},
                      support_root_why("support chord inside the segment (both ends clipped)", rule), {}, {}, {}};
    chord.calls.push_back(std::move(gap));
    const QuadraticEnd root_lo{symbols_.lo.t, 0, 0, 0}, root_hi{symbols_.hi.t, 0, 0, 0};
    fill_from_helper(chord, "M_roots", rule.function, {-a_, b_ / a_, chord_half, 0, 0}, rule.cost, true, GE::by_parts,
                     PartsEnds{root_lo, root_hi});
    choice.alternatives.push_back(std::move(chord));
  }

  // The chord straddling E (the vertex t* inside the segment, E inside the
  // ball, the other end clipped): the interval [r1, 1] (E = B) is the chord
  // [r1, r2] minus its part [1, r2] beyond E, of length r2 − 1 = q_E/(−a s)
  // < s = 1 − r1 (t* < 1), so the difference keeps at least half its digits
  // and each part's other root lies at least its length away; s = (1 − t*) +
  // h_c, a sum (1 − t* = −AB·BP/|AB|²). E = A likewise with [r1, 0] beyond
  // A, s = t* + h_c.
  void push_straddle_alternative(Choice& choice, const SupportRootRule& rule, bool at_b) {
    ArrayCall line_gap = line_gap_call();
    ArrayCall end_gap = end_gap_call(at_b);
    const ex chord_half = half_chord(line_gap);
    const ex q_end = end_q(end_gap);
    const ex s = (at_b ? -ab_bp_ / ab_ab_ : ab_ap_ / ab_ab_) + chord_half;  // from E to the clipped root
    const ex beyond = q_end / (-a_ * s);                                    // from E to the other root
    std::vector<ex> conditions = one_end_clipped(at_b);
    conditions.insert(conditions.begin() + 2, at_b ? -ab_bp_ : ab_ap_);  // t* not beyond E
    Alternative straddle{conditions,
                         support_root_why(at_b ? "support chord straddling B (A clipped, P beside the segment, q(1) ≤ 1/4)"
                                                 ": the chord minus its part beyond the end"
                                               : "support chord straddling A (B clipped, P beside the segment, q(0) ≤ 1/4)"
                                                 ": the chord minus its part beyond the end",
                                          rule),
                         {}, {}, {}};
    straddle.calls.push_back(std::move(line_gap));
    straddle.calls.push_back(std::move(end_gap));
    const std::vector<ex> part_beyond =
        at_b ? std::vector<ex>{-a_, 1 + beyond / 2, beyond / 2, s, 0} : std::vector<ex>{-a_, -beyond / 2, beyond / 2, 0, s};
    fill_from_helper(straddle, "M_roots", rule.function, {-a_, b_ / a_, chord_half, 0, 0}, rule.cost, true,
                     GE::by_parts, root_and_end(at_b, q_end), part_beyond);
    choice.alternatives.push_back(std::move(straddle));
  }

  // The vertex t* beyond E (P projects beyond E, AB·BP ≥ 0 or AB·AP ≤ 0):
  // with σ the distance in t from E, q = q_E + 2gσ + aσ², g ≤ 0 the slope
  // into the segment (E = B: σ = 1 − t, g = −(a − b) = α AB·BP; E = A: σ =
  // t, g = −b); its roots are s = q_E/(√(g² − a q_E) − g) (the clip) and
  // −(√(g² − a q_E) − g)/(−a) (beyond E, at least s away since t* lies
  // beyond E: the rule sees no nearby branch point).
  void push_end_alternative(Choice& choice, const SupportRootRule& rule, bool at_b) {
    ArrayCall gap = end_gap_call(at_b);
    const ex q_end = end_q(gap);
    const ex g = at_b ? alpha_ * ab_bp_ : -b_;
    const ex root_term = pow(pow(g, 2) - a_ * q_end, numeric(1, 2)) - g;  // √(g² − a q_E) − g ≥ 0
    const ex s = q_end / root_term;
    const ex far_gap = root_term / (-a_);
    const ex mid = at_b ? 1 - s / 2 : s / 2;
    std::vector<ex> conditions = one_end_clipped(at_b);
    conditions.insert(conditions.begin() + 2, at_b ? ab_bp_ : -ab_ap_);  // t* beyond E
    Alternative end{conditions,
                    support_root_why(at_b ? "support grazing B (A clipped, P beyond B, q(1) ≤ 1/4)"
                                          : "support grazing A (B clipped, P beyond A, q(0) ≤ 1/4)",
                                     rule),
                    {}, {}, {}};
    end.calls.push_back(std::move(gap));
    fill_from_helper(end, "M_roots", rule.function, {-a_, mid, s / 2, at_b ? ex(0) : far_gap, at_b ? far_gap : ex(0)},
                     rule.cost, true, GE::by_parts, root_and_end(at_b, q_end));
    choice.alternatives.push_back(std::move(end));
  }

  // A helper alternative taken where `conditions` hold. When the outputs
  // include G_E, its values are refined: G_E by parts where P is near the
  // line and projects onto the segment (sin∠(AB, AP) < 1/16, t* ∈ [0, 1]:
  // there G_E can be small against t* G_ap, and the difference loses that
  // ratio), elsewhere as a difference (beyond an end G_E has one sign and
  // the difference keeps its digits, while for the compact kernels the
  // parts formula's boundary terms cancel by ~R²/|AB|² far along the axis;
  // measured: soft kernel, far region, ∇f 8e-16 → 6.5e-13 by parts). Both
  // read the same helper call, written once. Without conditions the
  // alternative is the choice's fallback.
  void push_helper_alternatives(Choice& choice, const std::vector<ex>& conditions, const std::string& why,
                                const std::string& array, const std::string& function, const std::vector<ex>& args,
                                const HelperCost& cost) {
    const bool along_line = std::any_of(requests_.begin(), requests_.end(), [](const MomentRequest& r) { return r.along_line; });
    Alternative alt{conditions, why, {}, {}, {}};
    fill_from_helper(alt, array, function, args, cost, true, along_line ? GE::by_parts_near_line : GE::difference,
                     rule_ends_);
    choice.alternatives.push_back(std::move(alt));
  }

  // Takes every moment the outputs need from one helper call that fills an
  // array (include/skelconv/detail/stable_recurrence.hpp, gauss_moments.hpp):
  // function(m_lo, m_hi, k_max, args…, array). `cost` gives the call's
  // operations; `fixed_rule` says whether their number is the same at every P;
  // `along_line` and `ends`: how G_E is formed (GE, PartsEnds above).
  //
  // `minus_args`: the moments are those of the call with `args` minus those
  // of a second call with `minus_args` (an interval as a difference of two,
  // push_support_root_alternatives).
  void fill_from_helper(Alternative& alt, const std::string& array, const std::string& function,
                        const std::vector<ex>& args, const HelperCost& cost, bool fixed_rule = true,
                        GE along_line = GE::difference, const std::optional<PartsEnds>& ends = std::nullopt,
                        const std::optional<std::vector<ex>>& minus_args = std::nullopt) {
    const int m_lo = lowest_level(), m_hi = highest_level(), k_max = highest_moment();
    auto make_call = [&](const std::string& name, const std::vector<ex>& call_args) {
      ArrayCall call{name, function, {std::to_string(m_lo), std::to_string(m_hi), std::to_string(k_max)},
                     call_args, {}, cost(m_lo, m_hi, k_max), fixed_rule};
      for (int m = m_lo; m <= m_hi; m += 2)
        for (int k = 0; k <= k_max; ++k) call.elements.emplace_back(name + "_" + std::to_string(call.elements.size()));
      return call;
    };
    ArrayCall call = make_call(array, args);
    std::optional<ArrayCall> minus;
    if (minus_args) minus = make_call(array + "_minus", *minus_args);
    auto moment = [&](int k, int m) -> ex {  // M_{k,m} in the helper's layout
      const size_t at = static_cast<size_t>(((m - m_lo) / 2) * (k_max + 1) + k);
      return minus ? call.elements[at] - minus->elements[at] : ex(call.elements[at]);
    };
    auto weighted = [&](int shift, int m) {
      ex sum = 0;
      for (int k = 0; k <= spec_.weight_degree; ++k) sum += w_[k] * moment(k + shift, m);
      return sum;
    };
    auto values = [&](bool by_parts) {
      std::vector<ex> v;
      for (const MomentRequest& r : requests_) {
        if (!r.along_line)
          v.push_back(weighted(r.shift, r.level));
        else if (by_parts)
          v.push_back(ends ? along_line_moment(moment, r.level, ends->lo, ends->hi) : along_line_moment(moment, r.level));
        else
          v.push_back(weighted(1, r.level) - b_ / a_ * weighted(0, r.level));
      }
      return v;
    };
    alt.values = values(along_line == GE::by_parts);
    if (along_line == GE::by_parts_near_line)
      alt.refinement = Alternative::Refinement{
          {ab_ab_ * ap_ap_ - 256 * cross_cross_, b_ * (a_ - b_)}, "near the line, G_E by parts", values(true)};
    alt.calls.push_back(std::move(call));
    if (minus) alt.calls.push_back(std::move(*minus));
  }

  // program_.choose(choice), with each of lazy_steps_ defined inside the
  // alternatives that read it (in their branch of the generated code), and
  // nowhere else.
  void choose(Choice choice) {
    for (Alternative& alt : choice.alternatives) {
      std::vector<std::pair<symbol, ex>> read;
      for (const auto& step : lazy_steps_)
        if (reads(alt, step.first)) read.push_back(step);
      alt.steps.insert(alt.steps.begin(), read.begin(), read.end());
    }
    program_.choose(std::move(choice));
  }

  static bool reads(const Alternative& alt, const symbol& s) {
    auto has = [&](const std::vector<ex>& list) {
      return std::any_of(list.begin(), list.end(), [&](const ex& e) { return e.has(s); });
    };
    if (has(alt.conditions) || has(alt.values)) return true;
    if (alt.refinement && (has(alt.refinement->conditions) || has(alt.refinement->values))) return true;
    for (const auto& step : alt.steps)
      if (step.second.has(s)) return true;
    for (const ArrayCall& call : alt.calls)
      if (has(call.args)) return true;
    return false;
  }

  int kernel_index() const { return generated_family(spec_.family).compact_support ? -spec_.degree : spec_.degree; }

  ex define(const std::string& name, const ex& value) {
    if (GiNaC::is_a<symbol>(value)) return value;  // an alias needs no code
    symbol s(name);
    program_.define(s, value);
    return s;
  }

  // Σ_k w_k M_{k+shift,n}
  ex weighted_moment(MomentRecurrence& moments, int shift, int n) {
    ex sum = 0;
    for (int k = 0; k <= spec_.weight_degree; ++k) sum += w_[k] * moments.M(k + shift, n);
    return sum;
  }

  // An input symbol `name` read from the C++ element `array[index]`.
  symbol input(const std::string& name, const std::string& array, int index) {
    const std::string i = std::to_string(index);
    symbol s(name + i);
    program_.add_input(s, array + '[' + i + ']');
    return s;
  }

  virtual void read_inputs() {
    for (int i = 0; i < 3; ++i) {
      A_[i] = input("A", "in.a", i);
      B_[i] = input("B", "in.b", i);
      P_[i] = input("P", "in.p", i);
    }
    for (int k = 0; k <= spec_.weight_degree; ++k) w_.push_back(input("w", "in.w", k));
  }

  // Vectors and their products. |AB × AP|² and the dot products with BP are
  // formed directly rather than as differences of larger numbers, so D and
  // the values at B keep their digits near the line and near B.
  void define_geometry() {
    for (int i = 0; i < 3; ++i) {
      const std::string k = std::to_string(i);
      ab_[i] = define("ab" + k, B_[i] - A_[i]);
      if (point_lo_[i].is_zero()) {
        ap_[i] = define("ap" + k, P_[i] - A_[i]);
        bp_[i] = define("bp" + k, P_[i] - B_[i]);
      } else {
        // P = P_hi + P_lo (polygon edges: the foot as a double-word number):
        // the difference of the leading parts first (exact near A, B by
        // Sterbenz), then the trailing part, so P's rounding stays out.
        ap_[i] = define("ap" + k, define("ap_hi" + k, P_[i] - A_[i]) + point_lo_[i]);
        bp_[i] = define("bp" + k, define("bp_hi" + k, P_[i] - B_[i]) + point_lo_[i]);
      }
    }
    auto dot = [](const std::array<ex, 3>& u, const std::array<ex, 3>& v) {
      return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    };
    ab_ab_ = define("ab_ab", dot(ab_, ab_));
    ab_ap_ = define("ab_ap", dot(ab_, ap_));
    ap_ap_ = define("ap_ap", dot(ap_, ap_));
    const std::array<ex, 3> plain = {
        define("plain_cross0", ab_[1] * ap_[2] - ab_[2] * ap_[1]),
        define("plain_cross1", ab_[2] * ap_[0] - ab_[0] * ap_[2]),
        define("plain_cross2", ab_[0] * ap_[1] - ab_[1] * ap_[0]),
    };
    define_exact_cross(plain, define("plain_cross_cross", dot(plain, plain)));
    bp_bp_ = define("bp_bp", dot(bp_, bp_));
    ab_bp_ = define("ab_bp", dot(ab_, bp_));
    ap_bp_ = define("ap_bp", dot(ap_, bp_));
    length_ = define("length", pow(ab_ab_, numeric(1, 2)));
  }

  // AB × AP and |AB × AP|² (and, for a segment's gradient, the foot vector
  // H of define_foot), rounded once from the exact inputs where P is near
  // the line (sin∠(AB, AP) < 1/16, where the plain product's relative error
  // ε/sin∠ would exceed 16ε): skelconv/detail/exact_cross.hpp, whose header says
  // why D = |AB × AP|² needs it. Elsewhere the plain product is kept, at
  // the cost of one test.
  void define_exact_cross(const std::array<ex, 3>& plain, const ex& plain_cross_cross) {
    const symbol cross_cross("cross_cross");
    std::vector<symbol> targets{symbol("cross0"), symbol("cross1"), symbol("cross2"), cross_cross};
    const bool with_foot = gradient_needs_foot_;
    if (with_foot)
      for (int i = 0; i < 3; ++i) targets.emplace_back("foot" + std::to_string(i));
    Choice choice{targets, {}};
    Alternative away{{256 * plain_cross_cross - ab_ab_ * ap_ap_}, "P away from the line (sin∠(AB, AP) ≥ 1/16)",
                     {}, {plain[0], plain[1], plain[2], plain_cross_cross}, {}};
    Alternative near{{}, "P near the line: AB × AP rounded once from the exact inputs (segment_exact_cross)",
                     {}, {}, {}};
    ArrayCall call{"exact_cross", "segment_exact_cross<T>", {},
                   {A_[0], A_[1], A_[2], B_[0], B_[1], B_[2], P_[0], P_[1], P_[2]}, {},
                   helper_costs::exact_cross(), true};
    for (int i = 0; i < 3; ++i) call.elements.emplace_back("exact_cross_" + std::to_string(i));
    // With P = P_hi + P_lo: AB × AP_hi exactly rounded, plus AB × P_lo (~ε
    // of it, so its own rounding is ~ε²).
    std::array<ex, 3> exact{call.elements[0], call.elements[1], call.elements[2]};
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      exact[i] = exact[i] + (ab_[j] * point_lo_[k] - ab_[k] * point_lo_[j]);
    }
    near.values = {exact[0], exact[1], exact[2], exact[0] * exact[0] + exact[1] * exact[1] + exact[2] * exact[2]};
    near.calls.push_back(std::move(call));
    if (with_foot) {
      // H = AP − (AB·AP / |AB|²) AB away from the line; (AB × AP) × AB / |AB|² near it.
      const ex t_star = ab_ap_ / ab_ab_;
      for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        away.values.push_back(ap_[i] - t_star * ab_[i]);
        near.values.push_back((exact[j] * ab_[k] - exact[k] * ab_[j]) / ab_ab_);
      }
    }
    choice.alternatives.push_back(std::move(away));
    choice.alternatives.push_back(std::move(near));
    choice.generic = 0;
    program_.choose(std::move(choice));
    cross_ = {targets[0], targets[1], targets[2]};
    cross_cross_ = cross_cross;
    if (with_foot) foot_ = std::array<ex, 3>{targets[4], targets[5], targets[6]};
  }

  // t⊥ − t*: from the parameter t⊥ = AB·AP/|AB|² of P's foot on the line
  // AB to the vertex t* = b/a of q. Zero when a and b are α|AB|² and
  // α AB·AP (segments, polygon edges).
  virtual ex foot_offset() const { return 0; }

  // Hook for builders whose quadratic has another constant term (polygon
  // edges: β + α z², Hubert 2012 §5); segments keep β.
  virtual void adjust_beta() {}

  // q(t) = α|P − Γ(t)|² + β = a t² − 2 b t + c.
  virtual void define_quadratic() {
    const GeneratedFamily& row = generated_family(spec_.family);
    switch (row.alpha) {
      case GeneratedFamily::Alpha::one:
        alpha_ = 1;
        break;
      case GeneratedFamily::Alpha::parameter: {
        symbol parameter(row.parameter);
        program_.add_input(parameter, std::string("in.") + row.parameter);
        alpha_ = parameter;
        break;
      }
      case GeneratedFamily::Alpha::minus_inverse_square: {
        symbol parameter(row.parameter);
        program_.add_input(parameter, std::string("in.") + row.parameter);
        radius_ = parameter;
        inv_R_ = define("inv_R", pow(parameter, -1));
        alpha_ = -define("inv_R2", pow(inv_R_, 2));
        break;
      }
    }
    beta_ = row.beta;
    adjust_beta();
    a_ = define("a", alpha_ * ab_ab_);
    b_ = define("b", alpha_ * ab_ap_);
    c_ = define("c", beta_ + alpha_ * ap_ap_);
    // D = ac − b² = αβ|AB|² + α²|AB × AP|² (Lagrange's identity): no
    // cancellation near the segment's line.
    D_ = define("D", alpha_ * (beta_ * ab_ab_ + alpha_ * cross_cross_));
    a_minus_b_value_ = -alpha_ * ab_bp_;        // a − b = −α AB·BP
    q1_value_ = beta_ + alpha_ * bp_bp_;         // q(1) = β + α|BP|²
    c_minus_b_value_ = beta_ + alpha_ * ap_bp_;  // c − b = β + α AP·BP
  }

  // The quadratic's coefficients, common to every family.
  MomentSymbols quadratic_symbols() const {
    MomentSymbols m;
    m.a = a_;
    m.b = b_;
    m.c = c_;
    m.D = D_;
    return m;
  }

  // Inverse and Cauchy kernels: t ∈ [0, 1], q > 0, a > 0.
  MomentSymbols infinite_support_symbols() {
    MomentSymbols m = quadratic_symbols();
    const bool odd = spec_.degree % 2 != 0;
    const ex a_minus_b = a_minus_b_ = define("a_minus_b", a_minus_b_value_);
    const ex q1 = define("q1", q1_value_);
    const symbol r0("r0"), r1("r1");
    m.lo = {0, c_, r0, -b_};
    m.hi = {1, q1, r1, a_minus_b};
    if (odd) {
      program_.define(r0, pow(c_, numeric(1, 2)));
      program_.define(r1, pow(q1, numeric(1, 2)));
      program_.declare_square_root(r0, GiNaC::ex_to<symbol>(c_));
      program_.declare_square_root(r1, GiNaC::ex_to<symbol>(q1));
      m.J1 = define_J1_infinite(a_minus_b, r0, r1);
    } else {
      // J_2 = (atan((a−b)/√D) + atan(b/√D))/√D = atan2(√D, c − b)/√D: the two
      // atans of Hubert §3.1 summed into one, exact for all P off the line.
      const ex c_minus_b = define("c_minus_b", c_minus_b_value_);
      const ex root_D = pow(D_, numeric(1, 2));
      // Only the recurrences read J_2 (0/0 on the line) and ln(q(1)/q(0)):
      // the forms by Gauss rules do not pay for an atan2 and a log.
      symbol J2("J2"), log_ratio("log_ratio");
      lazy_steps_.emplace_back(J2, GiNaC::atan2(root_D, c_minus_b) / root_D);
      lazy_steps_.emplace_back(log_ratio, GiNaC::log(q1 / c_));
      m.J2 = J2;
      m.log_ratio = log_ratio;
    }
    return m;
  }

  // J_1 = (asinh((a−b)/√D) + asinh(b/√D))/√a (Hubert §3.1, "arcsch" = asinh)
  //     = asinh(X)/√a, with asinh x + asinh y = asinh(x√(1+y²) + y√(1+x²)):
  //   X = √a ((a−b) r0 + b r1) / D            when P projects on [A,B];
  //   X = √a (a − 2b) / ((a−b) r0 − b r1)     beyond an end, where the first
  // form cancels: the two are equal, since ((a−b)r0)² − (b r1)² = (a−2b) D.
  ex define_J1_infinite(const ex& a_minus_b, const symbol& r0, const symbol& r1) {
    const ex root_a = pow(a_, numeric(1, 2));
    symbol X("X");
    Choice choice{{X}, {}};
    choice.alternatives.push_back({{b_ * a_minus_b}, "P projects onto [A,B]: X = √a((a−b)r0 + b r1)/D",
                                   {}, {root_a * (a_minus_b * r0 + b_ * r1) / D_}, {}});
    choice.alternatives.push_back({{}, "P projects beyond an end: X = √a(a−2b)/((a−b)r0 − b r1)",
                                   {}, {root_a * (a_minus_b - b_) / (a_minus_b * r0 - b_ * r1)}, {}});
    program_.choose(std::move(choice));
    return define("J1", GiNaC::asinh(X) / root_a);
  }

  // Compact kernels: t ∈ [t0, t1] (the clip), a < 0, q ≥ 0.
  MomentSymbols compact_symbols() {
    MomentSymbols m = quadratic_symbols();
    const bool odd = spec_.degree % 2 != 0;
    auto end = [&](const std::string& tag, const std::string& input) {
      symbol t("t" + tag);
      program_.add_input(t, input);
      const ex slope = define("slope" + tag, a_ * t - b_);
      const ex q = define("q" + tag, nonnegative_part(c_ + t * (slope - b_)));
      symbol root("r" + tag);
      if (odd) {
        program_.define(root, pow(q, numeric(1, 2)));
        program_.declare_square_root(root, GiNaC::ex_to<symbol>(q));
      }
      return QuadraticEnd{t, q, root, slope};
    };
    m.lo = end("0", "in.t0");
    m.hi = end("1", "in.t1");
    if (odd) {
      // ∫ q^(-1/2) dt = asin((b − a t)/√(−D)) / √(−a) for a < 0, written as
      // atan2(b − a t, √(−a) √q) so that it stays exact where q = 0 (a clipped end).
      const ex root_minus_a = define("root_minus_a", length_ * inv_R_);  // √(−a) = |AB|/R
      m.J1 = define("J1", (GiNaC::atan2(-m.hi.slope, root_minus_a * m.hi.root) -
                           GiNaC::atan2(-m.lo.slope, root_minus_a * m.lo.root)) /
                              root_minus_a);
    }
    return m;
  }

  const SegmentKernelSpec spec_;
  StraightLineProgram program_;
  std::array<symbol, 3> A_, B_, P_;
  // P's trailing part where P is a double-word number P_ + point_lo_
  // (polygon edges: the foot P̄); 0 for segments.
  std::array<ex, 3> point_lo_{0, 0, 0};
  std::vector<ex> w_;
  std::array<ex, 3> ab_, ap_, bp_, cross_;
  ex ab_ab_, ab_ap_, ap_ap_, cross_cross_, bp_bp_, ab_bp_, ap_bp_, length_;
  // Whether the gradient's t* = b/a is the foot of P on AB (true for
  // segments: α scales a and b alike), so that define_exact_cross also
  // gives H; set before build() by the builders, false where it is not.
  bool gradient_needs_foot_ = false;
  std::optional<std::array<ex, 3>> foot_;
  ex alpha_, beta_, inv_R_, radius_;
  // Compact kernels: the forms of push_support_root_alternatives, which
  // read the segment's geometry (A, B, P, R); off for polygon edges.
  bool support_root_forms_ = true;
  ex a_, b_, c_, D_, a_minus_b_;
  // Compact kernels: c as their Gauss rules read it, and q, √q at the ends
  // of the same quadratic for G_E by parts (define_rule_constant).
  ex rule_c_;
  std::optional<PartsEnds> rule_ends_;
  ex a_minus_b_value_, q1_value_, c_minus_b_value_;  // set by define_quadratic
  ex output_scale_ = 1;                              // multiplies f and ∇f (σ^i for SCALIS)
  bool high_moments_by_panels_ = false;              // SCALIS: see choose_moments
  std::vector<std::pair<symbol, ex>> lazy_steps_;    // definitions only some forms read (choose)
  std::vector<MomentRequest> requests_;               // what choose_moments computes
  MomentSymbols symbols_;                             // the base symbols it defined
};


}  // namespace skelconv::codegen
