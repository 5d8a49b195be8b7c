"""Zanni et al. 2013, Figure 6, shaded: three thin primitives blended by sum
with a thick one, (a) classical convolution, (b) SCALIS (the section
figure's skeleton and levels). Measured on the meshes: the radius of each
thin primitive at the height PROBE_Y of the section figure, as the section figure measures it
(from the axis along +x to the surface, in the plane z = 0), read off the mesh's section: none
when no surface is within MERGED of the axis (merged into the thick one's lump). Drawn
front-on (looking down on the skeleton's plane), so that the thin primitives show."""
import numpy as np

from figlib import surface3d
from figlib.claims import Claim, fmt
from figlib.figure import Figure, load_skeleton
from figures.zanni2013_fig06 import classical_weight, smoothing_claim, DEGREE, PROBE_Y, ISO_CLASSICAL, SIGMA, SKELETON, THICK
from figlib.zanni import classical_segment


FIGURE = Figure(
    paper="Zanni et al. 2013", kind="Figure", number="6 (3-D)",
    caption="Blend of 3 primitives of small thickness (same thickness, varying length) with a thick linear primitive "
            "(horizontal segment). Details are smoothed when convolution surfaces are used (a), but not with "
            "homothetic surfaces (b).",
    original_caption="Mélange de 3 primitives à faible épaisseur (même épaisseur, longueur variable) avec une primitive "
                     "linéique épaisse (segment horizontal). Les détails sont lissés lorsque les surfaces de convolution "
                     "sont utilisées (a), mais pas avec les surfaces homothétiques (b).",
    section="shaded surfaces of the section figure's skeleton (thin radius 0.25, thick radius 1)",
    skeletons=[SKELETON], kernel="Cauchy 4, σ = 1 (classical: c_s⁴ with s = 1; the thick one weight 1, each thin one the weight that gives it radius 0.25 alone, 0.387, above τ_min = 0.354)",
    iso=f"SCALIS 1; classical {ISO_CLASSICAL:.5g} (radius 1 around the thick segment alone)",
    view="front-on (from above the skeleton's plane), one scale for both panels", size=(1600, 620))


# The section figure's rays stop at 0.99 from the thin axis: a surface reaching that far is not
# the thin primitive's own (the thin ones are 2 apart; a radius of 0.99 is ~4 τ).
MERGED = 0.99
VIEW = [0.0, -0.35, 1.0]          # front-on, from above the skeleton's plane z = 0, tilted a little


def thin_radii(m, thin, facet):
    """Per thin primitive, what the section figure's ray measures, on the mesh: the distance from its
    axis at y = PROBE_Y along +x to the nearest mesh point of the section near the plane z = 0
    (within a facet); NaN when there is none within MERGED (merged into the thick one's lump)."""
    section = surface3d.section(m, 1, PROBE_Y)
    near_plane = section[np.abs(section[:, 2]) < facet]
    out = []
    for p in thin:
        ahead = near_plane[:, 0] - p["a"][0]
        ahead = ahead[(ahead > 0) & (ahead < MERGED)]
        out.append(float(ahead.min()) if len(ahead) else np.nan)
    return np.array(out)


def draw(ctx):
    scalis = load_skeleton(SKELETON)["primitives"]
    classical = [classical_segment(p["a"], p["b"], classical_weight(p), classical_weight(p), "cauchy", DEGREE, SIGMA)
                 for p in scalis]
    thin = [p for p in scalis if p["radius"][0] < THICK]
    size = ctx.res(0.06, 0.1)
    a = surface3d.mesh(ctx, {"primitives": classical}, ISO_CLASSICAL, size, "fig6a_classical")
    b = surface3d.mesh(ctx, {"primitives": scalis}, 1.0, size, "fig6b_scalis")
    surface3d.panels(ctx, [(a, f"(a) classical, iso {ISO_CLASSICAL:.4g}"), (b, "(b) SCALIS, iso 1")], FIGURE.size,
                     view=VIEW)
    tau = thin[0]["radius"][0]
    c, s = thin_radii(a, thin, size), thin_radii(b, thin, size)
    if not (a.closed and b.closed):
        raise surface3d.MeshError(f"fig. 6 meshes not closed: {a.stats['closed']}, {b.stats['closed']}")
    return [smoothing_claim(tau, c, s, "on the meshes ")]
