"""Zanni et al. 2013, Figure 6: three thin primitives (same radius, different
lengths) blended by sum with a thick horizontal one. Classical convolution
smooths the details away, SCALIS keeps them. Drawn as the section z = 0;
measured: the radius of each thin primitive at 3/4 of its length, in the
blend, against its own radius."""
import numpy as np

from figlib import plot
from figlib.claims import Claim, fmt
from figlib.figure import Figure, load_skeleton
from figlib.levelset import crossing
from figlib.zanni import classical_cauchy_line, classical_segment

SKELETON = "zanni_fig6_scalis.json"
DEGREE = 4
SIGMA = 1.0
THICK = 1.0
ISO_CLASSICAL = classical_cauchy_line(THICK, THICK, DEGREE, SIGMA)   # radius 1 around the thick one

FIGURE = Figure(
    paper="Zanni et al. 2013", kind="Figure", number="6",
    caption="Blend of 3 primitives of small thickness (same thickness, varying length) with a thick linear primitive "
            "(horizontal segment). Details are smoothed when convolution surfaces are used (a), but not with "
            "homothetic surfaces (b).",
    original_caption="Mélange de 3 primitives à faible épaisseur (même épaisseur, longueur variable) avec une primitive "
                     "linéique épaisse (segment horizontal). Les détails sont lissés lorsque les surfaces de convolution "
                     "sont utilisées (a), mais pas avec les surfaces homothétiques (b).",
    section="the section z = 0 (our skeleton: the paper's is not given); thin radius 0.25, thick radius 1",
    skeletons=[SKELETON], kernel="Cauchy 4, σ = 1 (classical: c_s⁴ with s = 1, weight τ)",
    iso=f"SCALIS 1; classical {ISO_CLASSICAL:.5g} (radius 1 around the thick segment alone)",
    view="plane z = 0", size=(640, 280))


def draw(ctx):
    scalis = load_skeleton(SKELETON)["primitives"]
    classical = [classical_segment(p["a"], p["b"], p["radius"][0], p["radius"][1], "cauchy", DEGREE, SIGMA) for p in scalis]
    thin = [p for p in scalis if p["radius"][0] < THICK]
    xs = np.linspace(-4.5, 4.5, ctx.res(450, 110))
    ys = np.linspace(-1.8, 4.8, ctx.res(330, 80))
    fig, axes = plot.new_figure(FIGURE.size, 1, 2, constrained_layout=True, sharey=True)
    measured = {}
    for ax, prims, level, colour, title in ((axes[0], classical, ISO_CLASSICAL, plot.CLASSICAL, "(a) classical"),
                                            (axes[1], scalis, 1.0, plot.SCALIS, "(b) SCALIS")):
        field = ctx.field_of(prims)
        plot.contour_segments(ax, xs, ys, field.on_grid(xs, ys), level, colors=[colour])
        for p in scalis:
            plot.draw_segment(ax, p["a"], p["b"], lw=1.2)
        ax.set_aspect("equal")
        ax.set_xlabel("x")
        ax.set_title(f"{title}, iso {level:.4g}")
        probes = np.array([np.asarray(p["a"], float) + 0.75 * (np.asarray(p["b"], float) - np.asarray(p["a"], float))
                           for p in thin])
        measured[title[:3]] = crossing(field, probes, [1.0, 0, 0], level, 1e-9, 0.99)   # NaN: no surface / merged
    axes[0].set_ylabel("y")
    plot.save(fig, ctx.image_path, FIGURE.size)
    tau = thin[0]["radius"][0]
    c, s = measured["(a)"], measured["(b)"]
    describe = lambda r: ", ".join("none" if np.isnan(v) else fmt(v) for v in r)
    return [Claim(
        "details (thin primitives blended with a thick one) are smoothed by classical convolution, kept by SCALIS",
        f"radius of the 3 thin primitives at 3/4 of their length (their own radius {tau:g}): SCALIS {describe(s)}; "
        f"classical {describe(c)} (none: the thin part is not there, only a bump of the thick one's surface)",
        bool(np.all(np.abs(s - tau) < 0.4 * tau) and np.all(np.abs(np.nan_to_num(c, nan=0.0) - tau) > 0.4 * tau)))]
