// codegen/segment_families.cpp — see segment_families.hpp.
#include "segment_families.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "generated_families.hpp"
#include "segment_program_builder.hpp"

namespace skelconv::codegen {

REGISTER_FUNCTION(nonnegative_part, dummy())
REGISTER_FUNCTION(minimum, dummy())
REGISTER_FUNCTION(maximum, dummy())

namespace {

std::string weight_text(int weight_degree) {
  if (weight_degree == 0) return "w0";
  std::string s = "(w0";
  for (int k = 1; k <= weight_degree; ++k) s += " + w" + std::to_string(k) + (k == 1 ? " t" : " t^" + std::to_string(k));
  return s + ")";
}

// SCALIS segment (docs/mathematics.md §4, Zanni 2013 Table 3): with the radius
// τ(t) = τ0 + Δτ t and scale σ, both the inverse and the Cauchy kernel give
//     F = σ^i |AB| ∫_0^1 τ(t)^(i−1) q(t)^(−i/2) dt,
//     q = |P − Γ(t)|² + s2 τ(t)²,   s2 = σ² (Cauchy), 0 (inverse),
// a weighted segment integral with w(t) = τ(t)^(i−1) (the factor σ^i is
// applied to the outputs). For Cauchy, q is the squared distance in 4-D
// between P' = (P, 0) and Γ'(t) = (Γ(t), σ τ(t)), so D = ac − b² is, by
// Lagrange's identity there, |AB × AP|² + σ²|τ0 AB + Δτ AP|²: a sum of
// squares. The ends are swapped so that Δτ ≥ 0 (the field is symmetric):
// then every coefficient C(i−1,k) τ0^(i−1−k) Δτ^k of w is ≥ 0 and the
// weighted sums do not cancel. No division by τ0 or Δτ: a cone (τ0 = 0)
// and a cylinder (Δτ = 0) take the same code.
class ScalisSegmentProgramBuilder : public SegmentProgramBuilder {
 public:
  explicit ScalisSegmentProgramBuilder(const ScalisKernelSpec& scalis)
      : SegmentProgramBuilder(SegmentKernelSpec{scalis.family, scalis.degree, scalis.degree - 1}) {
    high_moments_by_panels_ = true;
  }

 private:
  void read_inputs() override {
    for (int i = 0; i < 3; ++i) {
      A_[i] = input("A", "end_a", i);
      B_[i] = input("B", "end_b", i);
      P_[i] = input("P", "in.p", i);
    }
    const symbol tau_lo("tau_lo"), tau_hi("tau_hi"), sigma("sigma");
    program_.add_input(tau_lo, "tau_lo");
    program_.add_input(tau_hi, "tau_hi");
    program_.add_input(sigma, "in.sigma");
    tau0_ = tau_lo;
    tau1_ = tau_hi;
    delta_tau_ = define("delta_tau", tau_hi - tau_lo);
    const int top = spec_.degree - 1;
    for (int k = 0; k <= top; ++k)
      w_.push_back(GiNaC::binomial(numeric(top), numeric(k)) * pow(tau0_, top - k) * pow(delta_tau_, k));
    output_scale_ = pow(sigma, spec_.degree);
    if (spec_.family == KernelFamily::cauchy) {
      sigma2_ = define("sigma2", pow(sigma, 2));
      // σ^i from the σ² the quadratic already has.
      output_scale_ = pow(sigma2_, spec_.degree / 2) * (spec_.degree % 2 == 0 ? ex(1) : ex(sigma));
    }
  }

  // Cauchy: b/a includes the σ²τ terms, so t* is not the foot t⊥ of P:
  // t⊥ − t* = AB·AP/|AB|² − (AB·AP − σ²Δτ τ0)/(|AB|² + σ²Δτ²)
  //         = σ²Δτ (τ0 |AB|² + Δτ AB·AP) / (|AB|² a),
  // the last factor AB·(τ0 AB + Δτ AP), the radial vector of D.
  ex foot_offset() const override {
    if (spec_.family != KernelFamily::cauchy) return 0;
    return sigma2_ * delta_tau_ * (tau0_ * ab_ab_ + delta_tau_ * ab_ap_) / (ab_ab_ * a_);
  }

  void define_quadratic() override {
    alpha_ = 1;
    beta_ = 0;
    const ex& s2 = sigma2_;
    a_ = define("a", ab_ab_ + s2 * pow(delta_tau_, 2));
    b_ = define("b", ab_ap_ - s2 * delta_tau_ * tau0_);
    c_ = define("c", ap_ap_ + s2 * pow(tau0_, 2));
    if (spec_.family == KernelFamily::cauchy) {
      std::array<ex, 3> v;  // τ0 AB + Δτ AP
      for (int i = 0; i < 3; ++i) v[i] = define("radial" + std::to_string(i), tau0_ * ab_[i] + delta_tau_ * ap_[i]);
      D_ = define("D", cross_cross_ + s2 * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
    } else {
      D_ = define("D", cross_cross_);
    }
    a_minus_b_value_ = -ab_bp_ + s2 * delta_tau_ * tau1_;  // a − b
    q1_value_ = bp_bp_ + s2 * pow(tau1_, 2);               // q(1) = |BP|² + σ²τ1²
    c_minus_b_value_ = ap_bp_ + s2 * tau0_ * tau1_;        // c − b
  }

  ex tau0_, tau1_, delta_tau_, sigma2_ = 0;
};

}  // namespace

std::string SegmentKernelSpec::name() const {
  return "segment_" + std::string(family_name(family)) + "_i" + std::to_string(degree) + "_w" +
         std::to_string(weight_degree);
}

std::string SegmentKernelSpec::equation() const {
  const GeneratedFamily& row = generated_family(family);
  return std::string("f(P) = |AB| ∫_") + (row.compact_support ? "t0^t1 " : "0^1 ") + weight_text(weight_degree) + " " +
         kernel_text(row, "P − Γ(t)", degree) + " dt";
}

StraightLineProgram build_segment_program(const SegmentKernelSpec& spec, SegmentOutputs outputs) {
  return SegmentProgramBuilder(spec).build(outputs);
}

std::string ScalisKernelSpec::name() const {
  return "scalis_segment_" + std::string(family_name(family)) + "_i" + std::to_string(degree);
}

std::string ScalisKernelSpec::equation() const {
  const std::string i = std::to_string(degree);
  const std::string kernel = family == KernelFamily::cauchy ? "(1 + (d/σ)²)^(−" + i + "/2)" : "(d/σ)^(−" + i + ")";
  return "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = " + kernel +
         ", τ(t) = τ0 + (τ1 − τ0) t  [= σ^" + i + " |AB| ∫_0^1 τ^" + std::to_string(degree - 1) + " (|P − Γ|²" +
         (family == KernelFamily::cauchy ? " + σ²τ²" : "") + ")^(−" + i + "/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]";
}

StraightLineProgram build_scalis_segment_program(const ScalisKernelSpec& spec, SegmentOutputs outputs) {
  if (spec.family == KernelFamily::compact) throw std::logic_error("SCALIS compact segments are not generated");
  if (spec.degree < 2) throw std::logic_error("SCALIS degrees start at 2");
  return ScalisSegmentProgramBuilder(spec).build(outputs);
}

}  // namespace skelconv::codegen
