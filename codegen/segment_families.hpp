// codegen/segment_families.hpp — the segment kernel families, described once.
//
// Every family of SPEC §1 writes its kernel as a power of a quadratic in the
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
// which shares its base terms with f = |AB| Σ_k w_k M_{k,n} (SPEC §2).
#pragma once

#include <string>

#include <skelconv/segment_input.hpp>

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

}  // namespace skelconv::codegen
