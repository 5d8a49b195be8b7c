// skelconv/scalis_compact.hpp — the SCALIS segment with the compact kernel
// K(d) = (1 − (d/σ)²)^(i/2) for d < σ, σ > 1 (SPEC §4, Zanni 2013 §3–4).
//
// STUB: the evaluator is written on another branch; this header only fixes
// the signature ScalisSegment calls, and the merge replaces it.
#pragma once

#include <array>
#include <stdexcept>

#include "skelconv/scalis_segment_input.hpp"

namespace skelconv {

/// The unnormalised F(P) of skelconv/scalis_segment_input.hpp for the compact
/// kernel of degree `degree`; writes ∇_P F to *grad when grad is not null.
template <class T>
T scalis_compact_F(int degree, const ScalisSegmentInput<T>& in, std::array<T, 3>* grad) {
  (void)degree;
  (void)in;
  (void)grad;
  throw std::logic_error("not implemented");
}

}  // namespace skelconv
