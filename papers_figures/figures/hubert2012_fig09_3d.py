"""Hubert 2012, Figure 9, shaded: the two parallel squares of the section
figure (z = ±1, R = 1) meshed with `skelconv mesh` for p³ and k_R⁴, each at
the level of one square alone at height τ = 0.3 above its centre. Measured
on the meshes: the surface's offsets from the upper square near its centre,
outward (z > 1) and inward (z < 1): an inward bulge makes the inner offset
larger; flat (compact) makes both τ."""
import numpy as np

from figlib import surface3d
from figlib.claims import Claim, fmt
from figlib.figure import Figure
from figures.hubert2012_fig09 import KERNELS, R, SKELETON, TAU, primitives

CENTRE_HALF_WIDTH = 0.5     # vertices with |x|, |y| < 0.5: the middle of the faces
FLAT = 0.01                 # |offset/τ − 1| below this: flat. Mesh offsets are exact to ~1e-4 here
                            # (the compact surface reads 0.3000 on both sides), so 1 % is well resolved
BULGE = 0.01                # inward / outward − 1 above this: an inward bulge

FIGURE = Figure(
    paper="Hubert 2012", kind="Figure", number="9 (3-D)",
    caption="Convolution surfaces based on parallel polygons (left) with a cubic inverse kernel (middle) "
            "and compact support kernel (right) where R is chosen to be less than the distance between "
            "the two polygons. An inward bulge appears in between the polygons for the cubic inverse "
            "kernel, while the convolution surface is flat towards the center of the polygons on both "
            "sides for the compact support kernel.",
    section="shaded surfaces (the skeleton panel is the section figure's); k_R⁴ stands for the paper's compact kernel",
    skeletons=[SKELETON], kernel=f"p³; k_R⁴ with R = {R:g}",
    iso=f"the level of one square alone at height τ = {TAU} above its centre",
    view="the fixed camera of render3d, one scale for both panels", size=(640, 300))


def offsets(m):
    """(outward, inward) offsets of the surface from the square z = 1 near its centre."""
    v = m.vertices[(np.abs(m.vertices[:, 0]) < CENTRE_HALF_WIDTH) & (np.abs(m.vertices[:, 1]) < CENTRE_HALF_WIDTH)]
    upper = v[v[:, 2] > 0]
    outer, inner = upper[upper[:, 2] > 1], upper[upper[:, 2] < 1]
    return float(np.mean(outer[:, 2]) - 1), float(1 - np.mean(inner[:, 2])) if len(inner) else float("nan")


def draw(ctx):
    items, measured = [], {}
    for family in KERNELS:
        prims = primitives(family)
        level = ctx.field_of(prims[:1]).f([[0, 0, 1 + TAU]])[0]
        m = surface3d.mesh(ctx, {"primitives": prims}, level, ctx.res(0.08, 0.2), f"fig9_{family}")
        measured[family] = offsets(m) + (m,)
        name = "cubic inverse p³" if family == "inverse" else f"compact k_R⁴, R = {R:g}"
        items.append((m, f"{name}, κ = {level:.4g}"))
    surface3d.panels(ctx, items, FIGURE.size)
    (i_out, i_in, i_m), (c_out, c_in, c_m) = measured["inverse"], measured["compact"]
    return [
        Claim("p³: an inward bulge between the polygons (the inner offset exceeds the outer)",
              f"mean offsets from the upper square over |x|, |y| < {CENTRE_HALF_WIDTH:g}: outward {fmt(i_out, 4)}, "
              f"inward {fmt(i_in, 4)} (+{fmt(100 * (i_in / i_out - 1), 2)} %) "
              f"({i_m.stats['triangles']} triangles, closed {i_m.stats['closed']})",
              i_in > (1 + BULGE) * i_out and i_m.closed),
        Claim("compact kernel: flat towards the centres, on both sides (both offsets τ)",
              f"outward {fmt(c_out, 5)}, inward {fmt(c_in, 5)}, τ = {TAU} ({c_m.stats['triangles']} triangles, "
              f"closed {c_m.stats['closed']})",
              abs(c_out / TAU - 1) < FLAT and abs(c_in / TAU - 1) < FLAT and c_m.closed),
    ]
