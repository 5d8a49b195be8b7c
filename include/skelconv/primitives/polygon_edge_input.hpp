// skelconv/primitives/polygon_edge_input.hpp — the contract between the polygon driver
// (skelconv/primitives/polygon_field.hpp) and the generated polygon edge kernels
// (generated/polygon_*.hpp).
//
// The field of a planar polygon Ω is a sum over its edges (Green's theorem,
// Hubert 2012 §5, docs/mathematics.md §3). With P̄ the projection of P on the plane, z the
// height of P above it and, for edge m from Q_m to Q_{m+1},
//
//     h_m = ((Q_m − P̄) × (Q_{m+1} − Q_m)) · n      (twice the signed area of
//                                                   the fan triangle P̄ Q_m Q_{m+1})
//     θ_m = the signed angle the edge subtends at P̄,
//
// each generated edge kernel returns the terms of its edge that the driver
// adds up. Which terms mean what depends on the family; see
// polygon_field.hpp, which assembles f and ∇f from them.
#pragma once

#include <array>

namespace skelconv {

/// Inputs of one polygon edge evaluation, on scalar type T.
template <class T>
struct PolygonEdgeInput {
  std::array<T, 3> a{};       ///< edge start Q_m
  std::array<T, 3> b{};       ///< edge end Q_{m+1}
  std::array<T, 3> p{};       ///< P̄, the projection of the query point on the plane, rounded
  /// P̄ − p, the rounding of P̄ (plane_foot, skelconv/detail/plane_height.hpp): the
  /// inverse and Cauchy kernels form P̄ − Q_m as (p − Q_m) + p_lo, so that
  /// near an edge or a vertex P̄'s position is known to ~ε of its distance
  /// from them, not ε|P|. The compact kernels read p alone: their clip
  /// [t0, t1] is computed from it (their field is bounded: a displacement
  /// of ε|P| changes it by ~ε|P|/R relative).
  std::array<T, 3> p_lo{};
  std::array<T, 3> point{};   ///< the query point P itself (compact: exact support gaps at the edge's ends)
  std::array<T, 3> normal{};  ///< unit normal n; the polygon runs counter-clockwise about it
  T z = T(0);                 ///< height of the query point: P = P̄ + z n
  T s = T(1);                 ///< Cauchy sharpness (cauchy only)
  T R = T(1);                 ///< support radius (compact only)
  /// Compact only: the part [t0, t1] of the edge inside the disc of radius
  /// √(R² − z²) around P̄ (skelconv/detail/clip.hpp). An edge that misses the disc
  /// is still evaluated, with t0 = t1 = 0: its angle θ still counts.
  T t0 = T(0);
  T t1 = T(1);
};

/// The terms one edge contributes (polygon_field.hpp assembles them).
template <class T>
struct PolygonEdgeTerms {
  T h = T(0);         ///< h_m above
  T theta = T(0);     ///< θ_m = atan2(h_m, (Q_m − P̄)·(Q_{m+1} − P̄))
  /// Compact: the part of θ already inside S_f and S_g (the clipped part's
  /// angle for a chord near P̄, else 0); 0 for inverse and Cauchy.
  T theta_in = T(0);
  T S_f = T(0);       ///< the edge's part of f: H_{i−2} (inverse, Cauchy), G^(j+1) − w^(j+1) θ_in (compact)
  T S_g = T(0);       ///< the edge's part of ∂f/∂z: H_i, G^(j) − w^j θ_in
  T J_g = T(0);       ///< ∫_0^1 K(|P − Γ(t)|) dt (∫_{t0}^{t1} for compact): the in-plane gradient
};

}  // namespace skelconv
