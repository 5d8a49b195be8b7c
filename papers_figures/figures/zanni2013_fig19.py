"""Zanni et al. 2013, Figure 19: two SCALIS segments in a V, blended by max
(a) and by sum (b). Our V: both segments start at the apex with radius 0 and
their radius grows in proportion to the distance from the apex, so the V is
its own homothetic image about the apex. A scale-invariant field (SCALIS)
then blends the same way near the thin end and near the thick end: the
paper's claim. Checked on the mesh: the shape's width across the V divided
by the distance from the apex, at two stations a factor 2 apart. f on the
V's axis is printed too: it is not scale invariant, because a cone's radius
grows like the distance s from the apex, so its far parts add ∫ ds/s
(logarithmic in the arm's length) to the field everywhere."""
import numpy as np

from figlib import surface3d
from figlib.claims import Claim, fmt
from figlib.figure import Figure

KERNEL = {"family": "cauchy", "degree": 4, "sigma": 1.0}
APEX = np.array([0.0, 0.0, 0.0])
ARM = np.array([0.6, 4.0, 0.0])          # one arm ends at (±0.6, 4, 0): the arms nearly touch
TAU_END = 0.5                            # radius at the arm's end (0 at the apex)
# Stations along the axis (y), away from the apex's numerical tip and the arms' end caps.
STATIONS = np.array([1.2, 2.4])
# Widths agree to the facet size over the station (the mesh term below) and to
# the arms' finite length: 3 %.
SIMILARITY_TOLERANCE = 0.03


def v_skeleton(blend):
    arms = [{"type": "scalis_segment", "a": list(APEX), "b": [sx * ARM[0], ARM[1], 0.0], "radius": [0.0, TAU_END],
             "kernel": KERNEL, "iso": 1.0} for sx in (-1, 1)]
    return {"primitives": [{"blend": blend, "children": arms}], "iso": 1.0}


FIGURE = Figure(
    paper="Zanni et al. 2013", kind="Figure", number="19",
    caption="Placing two segment skeletons in a \"V\" shows the behaviour of the homothety-invariant blend. The "
            "blend is the same at both ends of the shape; in particular the thin end is not over-smoothed. "
            "(a) \"max\" blend, (b) \"+\" blend.",
    original_caption="Le positionnement de deux squelettes segments en \"V\" permet d'apprécier le comportement du "
                     "mélange invariant par homothétie. Le mélange est le même aux deux extrémités de la forme, "
                     "notamment l'extrémité fine n'est pas trop lissée. (a) mélange \"max\", (b) mélange \"+\".",
    section="our V (the paper's is not given): SCALIS segments from (0,0,0) to (±0.6, 4, 0), radius 0 → 0.5; "
            "blend nodes `union` (max) and `sum`",
    kernel="SCALIS Cauchy 4, σ = 1", iso="1", view="the fixed camera of render3d, one scale for both panels",
    size=(640, 300))


def draw(ctx):
    claims, meshes = [], []
    for blend, label in (("union", "(a) max"), ("sum", "(b) +")):
        skeleton = v_skeleton(blend)
        on_axis = ctx.field_of(skeleton["primitives"]).f(np.stack([0 * STATIONS, STATIONS, 0 * STATIONS], axis=1))
        m = surface3d.mesh(ctx, skeleton, 1.0, ctx.res(0.05, 0.12), f"fig19_{blend}")
        w = surface3d.widths(m, 1, 0, STATIONS)
        ratio = w / STATIONS
        claims.append(Claim(
            f"{label} blend: the same blend at the thin and at the thick end (self-similar V)",
            f"f on the axis at y = {STATIONS[0]:g}, {STATIONS[1]:g}: {fmt(on_axis[0], 5)}, {fmt(on_axis[1], 5)}; "
            f"mesh width / y there: {fmt(ratio[0])}, {fmt(ratio[1])}; {m.stats['triangles']} triangles, "
            f"closed {m.stats['closed']}",
            abs(ratio[1] / ratio[0] - 1) < SIMILARITY_TOLERANCE + 2 * ctx.res(0.05, 0.12) / STATIONS[0]
            and m.closed))
        meshes.append((m, f"{label} blend, {m.stats['triangles']} triangles"))
        if blend == "sum":
            sum_axis = on_axis
        else:
            max_axis = on_axis
    claims.append(Claim("the + blend fills the V more than max (a larger field between the arms)",
                        f"f on the axis, + / max: {fmt(sum_axis[0] / max_axis[0])}, {fmt(sum_axis[1] / max_axis[1])}",
                        np.all(sum_axis > max_axis)))
    surface3d.panels(ctx, meshes, FIGURE.size)
    return claims
