"""Zanni et al. 2013, Figure 6, shaded: three thin primitives blended by sum
with a thick one, (a) classical convolution, (b) SCALIS (the section
figure's skeleton and levels). Measured on the meshes: the radius of each
thin primitive at 3/4 of its length, half the extent across it of the
mesh's section there (0 where the surface does not reach)."""
import numpy as np

from figlib import surface3d
from figlib.claims import Claim, fmt
from figlib.figure import Figure, load_skeleton
from figures.zanni2013_fig06 import DEGREE, ISO_CLASSICAL, SIGMA, SKELETON, THICK
from figlib.zanni import classical_segment

KEPT = 0.4                  # |r − τ| < 0.4 τ: the detail is kept (the section figure's threshold)

FIGURE = Figure(
    paper="Zanni et al. 2013", kind="Figure", number="6 (3-D)",
    caption="Blend of 3 primitives of small thickness (same thickness, varying length) with a thick linear primitive "
            "(horizontal segment). Details are smoothed when convolution surfaces are used (a), but not with "
            "homothetic surfaces (b).",
    original_caption="Mélange de 3 primitives à faible épaisseur (même épaisseur, longueur variable) avec une primitive "
                     "linéique épaisse (segment horizontal). Les détails sont lissés lorsque les surfaces de convolution "
                     "sont utilisées (a), mais pas avec les surfaces homothétiques (b).",
    section="shaded surfaces of the section figure's skeleton (thin radius 0.25, thick radius 1)",
    skeletons=[SKELETON], kernel="Cauchy 4, σ = 1 (classical: c_s⁴ with s = 1, weight τ)",
    iso=f"SCALIS 1; classical {ISO_CLASSICAL:.5g} (radius 1 around the thick segment alone)",
    view="the fixed camera of render3d, one scale for both panels", size=(640, 300))


def thin_radii(m, thin):
    """Half the width of the mesh's section y = const at 3/4 of each thin primitive, near it."""
    out = []
    for p in thin:
        a, b = np.asarray(p["a"], float), np.asarray(p["b"], float)
        probe = a + 0.75 * (b - a)
        out.append(0.5 * surface3d.widths(m, 1, 0, [probe[1]], near=probe[0], half_range=0.9)[0])
    return np.array(out)


def draw(ctx):
    scalis = load_skeleton(SKELETON)["primitives"]
    classical = [classical_segment(p["a"], p["b"], p["radius"][0], p["radius"][1], "cauchy", DEGREE, SIGMA)
                 for p in scalis]
    thin = [p for p in scalis if p["radius"][0] < THICK]
    size = ctx.res(0.06, 0.1)
    a = surface3d.mesh(ctx, {"primitives": classical}, ISO_CLASSICAL, size, "fig6a_classical")
    b = surface3d.mesh(ctx, {"primitives": scalis}, 1.0, size, "fig6b_scalis")
    surface3d.panels(ctx, [(a, f"(a) classical, iso {ISO_CLASSICAL:.4g}"), (b, "(b) SCALIS, iso 1")], FIGURE.size)
    tau = thin[0]["radius"][0]
    c, s = thin_radii(a, thin), thin_radii(b, thin)
    return [Claim(
        "details (thin primitives blended with a thick one) are smoothed by classical convolution, kept by SCALIS",
        f"radius of the 3 thin primitives at 3/4 of their length on the meshes (their own radius {tau:g}): SCALIS "
        f"{', '.join(fmt(r) for r in s)}; classical {', '.join(fmt(r) for r in c)} (0: the surface does not reach); "
        f"closed {a.stats['closed']}, {b.stats['closed']}",
        bool(np.all(np.abs(s - tau) < KEPT * tau) and np.all(np.abs(c - tau) > KEPT * tau) and a.closed and b.closed))]
