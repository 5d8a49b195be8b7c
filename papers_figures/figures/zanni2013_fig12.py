"""Zanni et al. 2013, Figure 12: the field of a compact kernel along a segment
whose weight decreases linearly to 0 at the right: classical (eq. 10) keeps a
support of constant radius R; SCALIS's support follows the radius, being the
envelope of the balls of radius στ(t) around Γ(t)."""
import numpy as np

from figlib import plot
from figlib.claims import Claim, fmt
from figlib.figure import Figure
from figlib.levelset import crossing
from figlib.zanni import classical_segment, scalis_segment

DEGREE = 4
SIGMA = 2.0
LENGTH = 4.0
TAU0 = 0.5
R = SIGMA * TAU0          # classical support radius = SCALIS support at the thick end
A, B = (0.0, 0.0, 0.0), (LENGTH, 0.0, 0.0)
TINY = np.finfo(float).tiny   # "f > 0": the support boundary is where f drops to 0

FIGURE = Figure(
    paper="Zanni et al. 2013", kind="Figure", number="12",
    caption="Potential field of (a) a classical convolution primitive (eq. (10)), (b) a homothetic primitive, "
            "for a compact-support kernel along a segment skeleton, with the weight varying linearly down to 0 "
            "on the right.",
    original_caption="Champ de potentiel associé à (a) une primitive de convolution classique (eq. (10)), (b) une "
                     "primitive homothétique, pour un noyau à support compact le long d'un squelette segment, avec "
                     "une variation linéaire de poids jusqu'à 0 à droite.",
    kernel=f"compact 4, σ = {SIGMA:g} (classical: k_R⁴ with R = σ τ0 = {R:g}, weight τ(t) = τ0(1 − t))",
    iso="colour: f / max f; white curve: the support boundary f = 0; the iso-curve f = c (SCALIS c = 1, "
        "classical the level giving radius τ0 at the thick end)",
    view="plane z = 0, segment (0,0,0)–(4,0,0), τ0 = 0.5", size=(640, 420))


def scalis_support(x):
    """Half-width of the SCALIS support at abscissa x: max over t ∈ [0,1] of
    (στ(t))² − (x − tL)², a quadratic in t (maximised exactly)."""
    dtau = -TAU0
    lead = SIGMA ** 2 * dtau ** 2 - LENGTH ** 2
    lin = SIGMA ** 2 * TAU0 * dtau + x * LENGTH
    t = np.clip(-lin / lead, 0.0, 1.0)
    g = lead * t * t + 2 * lin * t + SIGMA ** 2 * TAU0 ** 2 - x * x
    return np.sqrt(np.clip(g, 0, None))


def support_width(field, xs):
    origins = np.stack([xs, np.zeros_like(xs), np.zeros_like(xs)], axis=1)
    return crossing(field, origins, [0, 1.0, 0], TINY, 1e-12, 3.0)


def draw(ctx):
    classical = ctx.field_of([classical_segment(A, B, TAU0, 0.0, "compact", DEGREE, R)])
    scalis = ctx.field_of([scalis_segment(A, B, TAU0, 0.0, "compact", DEGREE, SIGMA)])
    classical_iso = classical.f([[0.0, TAU0, 0.0]])[0]   # not used for a claim: a level to draw
    xs = np.linspace(-1.4, 5.4, ctx.res(340, 85))
    ys = np.linspace(-1.4, 1.4, ctx.res(140, 40))
    fig, axes = plot.new_figure(FIGURE.size, 2, 1, constrained_layout=True, sharex=True)
    for ax, field, iso, title in ((axes[0], classical, classical_iso, "(a) classical (eq. 10)"),
                                  (axes[1], scalis, 1.0, "(b) SCALIS (eq. 14)")):
        grid = field.on_grid(xs, ys)
        grid[~np.isfinite(grid)] = np.nanmax(grid[np.isfinite(grid)])
        image = ax.pcolormesh(xs, ys, grid / grid.max(), cmap="magma", shading="auto", vmin=0, vmax=1)
        ax.contour(xs, ys, grid, levels=[grid.max() * 1e-9], colors=["white"], linewidths=0.8)
        ax.contour(xs, ys, grid, levels=[iso], colors=["cyan"], linewidths=1.0)
        plot.draw_segment(ax, A, B, color="white", lw=1.2)
        ax.set_aspect("equal")
        ax.set_ylabel("y")
        ax.set_title(f"{title}: white f = 0, cyan f = {iso:.3g}")
        ax.grid(False)
    axes[1].set_xlabel("x")
    fig.colorbar(image, ax=axes, shrink=0.8, label="f / max f")
    plot.save(fig, ctx.image_path, FIGURE.size)

    probe = np.array([0.25, 0.5, 0.75]) * LENGTH
    wc = support_width(classical, probe)
    ws = support_width(scalis, probe)
    predicted = scalis_support(probe)
    return [
        Claim("classical: the support keeps a constant radius R along the segment, whatever the weight",
              f"support half-width at x = 1, 2, 3: {', '.join(fmt(w, 15) for w in wc)} (R = {R:g})",
              bool(np.all(np.abs(wc - R) < 1e-12))),
        Claim("SCALIS: the support's radius varies with the weight (the envelope of the balls of radius στ(t))",
              f"support half-width at x = 1, 2, 3: {', '.join(fmt(w, 6) for w in ws)}; envelope (exact): "
              f"{', '.join(fmt(w, 6) for w in predicted)}; max difference {fmt(np.max(np.abs(ws - predicted)))}",
              bool(np.all(np.abs(ws - predicted) < 1e-9) and ws[0] > ws[1] > ws[2])),
    ]
