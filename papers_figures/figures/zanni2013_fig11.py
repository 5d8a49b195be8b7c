"""Zanni et al. 2013, Figure 11 (§4.3): with a compact-support kernel, a
constant-weight homothetic segment has exactly the thickness τ_c at a point
whose support ball (radius σ τ_c) meets only skeleton, i.e. where the segment
covers a length L = 2 τ_c √(σ² − 1) around the point's foot (Pythagoras:
τ_c² + (L/2)² = (σ τ_c)²). There the field equals that of an infinite line,
which is 1 at distance τ_c by SCALIS's normalisation.

Measured: f at distance τ_c from the middle of segments of length ℓ·L_min, for
ℓ from 0.5 to 2: the guarantee says f = 1 (to rounding) for every ℓ ≥ 1 and,
since the kernel is positive, f < 1 for ℓ < 1 (the missing skeleton took part
of the integral). (a) the iso-curves f = 1 for ℓ = 0.6, 1, 1.6 with the
support ball of the midpoint's surface point; (b) f(mid + τ_c n) − 1 against ℓ."""
import numpy as np

from figlib import plot
from figlib.claims import Claim, fmt
from figlib.figure import Figure
from figlib.zanni import scalis_segment

DEGREE, SIGMA, TAU = 6, 2.0, 0.5          # the paper's practice: compact polynomial kernel of degree 6 (§4.3)
L_MIN = 2 * TAU * np.sqrt(SIGMA ** 2 - 1)  # the paper's L = 2 τ_c √(σ² − 1)
EXACT = 1e-12             # |f − 1| for ℓ ≥ 1: the guarantee is exact, only rounding remains
SHORT_BELOW = 1e-6        # f < 1 − 1e-6 for ℓ ≤ 0.95: a shortfall well above rounding
DRAWN = (0.6, 1.0, 1.6)

FIGURE = Figure(
    paper="Zanni et al. 2013", kind="Figure", number="11",
    caption="Compact-support kernel: the thickness guarantee. A point at distance τ from a segment skeleton must "
            "be within the influence of a length L of skeleton for the thickness τ to be guaranteed.",
    original_caption="Cas du noyau à support compact : garantie sur l'épaisseur. Un point à la distance τ d'un "
                     "squelette segment doit être dans l'air d'influence d'une longueur L de squelette pour avoir "
                     "la garantie que l'épaisseur soit correcte.",
    section=f"(a) iso-curves of segments of length ℓ·L_min (L_min = 2τ√(σ²−1) = {L_MIN:.4g}) with the support ball "
            "(radius στ) of the point above the middle; (b) f − 1 at that point against ℓ",
    kernel=f"SCALIS compact {DEGREE}, σ = {SIGMA:g}, constant τ_c = {TAU:g}", iso="1",
    view="plane z = 0, segments centred on the origin along x", size=(1600, 640))


def segment(ell):
    half = 0.5 * ell * L_MIN
    return scalis_segment((-half, 0.0, 0.0), (half, 0.0, 0.0), TAU, TAU, "compact", DEGREE, SIGMA)


def draw(ctx):
    ells = np.linspace(0.5, 2.0, ctx.res(61, 16))
    ells = np.union1d(ells, [0.95, 1.0, 1.0 + 1e-9])
    above = np.array([ctx.field_of([segment(e)]).f([[0.0, TAU, 0.0]])[0] for e in ells])
    long_ = ells >= 1.0
    worst_long = float(np.max(np.abs(above[long_] - 1)))
    short = ells <= 0.95
    worst_short = float(np.max(above[short]))
    if ctx.image_path:
        fig, axes = plot.new_figure(FIGURE.size, 1, 2, constrained_layout=True)
        xs = np.linspace(-2.0, 2.0, ctx.res(400, 80))
        ys = np.linspace(-1.2, 1.2, ctx.res(240, 50))
        ax = axes[0]
        for ell, colour in zip(DRAWN, ("tab:red", "tab:green", "tab:blue")):
            values = ctx.field_of([segment(ell)]).on_grid(xs, ys)
            plot.contour_segments(ax, xs, ys, values, 1.0, colors=[colour])
            half = 0.5 * ell * L_MIN
            ax.plot([-half, half], [-0.02 * DRAWN.index(ell)] * 2, color=colour, lw=2.5, label=f"ℓ = {ell:g}")
        t = np.linspace(0, 2 * np.pi, 200)
        ax.plot(SIGMA * TAU * np.cos(t), TAU + SIGMA * TAU * np.sin(t), "k--", lw=1, label="support of (0, τ)")
        ax.plot([-L_MIN / 2, L_MIN / 2], [0, 0], "k|", ms=14)
        ax.plot([0], [TAU], "ko", ms=4)
        ax.set_aspect("equal")
        ax.set_title(f"(a) iso 1 for segments of length ℓ·L_min; ticks: L_min = {L_MIN:.4g}")
        ax.legend(loc="lower right", fontsize=9)
        ax = axes[1]
        ax.semilogy(ells, np.maximum(np.abs(above - 1), 1e-17), "o-", ms=3)
        ax.axvline(1.0, color="k", ls="--", lw=1)
        ax.set_xlabel("ℓ = segment length / L_min")
        ax.set_ylabel("|f(0, τ, 0) − 1|  (10⁻¹⁷: exactly 1)")
        ax.set_title("(b) the guarantee: f = 1 at distance τ once ℓ ≥ 1")
        plot.save(fig, ctx.image_path, FIGURE.size)
    return [
        Claim("the thickness is exactly τ_c where the support ball meets only skeleton: f = 1 at distance τ_c from "
              "the middle once L ≥ 2τ_c√(σ² − 1)",
              f"max |f − 1| over {int(long_.sum())} lengths ℓ ∈ [1, 2]: {fmt(worst_long)} (threshold {EXACT:g})",
              worst_long < EXACT),
        Claim("the guarantee needs that length: shorter segments are thinner than τ_c there",
              f"max f over {int(short.sum())} lengths ℓ ∈ [0.5, 0.95]: {fmt(worst_short, 6)} (below 1 − {SHORT_BELOW:g})",
              worst_short < 1 - SHORT_BELOW),
    ]
