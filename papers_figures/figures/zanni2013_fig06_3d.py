"""Zanni et al. 2013, Figure 6, shaded: three thin primitives blended by sum
with a thick one, (a) classical convolution, (b) SCALIS (the section
figure's skeleton and levels). Measured on the meshes: the radius of each
thin primitive at the height PROBE_Y of the section figure, half the extent across it of the
mesh's section there (0 where the surface does not reach)."""
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
    view="the fixed camera of render3d, one scale for both panels", size=(640, 300))


def thin_radii(m, thin):
    """Half the width of the mesh's section y = PROBE_Y across each thin primitive, near it."""
    out = []
    for p in thin:
        a, b = np.asarray(p["a"], float), np.asarray(p["b"], float)
        probe = np.array([a[0], PROBE_Y, a[2]])
        out.append(0.5 * surface3d.widths(m, 1, 0, [probe[1]], near=probe[0], half_range=0.9)[0])
    return np.array(out)


def draw(ctx):
    scalis = load_skeleton(SKELETON)["primitives"]
    classical = [classical_segment(p["a"], p["b"], classical_weight(p), classical_weight(p), "cauchy", DEGREE, SIGMA)
                 for p in scalis]
    thin = [p for p in scalis if p["radius"][0] < THICK]
    size = ctx.res(0.06, 0.1)
    a = surface3d.mesh(ctx, {"primitives": classical}, ISO_CLASSICAL, size, "fig6a_classical")
    b = surface3d.mesh(ctx, {"primitives": scalis}, 1.0, size, "fig6b_scalis")
    surface3d.panels(ctx, [(a, f"(a) classical, iso {ISO_CLASSICAL:.4g}"), (b, "(b) SCALIS, iso 1")], FIGURE.size)
    tau = thin[0]["radius"][0]
    c, s = thin_radii(a, thin), thin_radii(b, thin)
    if not (a.closed and b.closed):
        raise surface3d.MeshError(f"fig. 6 meshes not closed: {a.stats['closed']}, {b.stats['closed']}")
    return [smoothing_claim(tau, c, s, "on the meshes ")]
