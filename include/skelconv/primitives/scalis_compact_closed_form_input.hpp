// skelconv/primitives/scalis_compact_closed_form_input.hpp — the contract
// between the compact SCALIS segment (skelconv/primitives/scalis_compact.hpp)
// and its generated closed forms (generated/scalis_segment_compact.hpp,
// written by codegen/scalis_compact_writer.cpp) for even degrees i = 2m.
//
// On the support [t1, t2] (where Q = σ²τ² − |PΓ|² > 0) with x = (t − t1)/w,
// w = t2 − t1, the runtime hands over Q in Bernstein form,
//     Q = b0 (1 − x)² + 2 b1 x (1 − x) + b2 x²,   b0, b1, b2 ≥ 0,
// and τ(t) = τ(t1) (1 + λ x), λ = Δτ w / τ(t1) ≥ 0 (the segment oriented so
// that Δτ ≥ 0). The closed forms return the three integrals the field and its
// gradient are made of (scalis_compact.hpp, section 3 of its comment):
//     f  = ∫ ξ^m / τ dt,   g0 = ∫ ξ^(m−1) / τ³ dt,   g1 = ∫ (t − t*) ξ^(m−1) / τ³ dt
// over [t1, t2], with ξ = Q / (σ²τ²) and t* the foot of P on the line AB.
#pragma once

namespace skelconv {

/// The support of one compact SCALIS evaluation, in the segment's scaled,
/// oriented frame (scalis_compact_support.hpp).
template <class T>
struct ScalisCompactSupport {
  T width;        ///< w = t2 − t1 > 0
  T tau_lo;       ///< τ(t1) > 0
  T tau_hi;       ///< τ(t2) = τ(t1) + rise
  T rise;         ///< Δτ w ≥ 0 (formed as a product: no difference of radii)
  T b0, b1, b2;   ///< Q's Bernstein coefficients on [t1, t2], all ≥ 0
  T e0, e1;       ///< t1 − t*, t2 − t*
  T inv_sigma2;   ///< 1/σ²
};

/// What the closed forms compute (only f, only g0 and g1, or all three).
template <class T>
struct ScalisCompactIntegrals {
  T f;
  T g0;
  T g1;
};

}  // namespace skelconv
