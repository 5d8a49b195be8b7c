"""Zanni et al. 2013, Figure 7: a homothety applied to the skeleton and to the
radii. Classical convolution (a) does not give similar shapes, SCALIS (b)
does. Cauchy 4, σ = 1/2; homothety ratios 1/3 then 1/2 (scales 1, 1/3, 1/6).
Each shape is drawn scaled back to size 1, and compared with the unscaled
one by the Hausdorff distance of the section curves ÷ the shape's size."""
import numpy as np

from figlib import plot
from figlib.claims import Claim, fmt
from figlib.figure import Figure, load_skeleton, scaled_primitives
from figlib.levelset import densify, hausdorff
from figlib.zanni import classical_cauchy_line, classical_segment

SKELETON = "zanni_fig7_scalis.json"
SIGMA = 0.5
DEGREE = 4
SCALES = (1.0, 1.0 / 3.0, 1.0 / 6.0)
SIZE = 6.0                 # the skeleton's extent at scale 1 (for relative distances)
MAIN_RADIUS = 1.0          # the radius of the long segment at scale 1
ISO_CLASSICAL = classical_cauchy_line(MAIN_RADIUS, MAIN_RADIUS, DEGREE, SIGMA)

FIGURE = Figure(
    paper="Zanni et al. 2013", kind="Figure", number="7",
    caption="A homothety applied both to the dimensions of a convolution skeleton and to the associated weights τ. "
            "The classical formulation (a) does not generate similar shapes, unlike the homothetic formulation (b). "
            "The kernel is Cauchy 4 with σ = 1/2. For (a), τ = 14 for the largest shape; for (b), τ = 1. The ratio "
            "of the first homothety is 1/3, that of the second 1/2.",
    original_caption="Application d'une homothétie à la fois aux dimensions d'un squelette de convolution et aux "
                     "poids τ associés. La formulation classique (a) ne génère pas des formes similaires contrairement "
                     "à la formulation homothétique (b). Le noyau utilisé est Cauchy 4 avec σ = 1/2. Pour (a), on a "
                     "τ = 14 pour la forme la plus grande, pour (b), on a τ = 1. Le rapport de la première homothétie "
                     "est 1/3, celui de la seconde est 1/2.",
    section="the section z = 0 of a T-shaped skeleton (our own; the paper's is not given), at scales 1, 1/3, 1/6, "
            "each scaled back to size 1; weights/radii 1 and 0.5 at scale 1 (the paper's τ = 14 is in its own units)",
    skeletons=[SKELETON], kernel="Cauchy 4, σ = 1/2 (classical: c_s⁴ with s = 1/σ² = 4, weight τ)",
    iso=f"SCALIS 1; classical {ISO_CLASSICAL:.5g} (radius 1 around the long segment at scale 1)",
    view="plane z = 0, shapes scaled back to size 1", size=(640, 280))


def classical_from(prims):
    return [classical_segment(p["a"], p["b"], p["radius"][0], p["radius"][1], "cauchy", DEGREE, SIGMA) for p in prims]


def section(ctx, prims, level, alpha, n):
    """The level curve in z = 0 on a grid scaled by alpha, returned scaled back by 1/alpha."""
    xs = np.linspace(-4.5, 4.5, n) * alpha
    ys = np.linspace(-2.5, 4.5, int(n * 7 / 9)) * alpha
    grid = ctx.field_of(prims).on_grid(xs, ys)
    fig, ax = plot.new_figure((100, 100))
    lines = plot.contour_segments(ax, xs / alpha, ys / alpha, grid, level)
    plot.save(fig, None, (100, 100))
    return lines


def draw(ctx):
    base = load_skeleton(SKELETON)["primitives"]
    n = ctx.res(361, 91)
    fig, axes = plot.new_figure(FIGURE.size, 1, 2, constrained_layout=True, sharey=True)
    distances = {}
    styles = ("-", "--", ":")
    for ax, kind, colour in zip(axes, ("classical", "scalis"), (plot.CLASSICAL, plot.SCALIS)):
        reference = None
        distances[kind] = []
        for alpha, style in zip(SCALES, styles):
            prims = scaled_primitives(base, alpha)
            if kind == "classical":
                prims, level = classical_from(prims), ISO_CLASSICAL
            else:
                level = 1.0
            lines = section(ctx, prims, level, alpha, n)
            for k, line in enumerate(lines):
                ax.plot(line[:, 0], line[:, 1], color=colour, ls=style,
                        label=f"scale {fmt(alpha)}, scaled back" if k == 0 else None)
            points = densify(lines, 0.01)
            if reference is None:
                reference = points
            else:
                distances[kind].append(hausdorff(reference, points) / SIZE if len(points) else np.inf)
        for p in base:
            plot.draw_segment(ax, p["a"], p["b"], lw=1.2)
        ax.set_aspect("equal")
        ax.set_xlabel("x / scale")
        ax.legend(loc="lower center", fontsize=6)
    axes[0].set_title("(a) classical: shapes differ")
    axes[1].set_title("(b) SCALIS: similar shapes")
    axes[0].set_ylabel("y / scale")
    plot.save(fig, ctx.image_path, FIGURE.size)
    c, s = distances["classical"], distances["scalis"]
    return [
        Claim("(b) SCALIS: the homothetic shapes are similar",
              f"Hausdorff distance to the unscaled section ÷ size, scales 1/3 and 1/6: {fmt(s[0])}, {fmt(s[1])}",
              max(s) < 1e-9),
        Claim("(a) classical: the shapes are not similar",
              f"same distance, scales 1/3 and 1/6: {fmt(c[0])}, {fmt(c[1])}", min(c) > 0.02),
    ]
