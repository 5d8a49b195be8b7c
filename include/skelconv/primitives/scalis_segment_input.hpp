// skelconv/primitives/scalis_segment_input.hpp — the contract between the runtime and
// the SCALIS segment kernels (docs/mathematics.md §4, Zanni et al. 2013 §3–4).
//
// A SCALIS segment [A,B] has the radius τ(t) = τ0 + (τ1 − τ0) t, t ∈ [0, 1],
// and the SCALIS kernel K of docs/mathematics.md §1 with scale σ. Every SCALIS segment
// function computes the UNNORMALISED field
//
//     F(P) = ∫_0^1 K(|P − Γ(t)| / τ(t)) |AB| dt / τ(t),   Γ(t) = A + t (B − A)
//
// and/or ∇_P F. The runtime multiplies by c / h (docs/mathematics.md §4) so that f = c at
// distance τ from an infinite line of constant radius τ.
#pragma once

#include <array>

namespace skelconv {

/// Inputs of one SCALIS segment evaluation, on scalar type T.
template <class T>
struct ScalisSegmentInput {
  std::array<T, 3> a{};  ///< segment start A (t = 0)
  std::array<T, 3> b{};  ///< segment end B (t = 1)
  std::array<T, 3> p{};  ///< query point P
  T tau0 = T(1);         ///< radius at A, ≥ 0
  T tau1 = T(1);         ///< radius at B, ≥ 0 (not both 0)
  T sigma = T(1);        ///< kernel scale σ > 0 (> 1 for the compact kernel)
};

/// The same input on scalar type U, field by field (exact when U is at least
/// as wide as T): to evaluate one point in several precisions.
template <class U, class T>
ScalisSegmentInput<U> convert_scalar(const ScalisSegmentInput<T>& in) {
  ScalisSegmentInput<U> out;
  for (int c = 0; c < 3; ++c) {
    out.a[c] = U(in.a[c]);
    out.b[c] = U(in.b[c]);
    out.p[c] = U(in.p[c]);
  }
  out.tau0 = U(in.tau0);
  out.tau1 = U(in.tau1);
  out.sigma = U(in.sigma);
  return out;
}

}  // namespace skelconv
