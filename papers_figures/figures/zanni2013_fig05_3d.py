"""Zanni et al. 2013, Figure 5, shaded: the radius decreases linearly to 0 at
the end of the skeleton; classical convolution (a) rounds the end off before
the skeleton's end, SCALIS (b) ends in a cone whose tip is the skeleton's end.
Measured on the meshes (vertices on the surface): the tip (largest x), and
the radius along the middle against τ. Cross-check: POV-Ray's own
isosurface{} of the classical field (a single primitive) by 24-point
Gauss–Legendre quadrature of eq. 10, rendered with the same camera: the
silhouettes must agree."""
import os
import tempfile

import numpy as np

from figlib import plot, surface3d
from figlib.claims import Claim, fmt
from figlib.figure import Figure
from figlib.zanni import classical_cauchy_line, classical_segment, scalis_segment

DEGREE = 4
SIGMA = 1.0
LENGTH = 4.0
TAU0 = 1.0
ISO_CLASSICAL = classical_cauchy_line(TAU0, TAU0, DEGREE, SIGMA)   # radius τ0 on a line of weight τ0
A, B = (0.0, 0.0, 0.0), (LENGTH, 0.0, 0.0)
QUADRATURE_NODES = 24       # Gauss–Legendre nodes of the POV-Ray function: the kernel is smooth on a scale σ = 1
SILHOUETTE_AGREEMENT = 0.98  # fraction of pixels where mesh and isosurface must agree (the rest: facets, edges)

FIGURE = Figure(
    paper="Zanni et al. 2013", kind="Figure", number="5 (3-D)",
    caption="Different shapes generated when the weight decreases linearly to 0 at the end of the skeleton: "
            "classical formulation (a), homothetic (b). Note the unwanted rounded ends in (a).",
    original_caption="Différentes formes générées lorsque le poids décroît linéairement jusqu'à 0 au bout du "
                     "squelette : formulation classique (a), homothétique (b). Remarquez les extrémités arrondies "
                     "non voulues en (a).",
    section="shaded surfaces (`skelconv mesh`, POV-Ray); bottom row: POV-Ray's own isosurface{} of (a) "
            "as the cross-check of the mesh",
    kernel="Cauchy 4, σ = 1; classical: weight τ(t) = 1 − t; SCALIS: radius [1, 0]",
    iso=f"classical {ISO_CLASSICAL:.6g} (radius 1 on a line of weight 1); SCALIS 1",
    view="segment from (0,0,0) to (4,0,0), the fixed camera of render3d", size=(640, 500))


def classical_pov_function():
    """Eq. 10 for this segment in POV-Ray function syntax, iso subtracted (inside < 0):
    iso − Σ_k w_k (1 − t_k) L (1 + |P − Γ(t_k)|²/σ²)^(−i/2), Gauss–Legendre on [0, 1]."""
    nodes, weights = np.polynomial.legendre.leggauss(QUADRATURE_NODES)
    terms = []
    for x, w in zip(nodes, weights):
        t = 0.5 * (x + 1)
        coeff = 0.5 * w * (TAU0 * (1 - t)) * LENGTH
        terms.append(f"{coeff:.17g}*pow(1 + (pow(x - {t * LENGTH:.17g}, 2) + y*y + z*z)/{SIGMA ** 2:.17g}, "
                     f"{-DEGREE / 2:g})")
    return f"{ISO_CLASSICAL:.17g} - (" + " + ".join(terms) + ")"


def cross_check(m, frame, width, height):
    """(agreement, pixels of the mesh, pixels of the isosurface): both rendered in the same frame."""
    from figlib.surface3d import povray
    with tempfile.TemporaryDirectory() as tmp:
        mesh_png, iso_png = os.path.join(tmp, "mesh.png"), os.path.join(tmp, "iso.png")
        surface3d.render_one(m, mesh_png, width, height, frame)
        body = povray.isosurface(classical_pov_function(), [-1.5, -1.5, -1.5], [LENGTH + 1, 1.5, 1.5],
                                 max_gradient=4.0)
        povray.render_scene(povray.scene(body, *frame, width, height), iso_png, width, height)
        a, b = plot.plt.imread(mesh_png)[..., :3], plot.plt.imread(iso_png)[..., :3]
    agree = float(np.mean((a.min(axis=2) < 0.99) == (b.min(axis=2) < 0.99)))
    return agree, a, b


def draw(ctx):
    size = ctx.res(0.08, 0.25)
    classical = surface3d.mesh(ctx, {"primitives": [classical_segment(A, B, TAU0, 0.0, "cauchy", DEGREE, SIGMA)]},
                               ISO_CLASSICAL, size, "fig5a_classical")
    scalis = surface3d.mesh(ctx, {"primitives": [scalis_segment(A, B, TAU0, 0.0, "cauchy", DEGREE, SIGMA)]},
                            1.0, size, "fig5b_scalis")
    measured = {}
    for kind, m in (("classical", classical), ("scalis", scalis)):
        middle = m.vertices[(m.vertices[:, 0] > 0.2 * LENGTH) & (m.vertices[:, 0] < 0.8 * LENGTH)]
        r = np.hypot(middle[:, 1], middle[:, 2])
        tau = TAU0 * (1 - middle[:, 0] / LENGTH)
        measured[kind] = dict(tip=float(m.vertices[:, 0].max()), dev=float(np.max(np.abs(r - tau))))
    # the cross-check runs in ctest too, at a smaller picture (the claim needs no image file)
    # each panel's pixels at the saved image's size (the layout's 320 × 228 enlarged to print size)
    scale = plot.print_scale(FIGURE.size)
    w, h = ctx.res((round(320 * scale), round(228 * scale)), (120, 86))
    frame = surface3d.common_frame([classical, scalis])     # both panels at one scale and place
    agree, mesh_pixels, iso_pixels = cross_check(classical, frame, w, h)
    claims = [Claim("(ours) cross-check: the mesh of (a) and POV-Ray's isosurface{} of the same field "
                    f"({QUADRATURE_NODES}-point Gauss–Legendre quadrature of eq. 10) have the same silhouette",
                    f"{agree:.2%} of the {w}×{h} pixels agree (threshold {SILHOUETTE_AGREEMENT:.0%})",
                    agree >= SILHOUETTE_AGREEMENT)]
    if ctx.image_path is not None:
        fig, axes = plot.new_figure(FIGURE.size, 2, 2, squeeze=False)
        fig.subplots_adjust(left=0, right=1, bottom=0, top=0.95, wspace=0, hspace=0.09)
        with tempfile.TemporaryDirectory() as tmp:
            png = os.path.join(tmp, "b.png")
            surface3d.render_one(scalis, png, w, h, frame)
            pictures = [(mesh_pixels, f"(a) classical, mesh, iso {ISO_CLASSICAL:.4g}"),
                        (plot.plt.imread(png)[..., :3], "(b) SCALIS, mesh, iso 1"),
                        (iso_pixels, "(a) POV-Ray isosurface{} of the same field"),
                        (np.where(((mesh_pixels.min(axis=2) < 0.99) != (iso_pixels.min(axis=2) < 0.99))[..., None],
                                  np.array([0.8, 0.0, 0.0]), 1.0),
                         f"pixels where the silhouettes differ: {1 - agree:.2%}")]
        for ax, (pixels, title) in zip(axes.flat, pictures):
            ax.imshow(pixels, interpolation="nearest")
            ax.set_title(title)
            ax.set_axis_off()
        plot.save(fig, ctx.image_path, FIGURE.size)
    c, s = measured["classical"], measured["scalis"]
    return claims + [
        Claim("classical: the end is rounded off before the end of the skeleton",
              f"the mesh ends at x = {fmt(c['tip'], 4)} (skeleton end {LENGTH:g}); max |r − τ| on the middle 60 % "
              f"{fmt(c['dev'])}; {classical.stats['triangles']} triangles, closed {classical.stats['closed']}",
              c["tip"] < LENGTH - 0.1 and classical.closed),
        Claim("SCALIS: a cone whose tip is the end of the skeleton",
              f"the mesh ends at x = {fmt(s['tip'], 5)} (facet size {size:g}); max |r − τ| on the middle 60 % "
              f"{fmt(s['dev'])}; {scalis.stats['triangles']} triangles, closed {scalis.stats['closed']}",
              abs(s["tip"] - LENGTH) < size and s["dev"] < 0.5 * c["dev"] and scalis.closed),
    ]
