"""Zanni et al. 2013, Figure 16: SCALIS surfaces of triangle skeletons (eq. 15),
(a) constant radius (closed form), (b) radius varying linearly over the
triangle (numerical integration in skelconv too: ~1 ms per evaluation, so
(b) is meshed with `--method grid`, ~13 evaluations per triangle, and is one
triangle). Measured with the field (ray crossings along the triangle's
normal): the thickness above interior points against τ there."""
import numpy as np

from figlib import surface3d
from figlib.claims import Claim, fmt
from figlib.figure import Figure
from figlib.levelset import crossing

KERNEL = {"family": "cauchy", "degree": 4, "sigma": 1.0}
BASE = [[0, 0, 0], [3, 0, 0], [1.5, 2.6, 0]]          # in the plane z = 0
FOLDED = [[0, 0, 0], [3, 0, 0], [1.5, 0.9, 2.4]]      # shares the edge [0, 3] × {0}: a folded pair
TAU_A = 0.15
TAU_B = [0.08, 0.25, 0.15]
# The thickness of a finite triangle is τ up to the edges' influence, which falls
# like (r/τ)^(2−i) (docs/cli_skeleton.md, SCALIS triangles): r/τ ≈ 3 to 8 at our probes.
RELATIVE_TOLERANCE = 0.15
PROBES = np.array([[0.5, 0.25, 0.25], [0.25, 0.5, 0.25], [0.25, 0.25, 0.5]])  # barycentric, near each vertex

FIGURE = Figure(
    paper="Zanni et al. 2013", kind="Figure", number="16",
    caption="Homothetic implicit surfaces created from triangle skeletons: (a) triangles of constant thickness "
            "using analytic formulas, (b) triangles with tri-linear variation of thickness using numerical "
            "integration.",
    original_caption="Surfaces implicites homothétiques créées à partir de squelettes triangles : (a) triangles à "
                     "épaisseur constante utilisant des formules analytiques, (b) triangles à variation d'épaisseur "
                     "tri-linéaire utilisant une intégration numérique.",
    section="our skeletons (the paper's are not given): (a) two triangles folded along a shared edge, τ = 0.15; "
            "(b) one triangle, τ = 0.08, 0.25, 0.15 at its vertices",
    kernel="SCALIS Cauchy 4, σ = 1", iso="1",
    view="the fixed camera of render3d, one scale for both panels", size=(640, 300))


def triangle(vertices, radius):
    return {"type": "scalis_triangle", "vertices": vertices, "radius": radius, "kernel": KERNEL, "iso": 1.0}


def thickness(field, bary):
    """Distance from Σ bary_k v_k of the base triangle to the surface along +z."""
    origins = bary @ np.asarray(BASE, float)
    return crossing(field, origins, [0, 0, 1.0], 1.0, 1e-9, 3.0)


def draw(ctx):
    skeleton_a = {"primitives": [triangle(BASE, [TAU_A] * 3), triangle(FOLDED, [TAU_A] * 3)]}
    skeleton_b = {"primitives": [triangle(BASE, TAU_B)]}
    t_a = thickness(ctx.field_of([triangle(BASE, [TAU_A] * 3)]), PROBES)
    t_b = thickness(ctx.field_of(skeleton_b["primitives"]), PROBES)
    tau_b = PROBES @ np.asarray(TAU_B)
    claims = [
        Claim("(a) constant radius: the thickness is τ over the triangle",
              f"thickness at 3 interior points {', '.join(fmt(t) for t in t_a)} for τ = {TAU_A:g} "
              f"(tolerance {RELATIVE_TOLERANCE:.0%}: the edges' influence)",
              np.all(np.abs(t_a / TAU_A - 1) < RELATIVE_TOLERANCE)),
        Claim("(b) tri-linear radius: the thickness follows τ(u, v)",
              f"thickness {', '.join(fmt(t) for t in t_b)} where τ = {', '.join(fmt(t) for t in tau_b)}",
              np.all(np.abs(t_b / tau_b - 1) < RELATIVE_TOLERANCE)),
    ]
    # meshed in ctest too (coarser): the closedness claim needs no image
    a = surface3d.mesh(ctx, skeleton_a, 1.0, ctx.res(0.06, 0.25), "fig16a")
    b = surface3d.mesh(ctx, skeleton_b, 1.0, ctx.res(0.07, 0.25), "fig16b", method="grid")
    surface3d.panels(ctx, [(a, f"(a) constant τ = {TAU_A:g}, {a.stats['triangles']} triangles"),
                           (b, f"(b) τ = {', '.join(f'{t:g}' for t in TAU_B)}, grid mesher")], FIGURE.size)
    claims.append(Claim("both surfaces are closed manifolds", f"(a) {a.stats['closed']}, (b) {b.stats['closed']}",
                        a.closed and b.closed))
    return claims
