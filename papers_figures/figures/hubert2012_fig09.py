"""Hubert 2012, Figure 9: two parallel squares at distance 2, R = 1, drawn as
the section y = 0: cubic inverse p³ (an inward bulge between the polygons)
and compact k_R⁴ (flat towards the centre of the faces). k_R³ is not a
polygon kernel (compact polygon degrees are even), so k_R⁴ stands for the
paper's unnamed compact kernel."""
import numpy as np

from figlib import plot
from figlib.claims import Claim, fmt
from figlib.figure import Figure, load_skeleton
from figlib.levelset import crossing

SKELETON = "two_parallel_squares.json"
HALF_SIDE = 2.0            # squares [-2, 2]² at z = ±1
TAU = 0.3                  # sought thickness above the centre of one face
R = 1.0
KERNELS = {"inverse": {"family": "inverse", "degree": 3}, "compact": {"family": "compact", "degree": 4, "R": R}}

FIGURE = Figure(
    paper="Hubert 2012", kind="Figure", number="9",
    caption="Convolution surfaces based on parallel polygons (left) with a cubic inverse kernel (middle) "
            "and compact support kernel (right) where R is chosen to be less than the distance between "
            "the two polygons. An inward bulge appears in between the polygons for the cubic inverse "
            "kernel, while the convolution surface is flat towards the center of the polygons on both "
            "sides for the compact support kernel.",
    section="the section y = 0 of the surfaces, and f along the common normal through the centres (left)",
    skeletons=[SKELETON], kernel="p³; k_R⁴ with R = 1",
    iso="the level of one square alone at height τ = 0.3 above its centre",
    view="plane y = 0 (x horizontal, z vertical)", size=(640, 300))


def primitives(family):
    prims = load_skeleton(SKELETON)["primitives"]
    for p in prims:
        p["kernel"] = dict(KERNELS[family])
    return prims


def draw(ctx):
    fig, axes = plot.new_figure(FIGURE.size, 1, 3, constrained_layout=True)
    xs = np.linspace(-3.2, 3.2, ctx.res(320, 80))
    zs = np.linspace(-2.4, 2.4, ctx.res(240, 60))
    measured = {}
    for ax, family in zip(axes[1:], KERNELS):
        pair = ctx.field_of(primitives(family))
        single = ctx.field_of(primitives(family)[:1])
        level = single.f([[0, 0, 1 + TAU]])[0]
        plot.contour_segments(ax, xs, zs, pair.on_grid(xs, zs, plane="xz"), level, colors=["tab:blue"])
        for z in (1, -1):
            plot.draw_segment(ax, (-HALF_SIDE, z), (HALF_SIDE, z), lw=1.5)
        name = "cubic inverse $p^3$" if family == "inverse" else f"compact $k_R^4$, R = {R}"
        ax.set_title(f"{name}\nκ = {level:.4g}")
        ax.set_aspect("equal")
        ax.set_xlabel("x")
        # offsets of the surface from the upper square, outward (+z) and inward (−z)
        probe_x = np.array([0.0, 0.5, 1.0])
        tops = np.stack([probe_x, np.zeros(3), np.ones(3)], axis=1)
        outer = crossing(pair, tops, [0, 0, 1.0], level, 1e-9, 2.0)
        inner = crossing(pair, tops, [0, 0, -1.0], level, 1e-9, 1.0)
        line = np.stack([np.linspace(-1.0, 1.0, 21), np.zeros(21), np.full(21, 1 + TAU)], axis=1)
        f_line = pair.f(line)
        measured[family] = dict(level=level, outer=outer, inner=inner,
                                flat=float((f_line.max() - f_line.min()) / level))
        z_axis = np.linspace(-2.5, 2.5, ctx.res(501, 101))
        f_axis = pair.f(np.stack([np.zeros_like(z_axis), np.zeros_like(z_axis), z_axis], axis=1))
        axes[0].plot(z_axis, f_axis / level, label=name)
    axes[0].set_yscale("log")
    axes[0].set_ylim(1e-2, 1e3)
    axes[0].axhline(1.0, color="grey", lw=0.8, ls=":")
    axes[0].set_xlabel("z on the normal through the centres")
    axes[0].set_ylabel("f / κ (iso at 1)")
    axes[0].set_title("f along the normal")
    axes[0].legend(loc="upper center", fontsize=6)
    axes[1].set_ylabel("z")
    plot.save(fig, ctx.image_path, FIGURE.size)

    inv, com = measured["inverse"], measured["compact"]
    plane_level = np.pi * R * R * (1 - TAU * TAU / (R * R)) ** 3 / 3   # ∬ k_R⁴ over the plane at height τ
    return [
        Claim("p³: an inward bulge appears between the polygons",
              f"offset of the surface from the upper square at x = 0, 0.5, 1: inward "
              f"{', '.join(fmt(v) for v in inv['inner'])}, outward {', '.join(fmt(v) for v in inv['outer'])}",
              bool(np.all(inv["inner"] > inv["outer"] + 1e-3))),
        Claim("compact kernel: the surface is flat towards the centre, on both sides",
              f"offsets at x = 0, 0.5, 1: outward {', '.join(fmt(v, 15) for v in com['outer'])}, inward "
              f"{', '.join(fmt(v, 15) for v in com['inner'])}; f along z = 1 + τ, |x| ≤ 1: relative "
              f"variation {fmt(com['flat'])} (p³: {fmt(inv['flat'])}); κ = {fmt(com['level'], 15)} against "
              f"πR²(1 − τ²/R²)³/3 = {fmt(plane_level, 15)}",
              bool(np.all(np.abs(com["outer"] - TAU) < 1e-12) and np.all(np.abs(com["inner"] - TAU) < 1e-12)
                   and com["flat"] < 1e-13 and abs(com["level"] - plane_level) < 1e-13 * plane_level
                   and inv["flat"] > 1e-3)),
    ]
