// codegen/segment_families.hpp — the segment kernel families, described once.
//
// Every family of docs/mathematics.md §1 writes its kernel as a power of a quadratic in the
// squared distance, K = (α |P − Γ(t)|² + β)^(−n/2):
//
//     inverse p^i    α = 1,      β = 0,  n = i
//     Cauchy  c_s^i  α = s,      β = 1,  n = i
//     compact k_R^i  α = −1/R²,  β = 1,  n = −i   (on the clipped [t0, t1])
//
// so q(t) = a t² − 2 b t + c has a = α|AB|², b = α AB·AP, c = β + α|AP|²
// (Hubert 2012 §3.2–3.4), and differentiating under the integral gives
//
//     ∇f = −n α |AB| ( AP Σ_k w_k M_{k,n+2} − AB Σ_k w_k M_{k+1,n+2} )
//
// which shares its base terms with f = |AB| Σ_k w_k M_{k,n} (docs/mathematics.md §2).
#pragma once

#include <string>

#include <skelconv/primitives/segment_input.hpp>

#include "straight_line_program.hpp"

namespace skelconv::codegen {

/// One generated segment kernel: a family, a degree i and a weight degree.
struct SegmentKernelSpec {
  KernelFamily family;
  int degree;
  int weight_degree;

  std::string name() const;      ///< e.g. segment_cauchy_i4_w1
  std::string equation() const;  ///< the definition it implements, as text
};

/// Which outputs a generated function writes.
enum class SegmentOutputs { value, gradient, value_and_gradient };

/// The straight-line program computing `outputs` for `spec`. The outputs are
/// the C++ lvalues `f` and `grad[0..2]`.
StraightLineProgram build_segment_program(const SegmentKernelSpec& spec, SegmentOutputs outputs);

/// One generated SCALIS segment kernel (docs/mathematics.md §4, Zanni 2013 §3–4): the
/// inverse or Cauchy family, degree i ≥ 2, radius τ(t) = τ0 + (τ1 − τ0) t.
/// It is the segment kernel of degree i with the weight σ^i τ(t)^(i−1) and,
/// for Cauchy, q(t) = |P − Γ(t)|² + σ²τ(t)² (the same choices of stable
/// forms); its functions read ScalisSegmentInput and refer to the locals
/// end_a, end_b, tau_lo, tau_hi, the ends ordered so that tau_lo ≤ tau_hi.
struct ScalisKernelSpec {
  KernelFamily family;  ///< inverse or cauchy
  int degree;

  std::string name() const;      ///< e.g. scalis_segment_cauchy_i4
  std::string equation() const;  ///< the definition it implements, as text
};

StraightLineProgram build_scalis_segment_program(const ScalisKernelSpec& spec, SegmentOutputs outputs);

}  // namespace skelconv::codegen
