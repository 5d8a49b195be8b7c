// skelconv/primitives/segment_input.hpp — the contract between the runtime and the
// generated segment kernels (generated/segment_*.hpp).
//
// Every generated segment kernel computes
//
//     f(P) = |AB| ∫_{t0}^{t1} w(t) K(|P − Γ(t)|) dt,   Γ(t) = A + t (B − A)
//
// (docs/mathematics.md §2), and/or ∇_P f, in two steps: its `prepare` reads
// the segment's part of a SegmentInput (A, B, w and the kernel's parameter)
// once per segment, and its evaluations read that preparation and a
// SegmentPoint (P and the clip) at each point. One struct for all families
// keeps the generated table uniform: a family reads only the fields it needs.
#pragma once

#include <array>
#include <string_view>

#include "skelconv/kernels/kernel_family.hpp"  // KernelFamily, family_name
#include "skelconv/kernels/op_count.hpp"

namespace skelconv {

/// Largest weight-polynomial degree the generator emits by default.
inline constexpr int max_weight_degree = 3;

/// Inputs of one generated segment evaluation, on scalar type T.
template <class T>
struct SegmentInput {
  std::array<T, 3> a{};  ///< segment start A (t = 0)
  std::array<T, 3> b{};  ///< segment end B (t = 1)
  std::array<T, 3> p{};  ///< query point P
  /// Weight w(t) = Σ_k w[k] t^k; a function of weight degree d reads w[0..d].
  std::array<T, max_weight_degree + 1> w{T(1), T(0), T(0), T(0)};
  T s = T(1);   ///< Cauchy sharpness s > 0 (cauchy only)
  T R = T(1);   ///< support radius R > 0 (compact, and the compact levels of soft and wyvill)
  T gaussian_a = T(1);  ///< Gaussian sharpness a > 0 (gaussian only: K = b exp(−a r²))
  T gaussian_b = T(1);  ///< Gaussian height b > 0 (gaussian only)
  /// Compact only: the part [t0, t1] ⊆ [0, 1] of the segment inside the ball
  /// of radius R around P (see skelconv/detail/clip.hpp). The kernel vanishes at a
  /// clipped end, so the moving bounds add nothing to ∇f (docs/mathematics.md §2).
  T t0 = T(0);
  T t1 = T(1);
};

/// What a generated segment evaluation reads at each point (SegmentInput's
/// per-point fields): P, and for a compact kernel the clip [t0, t1].
template <class T>
struct SegmentPoint {
  std::array<T, 3> p{};
  T t0 = T(0);
  T t1 = T(1);
};

}  // namespace skelconv
