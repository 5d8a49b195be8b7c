"""Zanni et al. 2013, Figure 14 (§5.1): SCALIS surfaces before and after the
thickness correction, for the paper's two cases: radii (0,1,0) (a thickness
maximum between two tips) and (1,1) (constant radius, two free ends), with
τ = 0.5 and the compact kernel of degree 6, σ = 2 (Zanni §4.3's practice).

Each case is corrected twice:
- the paper's correction as §5.1 describes it (figlib.thickness.paper_correction:
  point primitives at the free ends and the thickness maximum, mixed by
  Barthe-type blends; the blend's operator and parameters are not in the
  paper, so they are ours);
- the project's, `skelconv thickness` on the SCALIS file (segment factors,
  ramps of classical compact segments and node points fitted to the radii,
  docs/thickness_correction.md).

Measured, independently of either: the thickness along the normal of the
skeleton's plane every τ/20 (figlib.thickness.profile, through `skelconv eval`).
Drawn as cuts in the skeleton's plane, the thickness along the skeleton, and
the meshed surfaces of the three versions."""
import numpy as np

from figlib import plot, surface3d
from figlib.claims import Claim, fmt
from figlib.figure import Figure
from figlib import thickness as th

TAU = 0.5
AFTER_WITHIN = 0.02      # |r/τ − 1| < 2 % along the skeleton after our correction (its own fit tolerance is 1 %)
END_THINNER = 0.9        # uncorrected: the (1,1) segment's free ends fall below 0.9 τ (half the skeleton is missing)
MAXIMUM_THINNER = 0.95   # uncorrected: the (0,1,0) maximum falls below 0.95 τ (the thinner parts integrate less)
CASES = {
    "(0,1,0)": [((0.0, 0.0), (2.0, 0.0), 0.0, TAU), ((2.0, 0.0), (4.0, 0.0), TAU, 0.0)],
    "(1,1)": [((0.0, 0.0), (4.0, 0.0), TAU, TAU)],
}
FACET = (0.035, 0.2)     # (full, quick) mesh facet sizes
VIEW = [0.2, -1.0, 0.45]    # from the front, a little above: the caps and the maximum in profile
# The shapes are long and thin: the camera frames the bounding sphere by the panel's height, so
# the frame's radius is shrunk to let the shape fill the panel's width instead.
FRAME_ZOOM = 0.6

FIGURE = Figure(
    paper="Zanni et al. 2013", kind="Figure", number="14",
    caption="Comparison between uncorrected (left) and corrected (right) surfaces, for thicknesses (0,1,0) and "
            "(1,1) along segment skeletons.",
    original_caption="Comparaison entre surfaces non corrigées (gauche) et corrigées (droite), pour respectivement "
                     "des épaisseurs de (0,1,0) et (1,1) le long de squelettes segments.",
    section="the paper's two cases with SCALIS segments of length 4: (0,1,0) radii 0 → 0.5 → 0, (1,1) radius 0.5; "
            "each uncorrected, corrected as the paper describes (points and Barthe-type blends: our parameters) and "
            "corrected by `skelconv thickness`: (a), (b) cuts in the skeleton's plane, (c) the thickness along the "
            "skeleton, (d)–(i) the surfaces",
    kernel=f"SCALIS compact {th.DEGREE}, σ = {th.SIGMA:g}; the paper's correction: compact points of support σ τ_n, "
           f"super-elliptic blends t = {th.BLEND_T:g}, bands {th.POINT_BAND:g} (points) and {th.SCALIS_BAND:g} "
           "(SCALIS)",
    iso="1", view="(a), (b) plane z = 0 (dotted: the requested radius); (c) thickness along z; (d)–(i) one camera, "
                  "one scale", size=(1600, 1500))


def draw(ctx):
    step = TAU / ctx.res(20, 4)
    results = {}
    for name, graph in CASES.items():
        prims = [th.scalis(a, b, r0, r1) for a, b, r0, r1 in graph]
        before, ours, _ = th.correct(ctx, prims)
        paper = th.paper_correction(prims)
        results[name] = dict(prims=prims, skeletons=(before, ours, paper),
                             profiles=[th.profile(ctx, s, prims, step) for s in (before, ours, paper)])
    worst = {n: [th.worst_departure(p) for p in r["profiles"]] for n, r in results.items()}
    ends = min(float(min(r[0], r[-1]) / TAU) for _, _, r in results["(1,1)"]["profiles"][0])
    maximum = float(results["(0,1,0)"]["profiles"][0][0][2][-1] / TAU)
    meshes = {}
    for name, r in results.items():
        meshes[name] = [surface3d.mesh(ctx, s, 1.0, ctx.res(*FACET), f"fig14_{name[1:-1].replace(',', '')}_{k}")
                        for k, s in enumerate(r["skeletons"])]
    if ctx.image_path:
        draw_image(ctx, results, meshes)
    closed = all(m.closed for ms in meshes.values() for m in ms)
    return [
        Claim("corrected, the surfaces keep the requested thickness along the whole skeleton, at the free ends and "
              "at the maximum (§5.1; §6.2: a guaranteed minimal thickness): our correction",
              f"max |r/τ − 1| after `skelconv thickness`, every τ/{ctx.res(20, 4)}: " +
              ", ".join(f"{n} {fmt(w[1])}" for n, w in worst.items()) + f" (goal < {AFTER_WITHIN:g})",
              max(w[1] for w in worst.values()) < AFTER_WITHIN),
        th.paper_claim(list(worst), [w[0] for w in worst.values()], [w[2] for w in worst.values()],
                       [w[1] for w in worst.values()]),
        Claim("uncorrected, the ends lack skeleton to integrate and come out thinner than τ, and so does the "
              "maximum of (0,1,0)",
              f"before: (1,1) ends r/τ = {fmt(ends)} (below {END_THINNER:g}); (0,1,0) maximum r/τ = {fmt(maximum)} "
              f"(below {MAXIMUM_THINNER:g})", ends < END_THINNER and maximum < MAXIMUM_THINNER),
        Claim("(ours) the six surfaces are closed manifolds",
              "; ".join(f"{n}: " + ", ".join(f"{m.stats['triangles']} triangles closed {m.stats['closed']}"
                                             for m in ms) for n, ms in meshes.items()), closed),
    ]


def draw_image(ctx, results, meshes):
    fig = plot.plt.figure(figsize=(FIGURE.size[0] / plot.DPI, FIGURE.size[1] / plot.DPI), dpi=plot.DPI,
                          constrained_layout=True)
    panels = fig.subplot_mosaic([["a", "a", "a", "b", "b", "b"], ["c", "c", "c", "c", "c", "c"],
                                 ["d", "d", "e", "e", "f", "f"], ["g", "g", "h", "h", "i", "i"]],
                                gridspec_kw={"height_ratios": [0.75, 1.0, 0.8, 0.8]})
    res = (ctx.res(480, 50), ctx.res(220, 26))
    for key, name in (("a", "(0,1,0)"), ("b", "(1,1)")):
        th.cut(panels[key], ctx, results[name]["skeletons"], results[name]["prims"], ((-0.8, 4.8), (-0.8, 1.3)),
               res, f"({key}) {name}, cut z = 0", legend_loc="upper center", legend_columns=2)
    ax = panels["c"]
    th.plot_profiles(ax, [(n, *r["profiles"]) for n, r in results.items()],
                     "(c) thickness along the skeleton, left end to right end")
    ax.axhspan(1 - AFTER_WITHIN, 1 + AFTER_WITHIN, color="0.88", label=f"±{AFTER_WITHIN:.0%}")
    ax.legend(loc="lower center", fontsize=8, ncol=4)
    frame = surface3d.common_frame([m for ms in meshes.values() for m in ms])
    layout = (FIGURE.size[0] / 3, 0.8 / 3.35 * FIGURE.size[1] - 30)
    for keys, name in (("def", "(0,1,0)"), ("ghi", "(1,1)")):
        for key, m, (label, _, _) in zip(keys, meshes[name], th.VERSIONS):
            surface3d.picture(panels[key], m, FIGURE.size, layout,
                              frame=(surface3d.povray.framing(m.vertices)[0], FRAME_ZOOM * frame[1]),
                              view=VIEW, title=f"({key}) {name}, {label}")
    plot.save(fig, ctx.image_path, FIGURE.size)
