"""Zanni et al. 2013, Figure 18 (§6.2): water drops, each from 3 SCALIS segments,
with the thickness correction of §5.1: pointed on one side, thick and round
on the other. Two drops (a straight one and a bent one), radius 0 at the tip
growing to 0.5 at the thick end; the paper prints no coordinates, so these
are ours. Corrected by `skelconv thickness` (the SCALIS variant: a factor per
segment, ramps and a point at the corrected nodes; docs/thickness_correction.md).

Measured, independently of the command's optimiser: the thickness along the
plane's normal every τ_max/20 (figlib.thickness), and along the drop's axis
how far the surface reaches beyond the tip and beyond the thick end."""
import numpy as np

from figlib import plot
from figlib.claims import Claim, fmt
from figlib.figure import Figure
from figlib import thickness as th

TAU_MAX = 0.5
AFTER_WITHIN = 0.02     # the claim of docs/thickness_correction.md: |r/τ − 1| < 2% along every segment, between the fit's samples too (it holds 1% at them)
POINTED = 0.05          # pointed: the surface ends within 0.05 τ_max beyond the tip (a round cap would reach ~τ there)
ROUND = (0.9, 1.1)      # round: beyond the thick end the surface reaches τ_end ± 10% (a hemispherical cap)
THIN_END = 0.9          # uncorrected: the thick end's thickness falls below 0.9 τ_end (half the skeleton is missing)

DROPS = {
    "straight drop": [((0.0, 0.0), (1.2, 0.0), 0.0, 0.3), ((1.2, 0.0), (1.9, 0.0), 0.3, 0.45),
                      ((1.9, 0.0), (2.3, 0.0), 0.45, 0.5)],
    "bent drop": [((0.0, 0.0), (1.0, 0.3), 0.0, 0.25), ((1.0, 0.3), (1.7, 0.7), 0.25, 0.4),
                  ((1.7, 0.7), (2.1, 1.1), 0.4, 0.5)],
}

FIGURE = Figure(
    paper="Zanni et al. 2013", kind="Figure", number="18",
    caption="Water drops created from 3 homothetic segment primitives each, applying the thickness correction "
            "of section 5.1.",
    original_caption="Gouttes d'eau créées à partir de 3 primitives segments homothétiques chacune et en appliquant "
                     "la méthode de correction d'épaisseur de la section 5.1.",
    section="two drops of our own (the paper prints no coordinates), each from 3 SCALIS segments with radii "
            "0 → … → 0.5, cut in their plane before and after the correction, and their thickness along the "
            "skeleton",
    kernel=f"SCALIS compact {th.DEGREE}, σ = {th.SIGMA:g}; radii straight: 0, 0.3, 0.45, 0.5; bent: 0, 0.25, "
           "0.4, 0.5; after: `skelconv thickness` (segment factors, ramps of classical compact segments, node points)",
    iso="1", view="(a), (b) plane z = 0 (dotted: the requested radius τ(t)); (c) thickness along z",
    size=(1600, 1300))


def primitives_of(drop):
    return [th.scalis(a, b, r0, r1) for a, b, r0, r1 in drop]


def axis_extents(ctx, skeleton, drop):
    """(beyond the tip, beyond the thick end) along the first and last segments' directions."""
    (a0, b0, _, _), (a1, b1, _, r_end) = drop[0], drop[-1]
    out_tip = np.subtract(a0, b0) / np.linalg.norm(np.subtract(a0, b0))
    out_end = np.subtract(b1, a1) / np.linalg.norm(np.subtract(b1, a1))
    reach = 2 * th.SIGMA * TAU_MAX
    tip = th.extent_beyond(ctx, skeleton, (*a0, 0.0), (*out_tip, 0.0), reach)
    end = th.extent_beyond(ctx, skeleton, (*b1, 0.0), (*out_end, 0.0), reach)
    return tip, end / r_end


def draw(ctx):
    step = TAU_MAX / ctx.res(20, 4)
    results = {}
    for name, drop in DROPS.items():
        prims = primitives_of(drop)
        before, after, _ = th.correct(ctx, prims)
        results[name] = dict(prims=prims, skeletons=(before, after),
                             before=th.profile(ctx, before, prims, step), after=th.profile(ctx, after, prims, step),
                             extent_before=axis_extents(ctx, before, drop), extent_after=axis_extents(ctx, after, drop))
    worst = max(th.worst_departure(r["after"]) for r in results.values())
    tips = [r["extent_after"][0] / TAU_MAX for r in results.values()]
    ends = [r["extent_after"][1] for r in results.values()]
    thin = [float(r["before"][-1][2][-1] / r["before"][-1][1][-1]) for r in results.values()]
    if ctx.image_path:
        draw_image(ctx, results)
    names = list(results)
    return [
        Claim("with the correction of §5.1, the drops keep the requested thickness along the whole skeleton",
              f"max |r/τ(t) − 1| after correction, both drops, every τ_max/{ctx.res(20, 4)}: {fmt(worst)} "
              f"(goal < {AFTER_WITHIN:g})", worst < AFTER_WITHIN),
        Claim("pointed on one side",
              "surface beyond the tip along the axis, ÷ τ_max: " +
              ", ".join(f"{n}: {fmt(t)}" for n, t in zip(names, tips)) + f" (below {POINTED:g})",
              max(tips) < POINTED),
        Claim("thick and round on the other (our reading: a cap of radius τ_end beyond the thick end)",
              "surface beyond the thick end along the axis, ÷ τ_end: " +
              ", ".join(f"{n}: {fmt(e)}" for n, e in zip(names, ends)) + f" (a round cap: in [{ROUND[0]:g}, {ROUND[1]:g}])",
              all(ROUND[0] <= e <= ROUND[1] for e in ends), expect_agreement=False,
              note="the correction fits the thickness along the plane's normal at the skeleton's points, not the "
                   "cap's extent along the axis: the straight drop's cap reaches past τ_end (the thickness at the "
                   "end itself is within 1%), the \"slight unwanted swellings\" §5.1 admits"),
        Claim("(why the correction) uncorrected, the thick end lacks skeleton to integrate and is too thin",
              "r/τ at the thick end before correction: " + ", ".join(f"{n}: {fmt(t)}" for n, t in zip(names, thin)) +
              f" (below {THIN_END:g})", max(thin) < THIN_END),
    ]


def draw_image(ctx, results):
    fig, _ = plot.new_figure(FIGURE.size, 1, 1, constrained_layout=True)
    fig.clf()
    panels = fig.subplot_mosaic([["a", "b"], ["c", "c"]], height_ratios=[1.2, 1])
    res = (ctx.res(520, 60), ctx.res(300, 40))
    straight, bent = results["straight drop"], results["bent drop"]
    th.cut(panels["a"], ctx, straight["skeletons"], straight["prims"], ((-0.4, 3.0), (-0.8, 0.8)), res,
           "(a) straight drop, cut z = 0 (its plane)")
    th.cut(panels["b"], ctx, bent["skeletons"], bent["prims"], ((-0.4, 2.8), (-0.6, 1.8)), res,
           "(b) bent drop, cut z = 0")
    ax = panels["c"]
    th.plot_profiles(ax, [(n, r["before"], r["after"]) for n, r in results.items()],
                     "(c) thickness along the skeleton, tip (left) to thick end (right)")
    ax.axhspan(1 - AFTER_WITHIN, 1 + AFTER_WITHIN, color="0.88", label=f"±{AFTER_WITHIN:.0%}")
    ax.legend(loc="lower left", fontsize=8, ncol=3)
    plot.save(fig, ctx.image_path, FIGURE.size)
