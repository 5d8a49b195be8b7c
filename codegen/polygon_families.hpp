// codegen/polygon_families.hpp — the polygon edge kernels, described once.
//
// The field of a planar polygon, C(P) = ∬_Ω K(|P − Q|) dQ, is by Green's
// theorem a sum over the edges of the fan triangles (P̄, Q_m, Q_{m+1})
// (Hubert 2012 §5, docs/mathematics.md §3). In polar coordinates about P̄ the radial
// integral has a closed form, and what is left on edge m, with h_m the
// doubled signed fan area and θ_m the angle it subtends, is for
// K = (α r² + β)^(−i/2) (inverse α = 1, β = 0; Cauchy α = s, β = 1) and
// ζ² = α z² + β:
//
//     C   = (ζ^(2−i) Θ − Σ_m H_{i−2,m}) / (α (i − 2)),    Θ = Σ_m θ_m ∈ {0, 2π}
//     H_n = α h ∫_0^1 dt / (α ρ(t)² q(t)^(n/2)),           q = α|P − Γ(t)|² + β
//
// with ρ the in-plane distance from P̄ (Hubert §6–7: our H_n are his
// recurrence written per edge). H_0 = θ, H_1 has a closed form (one atan2),
// and since α ρ² = q − ζ²,
//
//     H_n = (H_{n−2} − α h J_n) / ζ²        (upwards; J_n = ∫ q^(−n/2) dt)
//
// which divides by ζ² → 0 near the plane; there (ζ² ≤ q_min/2) each H_n is
// instead the integral in the edge's angle φ, smooth and done by a 20-point
// Gauss–Legendre rule (skelconv/detail/polygon_angle_integrals.hpp), exact to rounding.
// ∇C needs no new integrals: in the plane −Σ_m (E_m × n) J_{i,m} (the
// divergence theorem: the edges' own segment fields), along n
// −z (ζ^(−i) Θ − Σ_m H_{i,m}) (the polygon of degree i + 2).
//
// Compact k_R^{2j} (Hubert §8) is the same algebra with α = −1/R², β = 1,
// i → −2j and w = ζ² = 1 − z²/R²: the radial integral is a polynomial inside
// the support disc (radius √(R² − z²) about P̄) and constant outside, so
//
//     C = (R²/(2(j+1))) (w^(j+1) Θ − Σ_m G^(j+1)_m),   G^(p) = h ∫ q^p/ρ² dt
//
// over the part of each edge inside the disc, ∂C/∂z = −z (w^j Θ − Σ_m G^(j)_m).
// With q = w − ρ²/R², G^(p) = w^p θ_in − (h/R²) Σ_{k<p} w^k J_{−2(p−1−k)}
// (θ_in the angle of the clipped part, J_{−2l} = ∫ q^l exactly by Gauss–
// Legendre); near the disc's rim, where that cancels, G^(p) is an angle
// integral instead. This is the third sum of Hubert §8.2 (garbled in the
// OCR), derived from G^K of §8.1; the verifier confirms it by quadrature.
#pragma once

#include <string>

#include <skelconv/primitives/segment_input.hpp>

#include "segment_families.hpp"
#include "straight_line_program.hpp"

namespace skelconv::codegen {

/// One generated polygon edge kernel: a family and a degree i (for compact
/// kernels i = 2j, even).
struct PolygonKernelSpec {
  KernelFamily family;
  int degree;

  std::string name() const;      ///< e.g. polygon_edge_cauchy_i4
  std::string equation() const;  ///< the definition it serves, as text
};

/// The straight-line program writing the edge's terms (PolygonEdgeTerms)
/// that `outputs` needs.
StraightLineProgram build_polygon_edge_program(const PolygonKernelSpec& spec, SegmentOutputs outputs);

}  // namespace skelconv::codegen
