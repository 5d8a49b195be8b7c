// codegen/polygon_families.cpp — see polygon_families.hpp.
#include "polygon_families.hpp"

#include <map>
#include <stdexcept>

#include "generated_families.hpp"
#include "segment_program_builder.hpp"

namespace skelconv::codegen {

namespace {

// Near the plane, where ζ² ≤ q_min / kNearPlaneRatio (q_min the smaller end
// value of q), the upward recurrence for H_n would multiply rounding errors
// by ≥ kNearPlaneRatio a step; the angle integral of
// polygon_angle_integrals.hpp is used instead, when also αd² ≥ ζ²
// (D ≥ kNearPlaneRatio a ζ²: its integrand's singularities are then
// ≥ asinh 1 ≈ 0.88 away from the real axis) or the foot of P̄ is on the edge.
const ex kNearPlaneRatio = numeric(2);
// Compact kernels: the closed form G^(p) = w^p θ_in − … is used for a chord
// that comes within √kChordRimRatio of the support disc's radius of P̄.
const ex kChordRimRatio = numeric(1, 4);
// Compact kernels: a vertex Q with |P − Q|² ≥ (1 + kClearlyOutside) R² in
// plain arithmetic (from P and Q themselves, a relative error of a few ε
// wherever they lie) is outside the support ball for sure: its exact support
// gap is negative, and the chord form, which reads only max(0, gap), needs
// no exact value there.
const ex kClearlyOutside = numeric(1, 16);

// A polygon edge is a segment from Q_m to Q_{m+1} seen from P̄, whose
// quadratic has the constant term ζ² = β + α z² instead of β: everything
// else (geometry, J_n and their stable forms) is the segment's.
class PolygonEdgeProgramBuilder : public SegmentProgramBuilder {
 public:
  explicit PolygonEdgeProgramBuilder(const SegmentKernelSpec& edge_spec) : SegmentProgramBuilder(edge_spec) {
    support_root_forms_ = false;  // they read a segment's A, B, P, R; an edge's q has the term α z²
  }

  StraightLineProgram build(SegmentOutputs outputs) {
    read_inputs();
    define_geometry();
    define_quadratic();
    value_ = outputs != SegmentOutputs::gradient;
    gradient_ = outputs != SegmentOutputs::value;
    // h = ((Q_m − P̄) × E)·n; cross = AB × AP = (Q_m − P̄) × E.
    h_ = define("h", normal_[0] * cross_[0] + normal_[1] * cross_[1] + normal_[2] * cross_[2]);
    // θ = atan2(h, (Q_m − P̄)·(Q_{m+1} − P̄)), and AP·BP is that dot product.
    program_.add_output("out.h", h_);
    theta_ = define("theta", GiNaC::atan2(h_, ap_bp_));
    program_.add_output("out.theta", theta_);
    if (generated_family(spec_.family).compact_support)
      build_compact();
    else
      build_infinite_support();
    return std::move(program_);
  }

 private:
  void read_inputs() override {
    for (int i = 0; i < 3; ++i) {
      A_[i] = input("A", "in.a", i);
      B_[i] = input("B", "in.b", i);
      P_[i] = input("P", "in.p", i);
      // P̄'s rounding (PolygonEdgeInput::p_lo), for the kernels that are
      // not clipped: a compact edge's clip [t0, t1] comes from the rounded
      // P̄ (clip_to_ball), and its q(t0), q(t1) must vanish with it.
      if (!generated_family(spec_.family).compact_support) point_lo_[i] = input("P_lo", "in.p_lo", i);
      normal_[i] = input("n", "in.normal", i);
    }
    if (generated_family(spec_.family).compact_support)
      for (int i = 0; i < 3; ++i) point_[i] = input("X", "in.point", i);
    z_ = symbol("z");
    program_.add_input(z_, "in.z");
    w_.push_back(1);  // no weight
  }

  void adjust_beta() override { beta_ = define("zeta2", beta_ + alpha_ * pow(z_, 2)); }

  // Inverse and Cauchy: f needs H_{i−2}, ∇f needs H_i and J_i.
  void build_infinite_support() {
    const int i = spec_.degree;
    const bool odd = i % 2 != 0;
    const int lowest_J = odd ? 3 : 2;
    const int highest_H = gradient_ ? i : i - 2;
    std::vector<MomentRequest> requests;
    for (int m = lowest_J; m <= highest_H; m += 2) requests.push_back({"J_" + std::to_string(m), 0, m});
    std::vector<symbol> J;
    if (!requests.empty()) {
      J = choose_moments(requests);
    } else {
      symbols_ = infinite_support_symbols();  // f of i = 3 reads only H_1
    }
    auto J_at = [&](int m) { return J[static_cast<size_t>((m - lowest_J) / 2)]; };

    const ex zeta2 = beta_;
    const ex alpha_h = define("alpha_h", alpha_ * h_);
    const ex slope0 = symbols_.lo.slope, slope1 = symbols_.hi.slope;  // a t − b at t = 0, 1
    const int lowest_H = value_ ? i - 2 : i;

    std::vector<symbol> targets;
    if (value_) targets.emplace_back("H_f");
    if (gradient_) targets.emplace_back("H_g");
    Choice choice{targets, {}};
    {
      // Near the plane compared with the edge (ζ² ≤ q_min/2, q_min the least
      // q on the edge; kNearPlaneRatio = 2): H_n as an angle integral, every
      // level in one call.
      const ex vertex_term = maximum(D_ - kNearPlaneRatio * a_ * zeta2, -b_ * a_minus_b_);
      Alternative near{{minimum(symbols_.lo.q, symbols_.hi.q) - kNearPlaneRatio * zeta2, vertex_term},
                       "near the plane (ζ² ≤ q_min/2): H_n = sgn(h) ∫ q(φ)^(−n/2) dφ over the edge's angle, "
                       "polygon_edge_H_near_plane (20-point Gauss–Legendre)",
                       {}, {}, {}};
      ArrayCall call{"H_near", "polygon_edge_H_near_plane<T>", {std::to_string(lowest_H), std::to_string(highest_H)},
                     {alpha_h, a_, zeta2, slope0, slope1}, {}, helper_costs::polygon_H_near_plane(lowest_H, highest_H)};
      for (int n = lowest_H; n <= highest_H; n += 2)
        call.elements.emplace_back("H_near_" + std::to_string(call.elements.size()));
      if (value_) near.values.push_back(call.elements.front());
      if (gradient_) near.values.push_back(call.elements.back());
      near.calls.push_back(std::move(call));
      choice.alternatives.push_back(std::move(near));
    }
    {
      // Upwards from H_0 = θ or H_1, H_n = (H_{n−2} − α h J_n)/ζ².
      Alternative upward{{}, "H_n = (H_{n−2} − α h J_n)/ζ² upwards from H_" + std::string(odd ? "1" : "0"), {}, {}, {}};
      std::map<int, ex> H;  // H_n by level
      if (odd) {
        // H_1 = [atan(ζ (a t − b) / (α h √q))]_0^1 / ζ, the two atans in one atan2.
        const symbol zeta("zeta"), H1("H1");
        upward.steps.emplace_back(zeta, pow(zeta2, numeric(1, 2)));
        const ex r0 = symbols_.lo.root, r1 = symbols_.hi.root;
        upward.steps.emplace_back(
            H1, GiNaC::atan2(alpha_h * zeta * (slope1 * r0 - slope0 * r1),
                             pow(alpha_h, 2) * r0 * r1 + zeta2 * slope0 * slope1) /
                    zeta);
        H[1] = H1;
      } else {
        H[0] = theta_;
      }
      for (int n = odd ? 3 : 2; n <= highest_H; n += 2) {
        const symbol Hn("H" + std::to_string(n));
        upward.steps.emplace_back(Hn, (H[n - 2] - alpha_h * J_at(n)) / zeta2);
        H[n] = Hn;
      }
      if (value_) upward.values.push_back(H[i - 2]);
      if (gradient_) upward.values.push_back(H[i]);
      choice.alternatives.push_back(std::move(upward));
    }
    choice.generic = choice.alternatives.size() - 1;
    program_.choose(std::move(choice));
    if (value_) program_.add_output("out.S_f", targets.front());
    if (gradient_) {
      program_.add_output("out.S_g", targets.back());
      program_.add_output("out.J_g", J_at(i));
    }
  }

  // Compact k_R^{2j}: G^(p) = h ∫_{t0}^{t1} q^p / ρ² dt for p = j + 1 (f) and
  // p = j (∂f/∂z), and J_{−2j} (in-plane ∇f), over the clipped [t0, t1].
  // Since q = w − ρ²/R², G^(p) = w^p θ_in − (h/R²) Σ_{k<p} w^k J_{−2(p−1−k)}
  // (θ_in the angle of [t0, t1] at P̄): exact, but when the chord lies near
  // the rim of the support disc (q ≪ w on it) the two terms cancel, up to
  // (w/q_max)^p. There the integral is taken directly in u = tan φ instead.
  void build_compact() {
    const int j = spec_.degree / 2;
    std::vector<MomentRequest> requests;
    for (int l = j; l >= 0; --l) requests.push_back({"J_minus" + std::to_string(2 * l), 0, -2 * l});
    const std::vector<symbol> J = choose_moments(requests);
    auto J_minus = [&](int l) { return J[static_cast<size_t>(j - l)]; };  // J_{−2l}
    const ex w = beta_;                 // ζ² = 1 − z²/R²
    const ex inv_R2 = -alpha_;          // 1/R²
    const ex t0 = symbols_.lo.t, t1 = symbols_.hi.t;
    // In-plane slopes |E|² t − E·(P̄ − A) at the clip's ends: tan φ = slope/|h|.
    const ex slope0 = define("plane_slope0", ab_ab_ * t0 - ab_ap_);
    const ex slope1 = define("plane_slope1", ab_ab_ * t1 - ab_ap_);
    const int p_lo = gradient_ ? j : j + 1, p_hi = value_ ? j + 1 : j;

    // Targets: θ_in and the rest of each G^(p), G^(p) − w^p θ_in, so that the
    // driver adds the θ_in of all edges to Θ before multiplying by w^p: a
    // support disc that holds the whole polygon then costs nothing.
    std::vector<symbol> targets{symbol("theta_in")};
    if (value_) targets.emplace_back("G_f");
    if (gradient_) targets.emplace_back("G_g");
    Choice choice{targets, {}};
    {
      // The chord comes within half the disc radius of P̄ (ρ_near² ≤ w R²/4,
      // with |E|² ρ² = h² + slope²): q_max ≥ 3w/4 on it, and the closed form
      // loses at most (4/3)^p (≤ 7.5 for p ≤ 7).
      const ex reach = kChordRimRatio * w * ab_ab_ - inv_R2 * pow(h_, 2);
      Alternative split{{reach, maximum(reach - inv_R2 * minimum(pow(slope0, 2), pow(slope1, 2)), -slope0 * slope1)},
                        "chord within half the disc radius of P̄: θ_in = atan2(…), "
                        "G^(p) − w^p θ_in = −(h/R²) Σ_k w^k J_{−2(p−1−k)}",
                        {}, {}, {}};
      // The clipped part's ends v0 = t0 AB − AP, v1 = −BP − (1 − t1) AB:
      // v0 × v1 = (t1 − t0) AB × AP and v0·v1 written so that an unclipped
      // edge (t0 = 0, t1 = 1) gives θ_in = θ bit for bit (Θ − Σ θ_in is then
      // exactly the angle outside the disc).
      const ex clip_dot = ap_bp_ + (1 - t1) * ab_ap_ - t0 * ab_bp_ - t0 * (1 - t1) * ab_ab_;
      split.values.push_back(GiNaC::atan2((t1 - t0) * h_, clip_dot));
      auto G_rest = [&](int p) {
        ex sum = 0;
        for (int k = 0; k < p; ++k) sum += pow(w, k) * J_minus(p - 1 - k);
        return -inv_R2 * h_ * sum;
      };
      if (value_) split.values.push_back(G_rest(j + 1));
      if (gradient_) split.values.push_back(G_rest(j));
      choice.alternatives.push_back(std::move(split));
    }
    {
      Alternative chord{{}, "chord near the rim of the support disc: G^(p) = sgn(h) ∫ q^p du/(1 + u²), u = tan φ, "
                            "polygon_edge_G_compact_chord (Gauss–Legendre panels)",
                        {}, {}, {}};
      // R² − |P − Q|² at the edge's ends from the exact inputs (support_gap.hpp):
      // q at an end the clip keeps, without the cancellation of w − ρ²/R².
      // The chord reads an end's gap only where the clip keeps that end
      // (t0 = 0 for A, t1 = 1 for B; the clip stays in [0, 1]), and only as
      // max(0, gap), so each exact gap is computed there only: a clipped
      // end costs nothing. An edge the disc misses has t0 = t1 = 0: its A
      // is skipped too where it is clearly outside the ball (kClearlyOutside).
      const ex clearly_outside_A = (1 + kClearlyOutside) * pow(radius_, 2) - pow(point_[0] - A_[0], 2) -
                                   pow(point_[1] - A_[1], 2) - pow(point_[2] - A_[2], 2);
      std::array<ArrayCall, 2> gaps;
      for (int end = 0; end < 2; ++end) {
        const std::array<symbol, 3>& q = end == 0 ? A_ : B_;
        gaps[end] = support_gap_call(end == 0 ? "gap_A" : "gap_B", "exact_point_support_gap<T>",
                                     {q[0], q[1], q[2], point_[0], point_[1], point_[2]},
                                     helper_costs::point_support_gap());
        gaps[end].guard = end == 0 ? std::vector<ex>{-t0, clearly_outside_A} : std::vector<ex>{t1 - 1};
      }
      ArrayCall call{"G_chord", "polygon_edge_G_compact_chord<T>", {std::to_string(p_lo), std::to_string(p_hi)},
                     {h_, ab_ab_, w, inv_R2, slope0, slope1, t0, t1, gaps[0].elements[0], gaps[1].elements[0]}, {},
                     helper_costs::polygon_G_compact_chord(p_lo, p_hi)};
      chord.calls.push_back(std::move(gaps[0]));
      chord.calls.push_back(std::move(gaps[1]));
      for (int p = p_lo; p <= p_hi; ++p) call.elements.emplace_back("G_chord_" + std::to_string(call.elements.size()));
      chord.values.push_back(0);
      if (value_) chord.values.push_back(call.elements.back());
      if (gradient_) chord.values.push_back(call.elements.front());
      chord.calls.push_back(std::move(call));
      choice.alternatives.push_back(std::move(chord));
    }
    choice.generic = 0;
    program_.choose(std::move(choice));
    program_.add_output("out.theta_in", targets.front());
    if (value_) program_.add_output("out.S_f", targets[1]);
    if (gradient_) {
      program_.add_output("out.S_g", targets.back());
      program_.add_output("out.J_g", J_minus(j));
    }
  }

  std::array<ex, 3> normal_;
  std::array<symbol, 3> point_;  // P itself (compact: the support gaps at the edge's ends)
  symbol z_;
  ex h_, theta_;
  bool value_ = true, gradient_ = true;
};

}  // namespace

std::string PolygonKernelSpec::name() const {
  return "polygon_edge_" + std::string(family_name(family)) + "_i" + std::to_string(degree);
}

std::string PolygonKernelSpec::equation() const {
  return "C(P) = ∬_Ω " + kernel_text(generated_family(family), "P − Q", degree) + " dQ";
}

StraightLineProgram build_polygon_edge_program(const PolygonKernelSpec& spec, SegmentOutputs outputs) {
  const GeneratedFamily& row = generated_family(spec.family);
  if (spec.degree < row.min_polygon_degree || (row.even_polygon_degrees && spec.degree % 2 != 0))
    throw std::invalid_argument(spec.name() + ": polygons take inverse/Cauchy i ≥ 3 and even compact i ≥ 2");
  const SegmentKernelSpec edge{spec.family, spec.degree, 0};
  return PolygonEdgeProgramBuilder(edge).build(outputs);
}

}  // namespace skelconv::codegen
