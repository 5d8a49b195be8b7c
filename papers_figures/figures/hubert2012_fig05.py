"""Hubert 2012, Figure 5: two parallel segments; top p³, bottom k_R³; each
column one sought thickness τ (the level giving τ around ONE segment). p³:
a bulge, then a blend as the level drops; k_R³: only thicker. Measured at the
middle (x = 0): the outer and inner thickness against τ, and whether the two
curves have merged (f at the centre point ≥ κ).

The compact row's support R is chosen so that it CANNOT reach: every point of
one segment's curve lies within τ of that segment, hence at least 2·0.5 − τ
from the other one, and R is below that for every τ drawn. The curves must
then be exactly those of one segment alone (no bulge at all, not merely a
smaller one). The same check is run on a wrong model, the compact kernel with
a support that does reach the other segment at the largest τ: it must fail."""
import numpy as np

from figlib import plot
from figlib.claims import Claim, fmt
from figlib.figure import Figure, load_skeleton
from figlib.levelset import crossing
from figlib.reference import kernel, segment_on_bisector

SKELETON = "two_parallel_segments.json"
LENGTH = 4.0
HALF_GAP = 0.5             # the segments are at y = ±0.5
TAUS = (0.2, 0.3, 0.4)
# The support: below 2·HALF_GAP − max τ = 0.6, the distance from the nearest point of
# one segment's curve to the other segment, so that the other segment contributes 0 on
# every curve drawn (and above max τ, so that thickness τ can be reached at all).
R = 0.55
# The wrong model: a support beyond 0.6 (reaches the other segment from the inner side at τ = 0.4).
R_REACHING = 0.65
# "Exactly τ": the levels come from a quadrature of the definition (~1e-14) and the
# crossings are found to 1e-15 relative; any bulge above this is a real one.
EXACT = 1e-12

FIGURE = Figure(
    paper="Hubert 2012", kind="Figure", number="5",
    caption="Convolution curves based on two parallel segments. The top line uses the cubic inverse "
            "kernel p³ and the bottom line a compact support kernel k_R³. Columns correspond to an "
            "identical sought thickness. For the cubic inverse kernel, a bulge and then a blend appear "
            "between the line segments, while the convolution surfaces get only thicker with the "
            "compact support kernel.",
    skeletons=[SKELETON], kernel="p³; k_R³ with R = 0.55 (below 1 − τ: the support cannot reach the other "
                                 "segment); wrong model k_R³ with R = 0.65",
    iso="per column the level giving thickness τ = 0.2, 0.3, 0.4 around one segment alone",
    view="plane z = 0; segments of length 4 at y = ±0.5", size=(640, 290))


def primitives(family, support=R):
    prims = load_skeleton(SKELETON)["primitives"]
    for p in prims:
        p["kernel"] = {"family": family, "degree": 3}
        if family == "compact":
            p["kernel"]["R"] = support
    return prims


def measure(field, level):
    """Outer and inner offsets from the upper segment at x = 0 (NaN inner if merged)."""
    centre = field.f([[0, 0, 0]])[0]
    top = np.array([[0.0, HALF_GAP, 0.0]])
    outer = crossing(field, top, [0, 1.0, 0], level, 1e-9, 3.0)[0]
    inner = crossing(field, top, [0, -1.0, 0], level, 1e-9, HALF_GAP)[0]
    return outer, inner, centre >= level


def draw(ctx):
    xs = np.linspace(-2.8, 2.8, ctx.res(420, 110))
    ys = np.linspace(-1.2, 1.2, ctx.res(180, 50))
    fig, axes = plot.new_figure(FIGURE.size, 2, 3, constrained_layout=True, sharex=True, sharey=True)
    rows = {}
    for row, family in enumerate(("inverse", "compact")):
        field = ctx.field_of(primitives(family))
        K = kernel(family, 3, R=R)
        grid = field.on_grid(xs, ys)
        rows[family] = []
        for col, tau in enumerate(TAUS):
            level = segment_on_bisector(K, LENGTH, tau, support=R if family == "compact" else None)
            ax = axes[row, col]
            plot.contour_segments(ax, xs, ys, grid, level, colors=["tab:blue"])
            for p in field.skeleton["primitives"]:
                plot.draw_segment(ax, p["a"], p["b"], lw=1.2)
            rows[family].append((tau, level) + measure(field, level))
            name = "$p^3$" if family == "inverse" else f"$k_R^3$, R = {R}"
            ax.set_title(f"{name}: τ = {tau}, κ = {level:.3g}", fontsize=8)
            ax.set_aspect("equal")
        axes[row, 0].set_ylabel("y")
    for ax in axes[1]:
        ax.set_xlabel("x")
    plot.save(fig, ctx.image_path, FIGURE.size)

    def describe(family):
        parts = []
        for tau, _, outer, inner, merged in rows[family]:
            inner_text = "merged" if merged else f"inner {fmt(inner - tau)}"
            parts.append(f"τ = {tau}: outer {fmt(outer - tau)}, {inner_text}")
        return "; ".join(parts)

    def no_bulge(rows_):
        """Each segment's curve is that of the segment alone: offsets exactly τ on both sides, never merged."""
        return all(abs(o - t) < EXACT and not m and abs(i - t) < EXACT for t, _, o, i, m in rows_)

    inv = rows["inverse"]
    com = rows["compact"]
    bulge_then_blend = (all(o - t > EXACT for t, _, o, _, _ in inv) and inv[-1][4]
                        and not inv[0][4] and all(i - t > EXACT for t, _, _, i, m in inv if not m))
    # The wrong model: the same check with a support that reaches the other segment at τ = 0.4.
    wrong_field = ctx.field_of(primitives("compact", R_REACHING))
    wrong = [(tau, level) + measure(wrong_field, level) for tau in TAUS
             for level in [segment_on_bisector(kernel("compact", 3, R=R_REACHING), LENGTH, tau, support=R_REACHING)]]
    rows["wrong"] = wrong
    return [
        Claim("p³: a bulge and then a blend appear between the segments as the level drops",
              "offset − τ at x = 0: " + describe("inverse"), bulge_then_blend),
        Claim(f"k_R³: the curves only get thicker, never bulge or blend: with R = {R} the other segment is out of "
              f"reach, so both offsets are exactly τ (to {EXACT:g})",
              "offset − τ at x = 0: " + describe("compact"), no_bulge(com)),
        Claim("the contrast the figure shows: at every τ where p³ bulges inward, k_R³ (R out of reach) does not",
              "inner offset − τ, p³ against k_R³: " + "; ".join(
                  f"τ = {t}: {'merged' if mi else fmt(ii - t)} against {fmt(ic - t)}"
                  for (t, _, _, ii, mi), (_, _, _, ic, _) in zip(inv, com)),
              all((mi or ii - t > EXACT) and abs(ic - t) < EXACT for (t, _, _, ii, mi), (_, _, _, ic, _) in zip(inv, com))),
        Claim(f"(wrong model) k_R³ with R = {R_REACHING}, beyond 1 − τ at τ = 0.4, fails the same no-bulge check",
              "offset − τ at x = 0: " + describe("wrong"), not no_bulge(wrong)),
    ]
