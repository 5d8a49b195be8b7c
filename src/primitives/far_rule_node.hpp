// src/primitives/far_rule_node.hpp — one Gauss–Legendre node of a far rule
// (far_segment_rule.hpp) on every lane of a vector of doubles, shared by the
// per-segment rule (far_segment_rule.cpp: two nodes of one segment in
// SSE2's two lanes) and the batch (far_rule_batch.cpp: one node of two
// segments in SSE2, or two nodes of two segments in AVX's four lanes): the
// same operations in the same order on every lane, hence the same bits.
// Written with GCC's vector operators (what _mm_add_pd and the others are
// in GCC's headers) so that one definition serves __m128d and __m256d; a
// lane's value never depends on the vector's width, as long as no product
// and sum are fused (the AVX code is compiled without FMA).
// Internal to skelconv_runtime.
#pragma once

#include <emmintrin.h>
#include <immintrin.h>  // __m256d (its operations need AVX, which the caller enables)

namespace skelconv::detail::far_rule {

/// The vector of `Lanes` doubles: SSE2's (2) or AVX's (4).
template <int Lanes>
struct LaneVector;
template <>
struct LaneVector<2> {
  using type = __m128d;
};
template <>
struct LaneVector<4> {
  using type = __m256d;
};

/// Every lane of V (__m128d, __m256d) set to x.
template <class V>
[[gnu::always_inline]] inline V lanes_of(double x) {
  V v;
  for (int lane = 0; lane < int(sizeof(V) / sizeof(double)); ++lane) v[lane] = x;
  return v;
}

/// √x on every lane (correctly rounded): SSE2's sqrtpd, on each half of
/// AVX's four lanes (AVX's own intrinsic would need AVX code here).
[[gnu::always_inline]] inline __m128d lanes_sqrt(__m128d x) { return _mm_sqrt_pd(x); }
template <class V>  // __m256d (a template: only code that uses AVX's lanes compiles it)
[[gnu::always_inline]] inline V lanes_sqrt(V x) {
  const __m128d low = _mm_sqrt_pd(__builtin_shufflevector(x, x, 0, 1));
  const __m128d high = _mm_sqrt_pd(__builtin_shufflevector(x, x, 2, 3));
  return __builtin_shufflevector(low, high, 0, 1, 2, 3);
}

/// x^(I/2) from x, on every lane: from 1, I/2 products, and √x for odd I.
template <int I, class V>
[[gnu::always_inline]] inline V lanes_half_power(V x) {
  V result = lanes_of<V>(1.0);
  for (int k = 0; k < I / 2; ++k) result = result * x;
  if constexpr (I % 2 == 1) result = result * lanes_sqrt(x);
  return result;
}

/// What a node reads of its segment, per lane: P − A and B − A; the
/// classical sharpness s and weight coefficients w[0 … weight_degree]; the
/// SCALIS c0, c1 (c = c0 + c1 t).
template <int Lanes>
struct NodeSegmentOf {
  using V = typename LaneVector<Lanes>::type;
  V pa_x, pa_y, pa_z, ab_x, ab_y, ab_z;
  V sharpness, c0, c1;
  const V* w;
  int weight_degree;
};
using NodeSegment = NodeSegmentOf<2>;

/// Adds the node at t with Gauss weight g (per lane) to f and, with
/// `Gradient`, to ∇f's sums: classical Q̂ = 1 + s r², ω̂ the weight
/// polynomial; SCALIS Q̂ = r² + c², ω̂ = c^(I−1); the term g ω̂ Q̂^(−I/2),
/// and for ∇f the term Q̂^(−1) (P − Γ(t)).
template <int I, bool Gradient, bool Scalis, int Lanes, class V = typename LaneVector<Lanes>::type>
[[gnu::always_inline]] inline void add_node(V t, V g, const NodeSegmentOf<Lanes>& s, V& f, V& g_x, V& g_y, V& g_z) {
  const V one = lanes_of<V>(1.0);
  const V x = s.pa_x - t * s.ab_x;
  const V y = s.pa_y - t * s.ab_y;
  const V z = s.pa_z - t * s.ab_z;
  const V r2 = (x * x + y * y) + z * z;
  V weight = g;
  V inverse;
  if constexpr (Scalis) {
    const V c = s.c0 + t * s.c1;
    inverse = one / (r2 + c * c);
    for (int k = 1; k < I; ++k) weight = weight * c;
  } else {
    inverse = one / (one + s.sharpness * r2);
    if (s.weight_degree > 0) {
      V polynomial = s.w[s.weight_degree];
      for (int k = s.weight_degree - 1; k >= 0; --k) polynomial = polynomial * t + s.w[k];
      weight = weight * polynomial;
    }
  }
  const V term = weight * lanes_half_power<I>(inverse);
  f = f + term;
  if constexpr (Gradient) {
    const V slope = term * inverse;
    g_x = g_x + slope * x;
    g_y = g_y + slope * y;
    g_z = g_z + slope * z;
  }
}

}  // namespace skelconv::detail::far_rule
