"""Hubert 2012, Figure 1: the kernel graphs, drawn from skelconv itself.

Each curve is f/|AB| of a very short segment [A,B] (|AB| = 1e-4) seen from
distance r along its bisector, which is the kernel K(r) up to O(|AB|²/r²):
so the graphs show the kernels skelconv actually evaluates, and the claim
check compares them with the formulas of Hubert §2.1 (docs/mathematics.md §1).
"""
import numpy as np

from figlib import plot
from figlib.claims import Claim, fmt
from figlib.figure import Figure

DEGREES = (1, 2, 3, 4, 6, 8)
CAUCHY_S = 1.0
PS_S = 2.0            # the s of p_s^i: between c_s^i (value 1 at r = 0) and p^i (its limit s → ∞)
COMPACT_R = 1.0
SHORT = 1e-4          # segment length: K differs from f/|AB| by O((SHORT/r)²)
R_MIN = 0.05          # closest r on the graphs (inverse kernels blow up at 0)

FIGURE = Figure(
    paper="Hubert 2012", kind="Figure", number="1",
    caption="The graphs of the kernel functions p^i, p_s^i, c_s^i and k_R^i, varying i.",
    section="p^i, p_s^i (s = 2), c_s^i (s = 1) and k_R^i (R = 1) for i = 1, 2, 3, 4, 6, 8. p_s^i is not a "
            "skelconv kernel: it is drawn as s^{i/2} c_s^i (Hubert §2.1) from skelconv's Cauchy kernel with s = 2. "
            "k_R^1 is not offered by skelconv (compact degrees start at 2, §2.1 asks i ≥ 3): it is drawn dashed from "
            "its formula alone.",
    kernel="inverse p^i, p_2^i = 2^{i/2} c_2^i, Cauchy c_1^i, compact k_1^i", view="r from 0.05 to 2",
    size=(1600, 520))
# One colour per degree in every panel (the same i has the same colour in all four).
COLOURS = {i: f"C{k}" for k, i in enumerate(DEGREES)}

# panel: (skelconv family, the formula of Hubert §2.1, skelconv's kernel parameters, factor applied to
# skelconv's value to give the panel's kernel: p_s^i = s^{i/2} c_s^i)
KERNELS = {
    "inverse": ("inverse", lambda r, i: r ** -i, {}, lambda i: 1.0),
    "ps": ("cauchy", lambda r, i: (1 / PS_S + r * r) ** (-i / 2), {"s": PS_S}, lambda i: PS_S ** (i / 2)),
    "cauchy": ("cauchy", lambda r, i: (1 + CAUCHY_S * r * r) ** (-i / 2), {"s": CAUCHY_S}, lambda i: 1.0),
    "compact": ("compact", lambda r, i: np.where(r < COMPACT_R, np.clip(1 - r * r / COMPACT_R ** 2, 0, None)
                                                 ** (i / 2), 0.0), {"R": COMPACT_R}, lambda i: 1.0),
}
TITLES = {"inverse": r"power inverse $p^i(r) = r^{-i}$",
          "ps": r"$p_s^i(r) = (1/s + r^2)^{-i/2} = s^{i/2} c_s^i$, $s = 2$",
          "cauchy": r"Cauchy $c_s^i$, $s = 1$", "compact": r"compact $k_R^i$, $R = 1$"}


def segment_by_quadrature(formula, degree, r, nodes=12):
    """(1/|AB|) ∫ K(√(r² + s²)) ds over the short segment, by a Gauss–Legendre
    rule (the integrand is a polynomial-like function of s on so short a
    segment: 12 nodes are exact to rounding)."""
    x, w = np.polynomial.legendre.leggauss(nodes)
    s = 0.5 * SHORT * x
    values = formula(np.sqrt(r[:, None] ** 2 + s[None, :] ** 2), degree)
    return 0.5 * values @ w


def kernel_from_skelconv(ctx, family, degree, params, r):
    seg = {"type": "segment", "a": [-SHORT / 2, 0, 0], "b": [SHORT / 2, 0, 0],
           "kernel": dict(family=family, degree=degree, **params)}
    points = np.stack([np.zeros_like(r), r, np.zeros_like(r)], axis=1)
    return ctx.field_of([seg]).f(points) / SHORT


def draw(ctx):
    r = np.linspace(R_MIN, 2.0, ctx.res(400, 60))
    fig, axes = plot.new_figure(FIGURE.size, 1, 4, constrained_layout=True)
    worst = 0.0
    for ax, (panel, (family, formula, params, factor)) in zip(axes, KERNELS.items()):
        for i in DEGREES:
            if family == "compact" and i < 2:       # not a skelconv kernel: the formula alone, dashed
                ax.plot(r, formula(r, i), color=COLOURS[i], lw=1.8, ls="--", label=f"i = {i} (formula)")
                continue
            k = factor(i) * kernel_from_skelconv(ctx, family, i, params, r)
            exact = segment_by_quadrature(formula, i, r)
            scale = np.maximum(np.abs(exact), 1e-300)
            worst = max(worst, float(np.max(np.abs(k - exact)[exact > 1e-12] / scale[exact > 1e-12])))
            ax.plot(r, k, color=COLOURS[i], lw=1.8, label=f"i = {i}")
        ax.set_title(TITLES[panel])
        ax.set_xlabel("distance r")
        ax.set_ylim(0, 2.5 if panel in ("inverse", "ps") else 1.05)
        ax.legend(loc="upper right", ncol=2)            # each panel its own: the degrees it draws
    axes[0].set_ylabel("K(r)")
    plot.save(fig, ctx.image_path, FIGURE.size)

    # Regularity at r = R of the compact kernel: the left derivative of k_R^i
    # is -(i/R)(1 - r²/R²)^(i/2-1)·r/R → -2/R for i = 2 (a kink) and 0 for i ≥ 3.
    h = 1e-6
    slopes = {}
    for i in (2, 3, 4):
        pts = np.array([COMPACT_R - 2 * h, COMPACT_R - h])
        f = kernel_from_skelconv(ctx, "compact", i, {"R": COMPACT_R}, pts)
        slopes[i] = (f[1] - f[0]) / h
    return [
        Claim("the kernels are p^i = r^-i, p_s^i = (1/s + r²)^(-i/2) = s^(i/2) c_s^i, c_s^i = (1+sr²)^(-i/2), "
              "k_R^i = (1-r²/R²)^(i/2) (§2.1)",
              f"the curves are skelconv's f/|AB| of a 1e-4-long segment; against Gauss–Legendre "
              f"quadrature of these formulas over that segment: max relative difference {fmt(worst)} "
              f"(r in [{R_MIN}, 2], i = 1…8; p_s^i as s^(i/2) × skelconv's c_s^i; k_R^1 drawn from its formula only)",
              worst < 1e-9),
        Claim("k_R^i is not differentiable at r = R for i < 3; i ≥ 3 is needed for C¹ surfaces (§2.1)",
              f"left slope at r = R: i = 2: {fmt(slopes[2])} (kink, −2/R expected), "
              f"i = 3: {fmt(slopes[3])}, i = 4: {fmt(slopes[4])}",
              abs(slopes[2] + 2 / COMPACT_R) < 1e-3 and abs(slopes[3]) < 1e-2 and abs(slopes[4]) < 1e-4),
    ]
