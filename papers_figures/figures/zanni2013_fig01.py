"""Zanni et al. 2013, Figure 1: an implicit ant on an implicit branch, made of
SCALIS segments and triangles with the compact kernel of degree 6 (figlib/ant.py:
our skeleton, the paper prints none). Measured on the field (ray casting) and
on the mesh: the thin antenna and the thick branch keep their radius τ exactly
where the compact guarantee applies, a leg leaving the body is the leg alone
(no blending bulge), and the surface is one closed manifold of genus 5. The
thickness and junction checks are run on the wrong model too (the same skeleton
as a classical convolution, figlib.ant.classical_ant), where they must fail."""
import numpy as np

from figlib import ant, surface3d
from figlib.claims import Claim, fmt
from figlib.figure import Figure

# Probes of the thickness check: (primitive index, t): the two antennae's middle segments
# (τ = 0.045) and the branch (τ = 2.2) at x = 4, clear of the ant and of the branch's ends.
# figlib.ant.probe_is_clear confirms each one is where the compact guarantee applies.
THICKNESS_PROBES = [(14, 0.5), (17, 0.5), (37, 14 / 18)]
# The compact guarantee makes f = iso exactly at distance τ there; what remains is rounding and
# the root finder (levelset.X_TOL = 1e-15): 1e-9 relative leaves room for both and nothing else.
RELATIVE_TOLERANCE = 1e-9
# The junction probe: the middle legs' femurs (their three segments) at t = 0.7, the first
# tenth of the femur outside every other part's support (figlib.ant.probe_is_clear for the
# rest of the ant; the front and hind femurs have no such point before the knee).
LEG_CHAINS = [(25, 26, 27), (28, 29, 30)]
LEG_T = 0.7
# The wrong model fails the junction check when the body changes its leg's radius by more than
# 5 % there (a bulge one would see on a leg of radius 0.1); measured: far more, or no crossing.
BULGE = 0.05
# Genus 5: the six legs each join the body to the branch, so body + branch + 6 legs close
# 6 − 1 = 5 independent loops; Euler characteristic 2 − 2 g = −8.
EULER = -8
VIEW = [0.35, -1.0, 0.45]             # from the ant's right side, a little above and in front
FRAME = ([-0.75, 0.0, 0.8], 3.35)      # the ant fills the picture; the branch runs out of it

FIGURE = Figure(
    paper="Zanni et al. 2013", kind="Figure", number="1",
    caption="Implicit ant on an implicit branch.",
    original_caption="Fourmi implicite sur branche implicite",
    section="our ant (the paper prints no skeleton): 34 SCALIS segments and 4 SCALIS triangles (head, mandibles), "
            "radii 0.045 (antennae) to 0.8 (gaster), on a branch segment of radius 2.2; (b) the skeleton inside the "
            "translucent surface (tubes: segments, blue plates: triangles); (c) the wrong model, the same ant as a "
            "classical convolution (no branch: its radius exceeds the kernel's support)",
    skeletons=[ant.ANT], kernel="SCALIS compact, degree 6, σ = 1.5 (classical comparison: k_R^6, R = 1.2)",
    iso="1", view="per-figure camera on the ant", size=(1500, 440))


def thickness_errors(field, prims, reach, probes):
    """Per probe (index, t) of the SCALIS skeleton prims: the relative errors r/τ − 1 of the radius
    of `field` along RAYS perpendicular rays reaching reach·τ (NaN: no crossing)."""
    out = []
    for index, t in probes:
        point, tau, axis, clear = ant.segment_probe(prims, index, t)
        if not clear:
            raise ValueError(f"probe {index} at t = {t}: the compact guarantee does not apply there")
        out.append(ant.radii(field, point, ant.perpendicular_rays(axis, ant.RAYS), 1.0, reach * tau) / tau - 1)
    return np.array(out)


def leg_ratios(ctx, model, prims, reach):
    """Per middle leg: radius in the whole model ÷ radius of the leg's own three segments in that
    model, on RAYS rays reaching reach·τ (model: the ant's primitives, SCALIS or classical, in the
    order of prims; a ray running into the body has no crossing: reach stays below the gap)."""
    out = []
    for chain in LEG_CHAINS:
        point, tau, axis, _ = ant.segment_probe(prims, chain[0], LEG_T)
        if not all(ant.distance(point, q) >= ant.support(q) + 1.1 * tau for k, q in enumerate(prims) if k not in chain):
            raise ValueError(f"leg probe {chain[0]} at t = {LEG_T}: within another part's support")
        rays = ant.perpendicular_rays(axis, ant.RAYS)
        whole = ant.radii(ctx.field_of(model), point, rays, 1.0, reach * tau)
        alone = ant.radii(ctx.field_of([model[k] for k in chain]), point, rays, 1.0, reach * tau)
        out.append(whole / alone)
    return np.array(out)


def topology_of_cauchy(ctx, prims):
    """The wrong model of the topology check: the same skeleton with SCALIS Cauchy 4 (σ = 1), whose
    supports are infinite, meshed coarsely (topology only; every primitive is evaluated everywhere,
    so it costs minutes at the figure's size): None in quick runs."""
    if ctx.quick:
        return None
    cauchy = [dict(p, kernel={"family": "cauchy", "degree": 4, "sigma": 1.0}) for p in prims]
    return surface3d.mesh(ctx, {"primitives": cauchy}, 1.0, 0.5, "ant_cauchy4", distance=0.02)


def describe(errors):
    if np.isnan(errors).any():
        return "no surface crossing on some rays"
    spread = np.max(np.abs(errors))
    if spread <= RELATIVE_TOLERANCE:
        return f"max |r/τ − 1| = {fmt(spread)}"
    return f"r/τ from {fmt(1 + np.min(errors))} to {fmt(1 + np.max(errors))}, max |r/τ − 1| = {fmt(spread)}"


def draw(ctx):
    prims = ant.primitives()
    classical = ant.classical_ant(prims)
    s_err = thickness_errors(ctx.field_of(prims), prims, 1.1, THICKNESS_PROBES)
    # the antennae, rays to 10 τ: the classical antenna is that much wider (it ends before the head)
    c_err = thickness_errors(ctx.field_of(classical), prims, 10.0, THICKNESS_PROBES[:2])
    s_leg, c_leg = leg_ratios(ctx, prims, prims, 1.5), leg_ratios(ctx, classical, prims, 6.0)
    m = surface3d.mesh(ctx, {"primitives": prims}, 1.0, ctx.res(0.25, 0.5), "ant", distance=ctx.res(0.004, 0.02))
    if ctx.image_path is not None:
        c = surface3d.mesh(ctx, {"primitives": classical}, 1.0, 0.25, "ant_classical", distance=0.004)
        surface3d.panels(ctx, [(m, f"(a) SCALIS compact 6: {m.stats['triangles']} triangles"),
                               (m, "(b) its skeleton: 34 segments, 4 triangles"),
                               (c, "(c) wrong model: classical, same skeleton")], FIGURE.size,
                         frame=FRAME, view=VIEW, overlays=[None, surface3d.overlay(prims, 0.02), None])
    wrong = topology_of_cauchy(ctx, prims)
    taus = ", ".join(f"{ant.segment_probe(prims, i, t)[1]:g}" for i, t in THICKNESS_PROBES)
    euler = int(m.stats.get("euler_characteristic", 0))
    return [
        Claim("(scale invariance) the thickness is the requested τ at every scale: a thin antenna and the thick "
              "branch alike",
              f"radius on {ant.RAYS} rays at each of 3 probes (τ = {taus}; where the compact guarantee applies): "
              f"{describe(s_err)} (tolerance {RELATIVE_TOLERANCE:g})",
              bool(np.all(np.abs(s_err) <= RELATIVE_TOLERANCE))),
        Claim("(wrong model) a classical convolution of the same skeleton (one kernel k_R^6, R = 1.2, each part "
              "weighted to have its τ alone; no branch: R < 2.2) fails the same check on the antennae",
              f"antennae: {describe(c_err)}; f on the antenna's axis {fmt(ctx.field_of(classical).f([ant.segment_probe(prims, 14, 0.5)[0]])[0])} "
              f"(level 1): the head and the antenna's own neighbours swell it",
              bool(np.isnan(c_err).any() or np.max(np.abs(c_err)) > 1e3 * RELATIVE_TOLERANCE)),
        Claim("(no blending bulge; compact support: 'localised influences, limiting blends at a distance', §4.3) "
              "where a leg leaves the body's support it is the leg alone",
              f"middle femurs at t = {LEG_T}: radius in the ant ÷ radius of the leg alone, {ant.RAYS} rays each: "
              f"SCALIS max |ratio − 1| = {fmt(np.nanmax(np.abs(s_leg - 1)))}; classical (the wrong model) "
              f"{fmt(np.nanmin(c_leg))}–{fmt(np.nanmax(c_leg))}"
              f"{' and rays without a crossing' if np.isnan(c_leg).any() else ''}",
              bool(np.all(np.abs(s_leg - 1) <= RELATIVE_TOLERANCE)
                   and (np.isnan(c_leg).any() or np.nanmax(np.abs(c_leg - 1)) > BULGE))),
        Claim("(ours) the ant and its branch are one smooth closed surface: one component, genus 5 (six legs joining "
              "body and branch)",
              f"{m.stats['triangles']} triangles, components {m.stats.get('components')}, closed {m.stats['closed']}, "
              f"manifold {m.stats['manifold']}, Euler characteristic {euler} (genus {(2 - euler) / 2:g}); wrong model "
              f"(the same skeleton with the Cauchy 4 kernel of the Table 1 ant: infinite supports): " +
              ("meshed in full runs only" if wrong is None else
               f"components {wrong.stats.get('components')}, Euler characteristic {wrong.stats.get('euler_characteristic')}"),
              m.closed and m.stats.get("components") == "1" and euler == EULER
              and (wrong is None or not (wrong.stats.get("components") == "1"
                                         and int(wrong.stats.get("euler_characteristic", 0)) == EULER))),
    ]
