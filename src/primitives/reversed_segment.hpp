// src/primitives/reversed_segment.hpp — a segment read from its other end,
// for finite-support kernels evaluated near B.
//
// The generated compact closed forms (generated/segment_compact.hpp) measure
// everything from A: the squared distance on the support is a quadratic in t
// whose coefficients, c = 1 − |AP|²/R² and the others, are of size (|AB|/R)².
// For P near A they are O(1) on the support chord; for P near B they cancel
// from (|AB|/R)² down to O(1), and a thin support (R ≪ |AB|) loses digits
// there like ε (|AB|/R)² (up to 6e-11 relative at R = |AB|/100, 3e-3 at
// |AB|/10^6: tests/segment_thin_support_test.cpp). The same segment read from B — ends swapped, weight
// re-expanded as w(1 − t) — has P near its start and the same f and ∇_P f.
// The runtime evaluates from the end whose half of the segment holds P's
// foot on the line, so the closed form always works from the nearer end.
#pragma once

#include <array>

#include "skelconv/detail/double_word.hpp"
#include "skelconv/primitives/segment_input.hpp"

namespace skelconv::detail {

/// Whether P's foot on line AB lies beyond the segment's midpoint, on B's
/// side: 2 AB·AP > |AB|².
template <class T>
bool foot_on_b_half(const std::array<T, 3>& a, const std::array<T, 3>& b, const std::array<T, 3>& p) {
  T ab_ap = T(0), ab_ab = T(0);
  for (int c = 0; c < 3; ++c) {
    const T ab = b[c] - a[c];
    ab_ap += ab * (p[c] - a[c]);
    ab_ab += ab * ab;
  }
  return T(2) * ab_ap > ab_ab;
}

/// The coefficients v of w(1 − t) = Σ_j v_j t^j for w(t) = Σ_k w_k t^k:
/// v_j = (−1)^j Σ_{k ≥ j} C(k, j) w_k. Each sum is formed in double-word
/// arithmetic and rounded once, so a coefficient that nearly cancels (w(1)
/// small against the w_k) keeps the digits the given w_k define.
template <class T>
std::array<T, max_weight_degree + 1> reversed_weight(const std::array<T, max_weight_degree + 1>& w) {
  constexpr int n = max_weight_degree + 1;
  std::array<T, n> v{};
  for (int j = 0; j < n; ++j) {
    DoubleWord<T> sum{T(0), T(0)};
    T binomial = T(1);  // C(k, j), starting at k = j
    for (int k = j; k < n; ++k) {
      sum = word_add(sum, word_multiply(DoubleWord<T>{binomial, T(0)}, DoubleWord<T>{w[std::size_t(k)], T(0)}));
      binomial = binomial * T(k + 1) / T(k + 1 - j);  // C(k + 1, j), an exact small integer
    }
    const T rounded = sum.hi + sum.lo;
    v[std::size_t(j)] = j % 2 == 0 ? rounded : -rounded;
  }
  return v;
}

/// The segment's part of `in` read from B: A and B swapped, the weight
/// re-expanded (P and the clip are not touched: clip the reversed segment).
template <class T>
SegmentInput<T> reversed_segment(const SegmentInput<T>& in) {
  SegmentInput<T> out = in;
  out.a = in.b;
  out.b = in.a;
  out.w = reversed_weight(in.w);
  return out;
}

}  // namespace skelconv::detail
