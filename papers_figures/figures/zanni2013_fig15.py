"""Zanni et al. 2013, Figure 15 (§5.1, §6.1): examples of thickness correction
on SCALIS shapes. The paper shows pictures only; we draw three graphs of the
kinds §5.1 names (free extremities, a node of maximal radius, segments that
meet): an L corner of constant radius, a Y fork of unequal radii and the
(0,1,0) thickness maximum of Figure 14, corrected by `skelconv thickness`
(the SCALIS variant, docs/thickness_correction.md), and corrected as the
paper describes it (figlib.thickness.paper_correction: point primitives at
the free ends and maxima, Barthe-type blends whose parameters are ours).

Measured, independently of the command's optimiser: the thickness along the
plane's normal every τ_max/20 (figlib.thickness)."""
import numpy as np

from figlib import plot, surface3d
from figlib.claims import Claim, fmt
from figlib.figure import Figure
from figlib import thickness as th

TAU_MAX = 0.5
AFTER_WITHIN = 0.02    # the claim of docs/thickness_correction.md: |r/τ − 1| < 2% along every segment, between the fit's samples too (it holds 1% at them)
BEFORE_OFF = 0.05      # each example needs the correction: uncorrected, somewhere more than 5% from τ(t)
FACET = (0.035, 0.2)   # (full, quick) facet sizes of the Y fork's meshes
VIEW = [0.35, -0.6, 1.0]   # from above the graph's plane, in front


def polar(length, degrees):
    a = np.radians(degrees)
    return (length * np.cos(a), length * np.sin(a))


EXAMPLES = {
    "L corner": [((3.0, 0.0), (0.0, 0.0), 0.5, 0.5), ((0.0, 0.0), (0.0, 3.0), 0.5, 0.5)],
    "Y fork": [((0.0, 0.0), polar(3, 90), 0.5, 0.4), ((0.0, 0.0), polar(3, 210), 0.5, 0.3),
               ((0.0, 0.0), polar(3, 330), 0.5, 0.5)],
    "(0,1,0) maximum": [((0.0, 0.0), (2.0, 0.0), 0.0, 0.5), ((2.0, 0.0), (4.0, 0.0), 0.5, 0.0)],
}

FIGURE = Figure(
    paper="Zanni et al. 2013", kind="Figure", number="15",
    caption="Different examples of thickness correction.",
    original_caption="Différents exemples de correction d'épaisseur.",
    section="three graphs of our own (the paper prints no coordinates) of the kinds §5.1 corrects: free ends and "
            "a corner (L, radius 0.5), a junction of unequal radii (Y: 0.5 at the junction, 0.4, 0.3, 0.5 at the "
            "ends), a node of maximal radius (radii 0 → 0.5 → 0, Figure 14's (0,1,0)); cut in their plane before "
            "and after the paper's correction (as its text describes it) and ours, their thickness along the "
            "skeleton, and the Y fork's three surfaces",
    kernel=f"SCALIS compact {th.DEGREE}, σ = {th.SIGMA:g}; ours: `skelconv thickness` (segment factors, ramps of "
           f"classical compact segments, node points); the paper's: compact points of support σ τ_n, super-elliptic "
           f"blends t = {th.BLEND_T:g}, bands {th.POINT_BAND:g} (points) and {th.SCALIS_BAND:g} (SCALIS)",
    iso="1", view="(a)–(c) plane z = 0 (dotted: the requested radius τ(t)); (d) thickness along z; (e)–(g) one "
                  "camera, one scale",
    size=(1700, 1800))


def draw(ctx):
    step = TAU_MAX / ctx.res(20, 4)
    results = {}
    for name, graph in EXAMPLES.items():
        prims = [th.scalis(a, b, r0, r1) for a, b, r0, r1 in graph]
        before, after, _ = th.correct(ctx, prims)
        paper = th.paper_correction(prims)
        results[name] = dict(prims=prims, skeletons=(before, after, paper),
                             before=th.profile(ctx, before, prims, step), after=th.profile(ctx, after, prims, step),
                             paper=th.profile(ctx, paper, prims, step))
    worst_after = {n: th.worst_departure(r["after"]) for n, r in results.items()}
    worst_before = {n: th.worst_departure(r["before"]) for n, r in results.items()}
    worst_paper = {n: th.worst_departure(r["paper"]) for n, r in results.items()}
    fork = [surface3d.mesh(ctx, s, 1.0, ctx.res(*FACET), f"fig15_fork_{k}")
            for k, s in enumerate(results["Y fork"]["skeletons"])]
    if ctx.image_path:
        draw_image(ctx, results, fork)
    return [th.paper_claim(list(results), list(worst_before.values()), list(worst_paper.values()),
                           list(worst_after.values())),
            Claim("(ours) the Y fork's three surfaces are closed manifolds",
                  ", ".join(f"{m.stats['triangles']} triangles closed {m.stats['closed']}" for m in fork),
                  all(m.closed for m in fork)),
        Claim("the correction gives the shapes the thickness their radii ask for (§5.1; §6.2: a guaranteed minimal "
              "thickness on a skeleton graph)",
              f"max |r/τ(t) − 1| after correction, every τ_max/{ctx.res(20, 4)}: " +
              ", ".join(f"{n}: {fmt(w)}" for n, w in worst_after.items()) + f" (goal < {AFTER_WITHIN:g})",
              max(worst_after.values()) < AFTER_WITHIN),
        Claim("(why the correction) uncorrected, each shape departs from its radii: thin ends, a thin maximum, a "
              "bulging junction",
              "max |r/τ(t) − 1| before: " + ", ".join(f"{n}: {fmt(w)}" for n, w in worst_before.items()) +
              f" (above {BEFORE_OFF:g})",
              min(worst_before.values()) > BEFORE_OFF),
    ]


def draw_image(ctx, results, fork):
    fig, _ = plot.new_figure(FIGURE.size, 1, 1, constrained_layout=True)
    fig.clf()
    panels = fig.subplot_mosaic([["a", "a", "a", "b", "b", "b"], ["c", "c", "c", "b", "b", "b"],
                                 ["d", "d", "d", "d", "d", "d"], ["e", "e", "f", "f", "g", "g"]],
                                height_ratios=[1.1, 0.7, 1.1, 1.2])
    res = (ctx.res(420, 50), ctx.res(360, 40))
    th.cut(panels["a"], ctx, results["L corner"]["skeletons"], results["L corner"]["prims"],
           ((-1.0, 3.8), (-1.0, 3.8)), res, "(a) L corner, radius 0.5")
    th.cut(panels["b"], ctx, results["Y fork"]["skeletons"], results["Y fork"]["prims"],
           ((-3.3, 3.3), (-2.2, 3.6)), res, "(b) Y fork, radii 0.5 at the junction; 0.4 (up), 0.3, 0.5 at the ends")
    th.cut(panels["c"], ctx, results["(0,1,0) maximum"]["skeletons"], results["(0,1,0) maximum"]["prims"],
           ((-0.4, 4.4), (-0.8, 0.8)), (res[0], res[1] // 2), "(c) radii 0 → 0.5 → 0 (Figure 14's (0,1,0))")
    ax = panels["d"]
    th.plot_profiles(ax, [(n, r["before"], r["after"], r["paper"]) for n, r in results.items()],
                     "(d) thickness along every segment (junctions: from the node)")
    ax.axhspan(1 - AFTER_WITHIN, 1 + AFTER_WITHIN, color="0.88", label=f"±{AFTER_WITHIN:.0%}")
    ax.legend(loc="lower left", fontsize=8, ncol=4)
    radius = surface3d.common_frame(fork)[1]
    layout = (FIGURE.size[0] / 3, 1.2 / 4.1 * FIGURE.size[1] - 30)
    for key, m, (label, _, _) in zip("efg", fork, th.VERSIONS):
        surface3d.picture(panels[key], m, FIGURE.size, layout, frame=(surface3d.povray.framing(m.vertices)[0], radius),
                          view=VIEW, title=f"({key}) Y fork, {label}")
    plot.save(fig, ctx.image_path, FIGURE.size)
