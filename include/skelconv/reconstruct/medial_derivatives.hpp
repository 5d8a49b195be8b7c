// skelconv/reconstruct/medial_derivatives.hpp — how the field of one
// primitive of a medial mesh changes when its spheres move or grow: the
// Jacobian of the joint fit (medial_fit.hpp), in closed form from the
// primitive's own f and ∇f (docs/reconstruction_medial.md, "The fit").
//
// Compact kernels of even degree 2m only (the medial path's kernel):
// K(d) = (1 − d²/σ²)^m is then a polynomial along any line, and the one
// integral the derivatives need beyond f and ∇f (along a triangle's edges)
// is a polynomial's.
//
//  * SCALIS triangle of constant radius τ (the closed form), F(P) = ∬_T g(P − Q) dQ,
//    g(x) = K(|x|/τ)/τ². Moving vertex v_i by e moves every Q of T by λ_i(Q) e
//    (λ_i its barycentric coordinate). Split e = e_t + (e·n) n:
//      in the plane, Reynolds' transport theorem: ∂F/∂v_i · e_t = Σ over the two
//      edges at v_i of (ν · e_t) ∫_edge g(P − Q) λ_i(Q) ds (ν the edge's outward
//      normal in the plane);
//      along n, the motion λ_i(Q) n of the plane's points is, to first order, a
//      rigid rotation about an axis in the plane, V(X) = λ_i(X') n − h ∇λ_i for
//      X = X' + h n: ∂F/∂v_i · n = −∇F · V(P) = −λ_i(P') n·∇F + h ∇λ_i·∇F.
//    F is scale invariant (P, the vertices and τ scaled together leave it
//    unchanged), and invariant under translation, so Euler's identity gives
//    ∂F/∂τ = −Σ_i (v_i − P)·∂F/∂v_i / τ.
//  * SCALIS segment a → b, radius τ0 → τ1, F = ∫_0^L g(P − Q(s), τ(s)) ds,
//    g(x, τ) = K(|x|/τ)/τ. Moving b across the axis rotates the segment about
//    a (to first order): ∂F/∂b · e = −∇F · ((u × e) × (P − a)) / L for e ⊥ u.
//    Along the axis it lengthens it, and integrating d/ds g by parts:
//    ∂F/∂b · u = g(P − b, τ1) − ((τ1 − τ0) / L) ∂F/∂τ1; the same at a with
//    the signs of a reversed segment. ∂F/∂τ0, ∂F/∂τ1 by a forward difference
//    (no closed form is at hand).
//  * point w K(|P − c| / (σρ)): ∂f/∂c = −∇f, ∂f/∂ρ = −(P − c)·∇f / ρ
//    (f depends on (P − c)/ρ only).
// Checked against central differences of the primitives themselves in
// tests/reconstruct_medial_test.cpp (MedialDerivatives.*).
#pragma once

#include <array>

#include "skelconv/geometry.hpp"
#include "skelconv/primitives/point.hpp"
#include "skelconv/primitives/scalis_segment.hpp"
#include "skelconv/primitives/scalis_triangle.hpp"

namespace skelconv::reconstruct {

/// f and ∇f of one primitive at P, and ∂f/∂(its vertices), ∂f/∂(its radii).
template <std::size_t N>
struct PrimitiveDerivatives {
  FieldSample field;
  std::array<Vec3, N> vertex;  ///< ∂f/∂v_i
  /// The triangle: one, ∂f/∂τ of its common radius; the segment: ∂f/∂τ0,
  /// ∂f/∂τ1; the point: ∂f/∂ρ.
  std::array<double, N == 3 ? 1 : N> radius;
};

/// Throws InputError (at "kernel") unless the kernel is compact of even
/// degree, or the triangle's radii differ.
PrimitiveDerivatives<3> derivatives(const ScalisTriangle& triangle, const Vec3& p);
PrimitiveDerivatives<2> derivatives(const ScalisSegment& segment, const Vec3& p);
/// `rho` is the sphere's radius ρ (the kernel's support is σρ).
PrimitiveDerivatives<1> derivatives(const PointPrimitive& point, double rho, const Vec3& p);

}  // namespace skelconv::reconstruct
