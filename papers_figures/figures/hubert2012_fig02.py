"""Hubert 2012, Figure 2: level sets of the field of one segment, cubic
inverse p³ (left) and classical Cauchy c_s⁴ (right)."""
import numpy as np

from figlib import plot
from figlib.claims import Claim, fmt
from figlib.figure import Figure
from figlib.levelset import crossing
from figlib.reference import kernel, segment_on_bisector

LENGTH = 2.0                     # the segment [(-1,0,0), (1,0,0)]
THICKNESSES = (0.25, 0.5, 1.0)   # the levels drawn: thickness τ at the bisector
CAUCHY_S = 1.0

FIGURE = Figure(
    paper="Hubert 2012", kind="Figure", number="2",
    caption="Different level sets of the convolution function for a line segment with a cubic "
            "inverse power (left) and the classical Cauchy kernel (right).",
    skeletons=["segment_p3.json", "segment_cauchy4.json"],
    kernel="p³; c_s⁴ with s = 1", view="plane z = 0, x in [-2.6, 2.6], y in [-1.8, 1.8]",
    iso="the levels κ(τ) = l J_i(...) of thickness τ = 0.25, 0.5, 1 at the bisector "
        "(Hubert & Cani Prop. 4.1); for Cauchy also a level between f(A) and f(middle), "
        "whose level set crosses the segment",
    size=(640, 290))


def profile_heights(field, level, xs, y_max):
    """y where the level set crosses the vertical line x (NaN where it does not)."""
    origins = np.stack([xs, np.zeros_like(xs), np.zeros_like(xs)], axis=1)
    return crossing(field, origins, [0.0, 1.0, 0.0], level, 1e-9, y_max)


def panel(ctx, ax, field, K, title, extra_level=None):
    xs = np.linspace(-2.6, 2.6, ctx.res(520, 130))
    ys = np.linspace(-1.8, 1.8, ctx.res(360, 90))
    values = field.on_grid(xs, ys)
    levels = [(segment_on_bisector(K, LENGTH, tau), f"τ = {tau}") for tau in THICKNESSES]
    if extra_level is not None:
        levels.append((extra_level, "crossing [AB]"))
    colours = ["tab:blue", "tab:orange", "tab:green", "tab:purple"]
    for (level, label), colour in zip(levels, colours):
        plot.contour_segments(ax, xs, ys, values, level, colors=[colour])
        ax.plot([], [], color=colour, label=f"κ = {level:.4g} ({label})")
    plot.draw_segment(ax, (-1, 0), (1, 0))
    ax.set_aspect("equal")
    ax.set_title(title)
    ax.set_xlabel("x")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=2, fontsize=7)
    ax.set_ylim(-1.8, 1.8)
    return levels


def draw(ctx):
    inverse = ctx.field("segment_p3.json")
    cauchy = ctx.field("segment_cauchy4.json")
    fig, axes = plot.new_figure(FIGURE.size, 1, 2, constrained_layout=True)
    K3 = kernel("inverse", 3)
    K4 = kernel("cauchy", 4, s=CAUCHY_S)
    f_end, f_mid = cauchy.f([[-1, 0, 0], [0, 0, 0]])
    crossing_level = 0.5 * (f_end + f_mid)
    inverse_levels = panel(ctx, axes[0], inverse, K3, "cubic inverse $p^3$")
    cauchy_levels = panel(ctx, axes[1], cauchy, K4, "Cauchy $c_s^4$, s = 1", crossing_level)
    axes[0].set_ylabel("y")
    plot.save(fig, ctx.image_path, FIGURE.size)

    # Thickness at the bisector: levels from the paper's formula (quadrature),
    # the crossing measured on skelconv's field.
    worst_tau = 0.0
    strict_max = True
    xs = np.linspace(-2.0, 2.0, ctx.res(81, 21))
    for field, levels in ((inverse, inverse_levels), (cauchy, cauchy_levels[:len(THICKNESSES)])):
        for (level, _), tau in zip(levels, THICKNESSES):
            y0 = profile_heights(field, level, np.array([0.0]), 3.0)[0]
            worst_tau = max(worst_tau, abs(y0 - tau) / tau)
            y = profile_heights(field, level, xs, 3.0)
            off = np.abs(xs) > 1e-12
            strict_max &= bool(np.all(np.nan_to_num(y[off], nan=-1) < y0))
    # The Cauchy crossing level meets the line of [AB] inside the segment.
    axis = crossing(cauchy, [[0, 0, 0]], [1.0, 0, 0], crossing_level, 0.0, 5.0)[0]
    return [
        Claim("the level κ = l J_i(l², l²/2, l²/4 + τ²) gives thickness τ at the bisector "
              "(Hubert & Cani Prop. 4.1, §3.2–3.3)",
              f"κ by quadrature of the definition, crossing of skelconv's field: max |y − τ|/τ = "
              f"{fmt(worst_tau)} (τ = 0.25, 0.5, 1; p³ and c⁴)", worst_tau < 1e-10),
        Claim("the point of the level set farthest from the segment lies on the perpendicular "
              "bisector; for p^i and c_s^i a strict maximum (§3)",
              f"height of each level set on {len(xs)} vertical lines, x in [−2, 2]: "
              f"{'all below' if strict_max else 'NOT all below'} the height at x = 0", strict_max),
        Claim("for l J_i(sl²,0,1) ≤ κ ≤ l J_i(sl², sl²/2, 1 + sl²/4) the Cauchy level set "
              "crosses the segment [AB] (§3.3)",
              f"κ = {fmt(crossing_level, 5)} between f(A) = {fmt(f_end, 5)} and f(middle) = "
              f"{fmt(f_mid, 5)}: the level set meets the axis at x = ±{fmt(axis, 4)}, inside [−1, 1]",
              0 < axis < 1),
    ]
