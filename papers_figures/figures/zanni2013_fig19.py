"""Zanni et al. 2013, Figure 19: two SCALIS segments in a V, blended by max
(a) and by sum (b). Our V: both segments start at the apex with radius 0 and
their radius grows in proportion to the distance from the apex, so the V is
its own homothetic image about the apex. A scale-invariant field then blends
the same way near the thin end and near the thick end: the paper's claim.

Checked with the field, as the identity it is: for SCALIS, f(apex + λ(P − apex))
= f(P) for every P whose kernel support does not reach the arms' far ends
(the substitution s → λs in eq. 14, with τ(λs) = λτ(s)). The kernel is the
compact one of §4.3 (degree 6), so that the arms' far ends are out of reach of
the points checked: with an infinite kernel the far parts of a cone add a
logarithmic term ∫ ds/s everywhere and the identity only holds for an infinite
V. The same check on the wrong model, classical convolution of the same V
(weight τ(s), one fixed kernel), must fail: its blend does depend on the scale.

The V is open (the arms apart, the field on the V's axis below the level), so
that the blend is the rounding of the crotch between the arms, drawn front-on."""
import numpy as np

from figlib import surface3d
from figlib.claims import Claim, fmt
from figlib.figure import Figure
from figlib.zanni import classical_segment

DEGREE, SIGMA = 6, 3.0                   # compact SCALIS kernel, support σ τ
KERNEL = {"family": "compact", "degree": DEGREE, "sigma": SIGMA}
APEX = np.array([0.0, 0.0, 0.0])
ARM = np.array([2.4, 8.0, 0.0])          # one arm ends at (±2.4, 8, 0): half-angle atan 0.3 = 16.7°
# Radius / distance from the apex: 0.57 of the half-angle's tangent, so that on the V's axis
# each arm is seen at 1.75 τ: its field there is below half the level, so the crotch stays
# open under max and under + (measured: the claims print f on the axis), while the supports
# σ τ = 3 τ overlap there and the + blend's fuller crotch shows.
SLOPE = 0.17
TAU_END = SLOPE * float(np.linalg.norm(ARM))
# The identity is checked at points of a cross-section of the V (station y = 1.5, across
# both arms and the crotch, and above the plane) against the same points scaled by 1/3
# (the thin end, y = 0.5) and by 2 (y = 3): every station is far enough from the arms'
# ends (8.35 long) that the supports (reaching arm parameters up to 1/(1 − 3 × 0.17) of
# their own) do not see them.
STATION = 1.5
SCALES = (1.0 / 3.0, 2.0)
# An exact identity: the tolerance is the evaluation's accuracy (closed forms and Gauss
# panels to ~1e-14 relative), with a margin of 100 for the sum over two arms.
INVARIANCE_TOLERANCE = 1e-12
FACET = (0.06, 0.15)                     # (full, quick) facet sizes
VIEW = [0.0, -0.12, 1.0]                 # front-on: looking down on the V's plane z = 0

FIGURE = Figure(
    paper="Zanni et al. 2013", kind="Figure", number="19",
    caption="Placing two segment skeletons in a \"V\" shows the behaviour of the homothety-invariant blend. The "
            "blend is the same at both ends of the shape; in particular the thin end is not over-smoothed. "
            "(a) \"max\" blend, (b) \"+\" blend.",
    original_caption="Le positionnement de deux squelettes segments en \"V\" permet d'apprécier le comportement du "
                     "mélange invariant par homothétie. Le mélange est le même aux deux extrémités de la forme, "
                     "notamment l'extrémité fine n'est pas trop lissée. (a) mélange \"max\", (b) mélange \"+\".",
    section=f"our V (the paper's is not given): SCALIS segments from (0,0,0) to (±{ARM[0]:g}, {ARM[1]:g}, 0), radius "
            f"0 → {TAU_END:.3g} (radius = {SLOPE:g} × distance from the apex); blend nodes `union` (max) and `sum`",
    kernel=f"SCALIS compact, degree {DEGREE}, σ = {SIGMA:g} (wrong model: classical Cauchy 4, weight τ(s))",
    iso="1", view="front-on (looking down on the V's plane), one scale for both panels",
    size=(1600, 900))


def arms():
    return [np.array([sx * ARM[0], ARM[1], 0.0]) for sx in (-1, 1)]


def v_skeleton(blend):
    children = [{"type": "scalis_segment", "a": list(APEX), "b": list(end), "radius": [0.0, TAU_END],
                 "kernel": KERNEL, "iso": 1.0} for end in arms()]
    return {"primitives": [{"blend": blend, "children": children}], "iso": 1.0}


def classical_v(blend):
    """The wrong model: eq. 10 with weight τ(s) (0 at the apex) and one Cauchy 4 kernel, σ = 1."""
    children = [classical_segment(APEX, end, 0.0, TAU_END, "cauchy", 4, 1.0) for end in arms()]
    return {"primitives": [{"blend": blend, "children": children}]}


def probes():
    """Points of the cross-section y = STATION: across both arms and the crotch, in and above the plane."""
    half_width = (ARM[0] / ARM[1] + SLOPE) * STATION        # the arm's axis plus its radius, at y = STATION
    xs = np.linspace(-1.0, 1.0, 17) * half_width
    zs = np.array([0.0, 0.05, 0.1]) * STATION
    return np.array([[x, STATION, z] for x in xs for z in zs]) + APEX


def invariance(field):
    """max over λ in SCALES and the probes P of |f(apex + λ(P − apex)) − f(P)| / max f(P)."""
    p = probes()
    here = field.f(p)
    worst = max(float(np.max(np.abs(field.f(APEX + scale * (p - APEX)) - here))) for scale in SCALES)
    return worst / float(np.max(np.abs(here))), float(np.max(here))


def draw(ctx):
    claims, meshes = [], []
    for blend, label in (("union", "(a) max"), ("sum", "(b) +")):
        skeleton = v_skeleton(blend)
        field = ctx.field_of(skeleton["primitives"])
        departure, peak = invariance(field)
        wrong, _ = invariance(ctx.field_of(classical_v(blend)["primitives"]))
        on_axis = field.f([[0.0, scale * STATION, 0.0] for scale in (SCALES[0], 1.0, SCALES[1])])
        m = surface3d.mesh(ctx, skeleton, 1.0, ctx.res(*FACET), f"fig19_{blend}")
        claims.append(Claim(
            f"{label} blend: the same blend at the thin and at the thick end (SCALIS: f(λP) = f(P) about the apex)",
            f"max |f(λP) − f(P)| / max f, λ = 1/3 and 2, over {len(probes())} points of the section y = {STATION:g} "
            f"(so at y = 0.5, 1.5, 3): {fmt(departure)} (tolerance {INVARIANCE_TOLERANCE:g}; max f there {fmt(peak)}); "
            f"f on the V's axis there: {', '.join(fmt(v, 6) for v in on_axis)} "
            f"({'below 1: the V is open' if on_axis.max() < 1 else 'above 1: the crotch is filled'}); mesh "
            f"{m.stats['triangles']} triangles, closed {m.stats['closed']}",
            departure < INVARIANCE_TOLERANCE and m.closed))
        claims.append(Claim(
            f"(wrong model) {label} blend of the classical convolution of the same V fails the same check",
            f"max |f(λP) − f(P)| / max f: {fmt(wrong)}", not wrong < INVARIANCE_TOLERANCE))
        meshes.append((m, f"{label} blend, {m.stats['triangles']} triangles"))
    surface3d.panels(ctx, meshes, FIGURE.size, view=VIEW)
    return claims
