// skelconv/primitives/scalis_compact.hpp — the SCALIS segment with the compact kernel
// (docs/mathematics.md §4, Zanni et al. 2013 §4.1–4.3): F and ∇F, exact to rounding.
//
// F(P) = ∫_0^1 K(|P − Γ(t)| / τ(t)) |AB| dt / τ(t),  K(d) = (1 − (d/σ)²)^(i/2)
// for d < σ (else 0), τ(t) = τ0 + Δτ t, i = degree ∈ 2..10 (any i ≥ 2 works).
//
// 1. The support (Zanni §4.3). K > 0 ⇔ Q(t) > 0 with
//        Q(t) = σ²τ(t)² − |P − Γ(t)|² = α t² + 2β t + γ,
//        α = σ²Δτ² − |AB|²,  β = σ²Δτ τ0 + AB·AP,  γ = σ²τ0² − |AP|²,
//    and F = |AB| ∫_{t1}^{t2} ξ^(i/2) / τ dt with ξ = Q/(σ²τ²) ∈ (0, 1].
//    {t ∈ [0,1] : Q > 0} is ONE interval (the paper's "geometric
//    considerations"): where τ ≥ 0, Q > 0 ⇔ g(t) = στ(t) − |PΓ(t)| > 0, and g
//    is concave (linear minus convex), so {g > 0} is an interval. This holds
//    for every σ > 0, not only σ > 1. We orient the segment so that Δτ ≥ 0
//    (F is symmetric under A ↔ B); then the cone tip t_tip = −τ0/Δτ is ≤ 0,
//    and since Q(t_tip) = −|PΓ(t_tip)|² ≤ 0, for α > 0 the tip lies between
//    the roots, so the support is [max(0, r_hi), 1]; for α < 0 it is
//    [max(0, r_lo), min(1, r_hi)]; for α = 0, Q is linear. The discriminant is
//        β² − αγ = σ²|Δτ AP + τ0 AB|² − |AB × AP|²
//    (expand both sides), formed with γ in double-word arithmetic from the
//    exact inputs (exact_support_depths), and
//    the roots as q = −(β + sign(β)√disc), r = γ/q, r' = q/α (no
//    cancellation; r' is never formed when α = 0). Q is evaluated factored
//    about a root ρ, Q = s (α s + Q'(ρ)) with s = t − ρ and Q'(ρ) = ±2√disc, so
//    it keeps its relative accuracy next to the support bounds.
//
// 2. The integral. Even i (double): in closed form where a proven bound says
//    it is accurate (generated/scalis_segment_compact.hpp; the method and the
//    bounds are in codegen/scalis_compact_writer.cpp's comment): Q in
//    Bernstein form on the support (nonnegative coefficients,
//    closed_form_input), the substitution y = (1 + λ)x/(1 + λx) and one
//    stable recurrence reduce every integral to K_i(κ) = ∫ y^i/(1 − κy),
//    κ = Δτ w/τ(t2): Chebyshev interpolants where τ varies little over the
//    support (Δτ → 0, where the paper's partial fractions cancel), the
//    partial fractions with their one logarithm where it varies a lot (a
//    cone tip near the support); Δτ = 0, α = 0 and double roots need no
//    form of their own. Within 2^−40 of a cone tip (τ(t1) < 2^−40 τ(t2)) the
//    closed form declines and the panels below take the point; so do odd i
//    (√Q has branch points at the roots of Q) and the wider types (the
//    closed forms carry double constants).
//    The panels: closed forms in u = τ(t) alone (partial fractions and the
//    Hubert–Cani recurrence, Zanni §4.3) cancel badly when τ varies little
//    over the support (Δτ → 0: the terms grow like 1/Δτ^k and cancel to a
//    constant-radius answer) and need separate forms for Δτ = 0, α = 0 and
//    double roots. We instead use Gauss–Legendre on panels, with a substitution
//    that makes the integrand ANALYTIC on every panel, and panels chosen so
//    that the rule is exact to rounding (an a-priori bound, not adaptivity):
//      * at a support bound ρ that is a root of Q (odd i only), t = ρ ± v²:
//        then √Q = v √|αs + Q'(ρ)| is analytic at v = 0, and dt = 2v dv;
//        an interval with two root ends is cut in half, one substitution per
//        half; a root end is otherwise paired with a plain linear half;
//      * the only other singularities of the integrand (in the complex plane
//        of the panel variable) are the pole of 1/τ^(i+1) at t_tip and, for odd
//        i, the branch points at the roots of Q not removed above, mapped
//        through the substitution (v = ±√w, w real, possibly imaginary);
//      * a panel [a, b] is accepted when every singularity z lies outside the
//        Bernstein ellipse of [a, b] of parameter ρ_min = 4 for the pole, 3
//        for a branch point (ρ(z) = s + √(s²−1), s = (|z−a| + |z−b|)/(b−a));
//        otherwise it is bisected. A singularity at distance δ from a panel of
//        length ℓ costs ~log2(ℓ/δ) panels. (With two root ends, each square
//        half sees the other root at ρ = 3.36: one panel each.)
//    Error bound (Trefethen, Approximation Theory and Approximation Practice,
//    Thm 19.3, whose I_n has n + 1 points): for f analytic in the Bernstein
//    ellipse E_ρ with |f| ≤ M there, the N-point rule errs by
//    ≤ (64/15) M ρ^(2−2N) / (ρ² − 1). On an
//    accepted panel the nearest singularity is on or outside E_4. The rule's
//    error on the bare pole (x0 − x)^(−(i+1)), x0 on E_4, is 9e-16 for i = 10
//    and N = 20, 6e-21 for N = 25, 3e-26 for N = 30, 1e-33 for N = 40
//    (computed in binary128). The numerator Q^(i/2) adds the factor M/max|f|
//    of the bound (a polynomial of degree i grows up to ρ^i off the
//    interval), which is what the partial-fraction cancellation looks like
//    here: with N = 20 double lost up to 3e-12 at i = 10; N = 25 leaves
//    every generic sample at rounding level. Hence N = 25 (double), 30
//    (long double), 40 (binary128: measured within 2e-32 of the reference).
//    This is what Zanni §4.3 computes in closed form; no interval where a
//    closed form would cancel (Δτ → 0, α → 0, P near the tip) needs a special
//    case: Δτ = 0 has no pole, α = 0 has one root, and a pole near the support
//    (P near a cone tip) only adds panels (~log2(1/ε) at distance ε).
//
// 3. The gradient (Zanni §4.3, Leibniz's rule). Q vanishes at a support bound
//    that is a root, and a bound at 0 or 1 does not move, so the bounds add
//    nothing; ∂Q/∂P = −2(P − Γ(t)) gives
//        ∇F = −(i |AB| / σ²) ∫ ξ^((i−2)/2) (P − Γ(t)) / τ³ dt,
//    with P − Γ(t) = H − (t − t*) AB, t* = AB·AP/|AB|², H = P − Γ(t*) ⟂ AB, so the
//    two directions never cancel each other.
//
// 4. Special points. P exactly at a cone tip (τ = 0 at that end and P = the
//    end point): the support is empty when α < 0 (slender cone, F = 0, ∇F = 0)
//    and F = +∞ when α > 0 (the integrand ~ 1/|t − t_tip|; ∇F is then NaN).
//    Near the tip everything is finite, and accurate down to |P − tip| ≈
//    1e-150 τ_max in double (closer, |AP|² underflows: F loses digits, ∇F
//    may be NaN; |AP|² == 0 is treated as the tip). Inputs are translated to A
//    and scaled by a power of two (exact) so that no square overflows; F is
//    scale invariant.
//
// 5. Accuracy (double, verify/test_scalis_properties.cpp against binary128
//    quadrature of the definition, 2,000 generic points per degree 2..10):
//    F ≤ 4.8e-14 relative, each ∇F component ≤ 2.7e-13 of |∇F|; a
//    component as small as 1–5% of |∇F| has up to 3e-12 error of its own.
//    Near the support boundary F ~ η^((i+1)/2) at relative depth η: ≤ 2.4e-15
//    for η down to 1e-10, since Q(0), Q(1) and the discriminant come from
//    the exact inputs there (support_depths; from the rounded AP and
//    AB × AP they carried ~ε/η: 2e-10 at η = 1e-5), each root is its offset
//    from the nearer end of the segment (2.5e-13 at i = 10 before, a short
//    support at an end), and the width between two roots is 2√disc/|α|.
//    Cost (callgrind, F and ∇F, i = 4 or 6, P inside the support of a
//    segment with τ 0.2 → 0.3): the closed form ~1,700 instructions, of
//    which ~1,360 are the support (prepare, closed_form_input) and ~320–440
//    the generated form; the panels ~4,100–4,250 (one panel of 25 nodes for
//    even i, two for odd i, more only near a cone tip). Operation counts:
//    generated/opcounts.csv, rows scalis_segment_compact_i*.
#pragma once

#include <array>
#include <limits>
#include <type_traits>

#include "generated/scalis_segment_compact.hpp"
#include "skelconv/detail/scalis_compact_support.hpp"

namespace skelconv {

/// Unnormalised compact SCALIS field F(P) = ∫_0^1 K(|P−Γ(t)|/τ(t)) |AB| dt/τ(t),
/// K(d) = (1 − (d/σ)²)^(i/2) for d < σ, else 0, i = degree ∈ 2..10, at P = p
/// from the segment's preparation (detail::prepare_segment, once per segment);
/// writes ∇_P F to *grad when grad != nullptr. Method and accuracy: header comment.
template <class T>
T scalis_compact_F(const detail::CompactSegment<T>& segment, const std::array<T, 3>& p,
                   std::type_identity_t<std::array<T, 3>>* grad) {
  using namespace detail;
  const bool with_grad = grad != nullptr;
  if (with_grad) *grad = {T(0), T(0), T(0)};
  const Prepared<T> pr = prepare(segment, p);
  if (pr.done) {
    if (with_grad && pr.grad_nan) grad->fill(std::numeric_limits<T>::quiet_NaN());
    return pr.value;
  }
  // The closed forms carry double-precision constants: wider types keep the
  // panels. They decline (false) where no form is proven accurate.
  if constexpr (std::numeric_limits<T>::digits == 53) {
    ScalisCompactIntegrals<T> closed{};
    if (segment.degree % 2 == 0 &&
        generated::scalis_segment_compact_closed_form(segment.degree, with_grad ? 2 : 0, closed_form_input(pr),
                                                      closed))
      return finish(pr, Sums<T>{closed.f, closed.g0, closed.g1}, grad);
  }
  return finish(pr, integrate_support(pr.fr, pr.roots, pr.support, pr.sd, with_grad), grad);
}

/// The same at the point of `in`, its segment prepared for this one call.
/// (T is deduced from `in` alone, so `grad` may be a literal nullptr.)
template <class T>
T scalis_compact_F(int degree, const ScalisSegmentInput<T>& in, std::type_identity_t<std::array<T, 3>>* grad) {
  return scalis_compact_F(detail::prepare_segment(degree, in), in.p, grad);
}

}  // namespace skelconv
