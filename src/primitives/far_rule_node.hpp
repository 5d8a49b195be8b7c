// src/primitives/far_rule_node.hpp — one Gauss–Legendre node of a far rule
// (far_segment_rule.hpp) on both SSE2 lanes, shared by the per-segment
// rule (far_segment_rule.cpp: two nodes of one segment) and the batch
// (far_rule_batch.cpp: one node of two segments): the same operations in
// the same order either way, hence the same bits.
// Internal to skelconv_runtime.
#pragma once

#include <emmintrin.h>

namespace skelconv::detail::far_rule {

/// x^(I/2) from x, on both lanes: from 1, I/2 products, and √x for odd I.
template <int I>
[[gnu::always_inline]] inline __m128d lanes_half_power(__m128d x) {
  __m128d result = _mm_set1_pd(1.0);
  for (int k = 0; k < I / 2; ++k) result = _mm_mul_pd(result, x);
  if constexpr (I % 2 == 1) result = _mm_mul_pd(result, _mm_sqrt_pd(x));
  return result;
}

/// What a node reads of its segment, per lane: P − A and B − A; the
/// classical sharpness s and weight coefficients w[0 … weight_degree]; the
/// SCALIS c0, c1 (c = c0 + c1 t).
struct NodeSegment {
  __m128d pa_x, pa_y, pa_z, ab_x, ab_y, ab_z;
  __m128d sharpness, c0, c1;
  const __m128d* w;
  int weight_degree;
};

/// Adds the node at t with Gauss weight g (per lane) to f and, with
/// `Gradient`, to ∇f's sums: classical Q̂ = 1 + s r², ω̂ the weight
/// polynomial; SCALIS Q̂ = r² + c², ω̂ = c^(I−1); the term g ω̂ Q̂^(−I/2),
/// and for ∇f the term Q̂^(−1) (P − Γ(t)).
template <int I, bool Gradient, bool Scalis>
[[gnu::always_inline]] inline void add_node(__m128d t, __m128d g, const NodeSegment& s, __m128d& f, __m128d& g_x,
                                            __m128d& g_y, __m128d& g_z) {
  const __m128d one = _mm_set1_pd(1.0);
  const __m128d x = _mm_sub_pd(s.pa_x, _mm_mul_pd(t, s.ab_x));
  const __m128d y = _mm_sub_pd(s.pa_y, _mm_mul_pd(t, s.ab_y));
  const __m128d z = _mm_sub_pd(s.pa_z, _mm_mul_pd(t, s.ab_z));
  const __m128d r2 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(x, x), _mm_mul_pd(y, y)), _mm_mul_pd(z, z));
  __m128d weight = g;
  __m128d inverse;
  if constexpr (Scalis) {
    const __m128d c = _mm_add_pd(s.c0, _mm_mul_pd(t, s.c1));
    inverse = _mm_div_pd(one, _mm_add_pd(r2, _mm_mul_pd(c, c)));
    for (int k = 1; k < I; ++k) weight = _mm_mul_pd(weight, c);
  } else {
    inverse = _mm_div_pd(one, _mm_add_pd(one, _mm_mul_pd(s.sharpness, r2)));
    if (s.weight_degree > 0) {
      __m128d polynomial = s.w[s.weight_degree];
      for (int k = s.weight_degree - 1; k >= 0; --k) polynomial = _mm_add_pd(_mm_mul_pd(polynomial, t), s.w[k]);
      weight = _mm_mul_pd(weight, polynomial);
    }
  }
  const __m128d term = _mm_mul_pd(weight, lanes_half_power<I>(inverse));
  f = _mm_add_pd(f, term);
  if constexpr (Gradient) {
    const __m128d slope = _mm_mul_pd(term, inverse);
    g_x = _mm_add_pd(g_x, _mm_mul_pd(slope, x));
    g_y = _mm_add_pd(g_y, _mm_mul_pd(slope, y));
    g_z = _mm_add_pd(g_z, _mm_mul_pd(slope, z));
  }
}

}  // namespace skelconv::detail::far_rule
