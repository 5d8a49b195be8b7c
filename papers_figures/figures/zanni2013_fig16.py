"""Zanni et al. 2013, Figure 16: SCALIS surfaces of triangle skeletons (eq. 15),
(a) constant radius (closed form), (b) radius varying linearly over the
triangle (numerical integration in skelconv too, so (b) is meshed with
`--method grid`, and is one triangle).

The kernel is the compact one of Zanni §4.3 (degree 6, support σ τ), so that
"constant thickness" is a statement with an exact answer: above an interior
point of a triangle whose support disc stays inside that triangle and away
from every other primitive, f = 1 exactly at distance τ (the compact guarantee
of Figure 11, figlib.ant). (a) is measured on BOTH triangles of the folded
pair, at points where the guarantee applies (figlib.ant.triangle_probe
confirms each); the same check on a wrong model, the same pair with the
infinite Cauchy 4 kernel (every edge and the other triangle reach every
point), must fail.

(b) has no exact answer: with τ varying, a surface point sees a range of
radii. The property checked is the mean-value bound: the thickness above a
point lies between the smallest and largest τ of the skeleton within the
support (radius σ τ_max) of the surface point, and it grows where τ grows."""
import numpy as np

from figlib import ant, surface3d
from figlib.claims import Claim, fmt
from figlib.figure import Figure
from figlib.levelset import crossing

DEGREE, SIGMA = 6, 1.5
KERNEL = {"family": "compact", "degree": DEGREE, "sigma": SIGMA}
WRONG_KERNEL = {"family": "cauchy", "degree": 4, "sigma": 1.0}
BASE = [[0, 0, 0], [3, 0, 0], [1.5, 2.6, 0]]          # in the plane z = 0
FOLDED = [[0, 0, 0], [3, 0, 0], [1.5, -1.3, 2.25]]    # shares the edge [0, 3] × {0}, folded 120° from BASE
TAU_A = 0.15
TAU_B = [0.08, 0.25, 0.15]
# The guarantee is exact: rounding and the root finder only (as in zanni2013_fig01).
RELATIVE_TOLERANCE = 1e-9
# (a): per triangle, barycentric probes away from the shared edge (its support would see the other triangle).
PROBES_A = [[0.25, 0.25, 0.5], [0.35, 0.2, 0.45], [0.2, 0.35, 0.45]]
# (b): probes near each vertex.
PROBES_B = np.array([[0.5, 0.25, 0.25], [0.25, 0.5, 0.25], [0.25, 0.25, 0.5]])
# Camera: from inside the fold's opening (between the two triangles' outer... inner faces), above.
VIEW = [0.35, 0.25, 1.0]

FIGURE = Figure(
    paper="Zanni et al. 2013", kind="Figure", number="16",
    caption="Homothetic implicit surfaces created from triangle skeletons: (a) triangles of constant thickness "
            "using analytic formulas, (b) triangles with tri-linear variation of thickness using numerical "
            "integration.",
    original_caption="Surfaces implicites homothétiques créées à partir de squelettes triangles : (a) triangles à "
                     "épaisseur constante utilisant des formules analytiques, (b) triangles à variation d'épaisseur "
                     "tri-linéaire utilisant une intégration numérique.",
    section="our skeletons (the paper's are not given): (a) two triangles folded 120° along a shared edge, τ = 0.15; "
            "(b) one triangle, τ = 0.08, 0.25, 0.15 at its vertices, coloured by the height of the surface above "
            "its plane",
    kernel=f"SCALIS compact, degree {DEGREE}, σ = {SIGMA:g} (wrong model for (a): SCALIS Cauchy 4, σ = 1)", iso="1",
    view="one camera above the fold's opening, one scale for both panels", size=(1600, 760))


def triangle(vertices, radius, kernel=KERNEL):
    return {"type": "scalis_triangle", "vertices": vertices, "radius": radius, "kernel": kernel, "iso": 1.0}


def thickness_a(ctx, kernel):
    """Per probe of each triangle of the pair: (distance to f = 1 along +n and −n) / τ − 1."""
    prims = [triangle(BASE, [TAU_A] * 3), triangle(FOLDED, [TAU_A] * 3)]
    field = ctx.field_of([triangle(p["vertices"], p["radius"], kernel) for p in prims])
    out = []
    for index in range(2):
        for bary in PROBES_A:
            point, tau, normal, clear = ant.triangle_probe(prims, index, bary)
            if not clear:
                raise ValueError(f"triangle {index} probe {bary}: the compact guarantee does not apply there")
            out.append(ant.radii(field, point, np.array([normal, -normal]), 1.0, 3 * tau) / tau - 1)
    return np.array(out)


def tau_b(points):
    """τ at points of the plane z = 0, by the barycentric coordinates in BASE."""
    v = np.asarray(BASE, float)[:, :2]
    m = np.column_stack([v[1] - v[0], v[2] - v[0]])
    uv = np.linalg.solve(m, (np.atleast_2d(points)[:, :2] - v[0]).T).T
    bary = np.column_stack([1 - uv.sum(axis=1), uv])
    return bary @ np.asarray(TAU_B)


def tau_range_within(point, reach, samples=60):
    """(min, max) of τ over the triangle within `reach` of `point` (a fine barycentric sample)."""
    k = np.arange(samples + 1)
    u, v = np.meshgrid(k, k)
    keep = u + v <= samples
    bary = np.column_stack([u[keep], v[keep]]) / samples
    q = np.asarray(BASE, float)[0] + bary @ (np.asarray(BASE, float)[1:] - np.asarray(BASE, float)[0])
    near = np.linalg.norm(q - point, axis=1) <= reach
    t = tau_b(q[near])
    return float(t.min()), float(t.max())


def draw(ctx):
    right, wrong = thickness_a(ctx, KERNEL), thickness_a(ctx, WRONG_KERNEL)
    skeleton_b = {"primitives": [triangle(BASE, TAU_B)]}
    origins = PROBES_B @ np.asarray(BASE, float)
    t_b = crossing(ctx.field_of(skeleton_b["primitives"]), origins, [0, 0, 1.0], 1.0, 1e-9, 3.0)
    tau_here = tau_b(origins)
    ranges = [tau_range_within(o + [0, 0, t], SIGMA * max(TAU_B)) for o, t in zip(origins, t_b)]
    within = all(lo <= t <= hi for t, (lo, hi) in zip(t_b, ranges))
    ordered = list(np.argsort(t_b)) == list(np.argsort(tau_here))
    a_text = ", ".join(fmt(e) for e in right.ravel())
    claims = [
        Claim("(a) constant radius: the thickness is τ over each triangle of the folded pair, where no edge and "
              "no other triangle is within the support",
              f"r/τ − 1 on both sides above {len(PROBES_A)} points of each triangle (τ = {TAU_A:g}): max "
              f"|r/τ − 1| = {fmt(np.max(np.abs(right)))} (tolerance {RELATIVE_TOLERANCE:g}; all: {a_text})",
              bool(np.all(np.abs(right) <= RELATIVE_TOLERANCE))),
        Claim("(wrong model) the same pair with the infinite Cauchy 4 kernel fails the same check",
              "max |r/τ − 1| = " + ("no crossing on some rays" if np.isnan(wrong).any()
                                    else fmt(np.max(np.abs(wrong)))),
              bool(np.isnan(wrong).any() or np.max(np.abs(wrong)) > RELATIVE_TOLERANCE)),
        Claim("(b) tri-linear radius: the thickness follows τ(u, v): it grows where τ grows, and lies between the "
              "smallest and largest τ the surface point's support (σ τ_max) reaches",
              "thickness " + ", ".join(f"{fmt(t)} (τ here {fmt(th)}, reachable [{fmt(lo)}, {fmt(hi)}])"
                                       for t, th, (lo, hi) in zip(t_b, tau_here, ranges)),
              within and ordered),
    ]
    # (a) is meshed in ctest too (coarser); (b), numerically integrated, needs facets finer than its
    # thinnest radius 0.08 for the grid mesher (several seconds even coarse): full runs only
    a = surface3d.mesh(ctx, {"primitives": [triangle(BASE, [TAU_A] * 3), triangle(FOLDED, [TAU_A] * 3)]}, 1.0,
                       ctx.res(0.04, 0.25), "fig16a")
    if ctx.quick:
        claims.append(Claim("(ours) the surface of (a) is a closed manifold ((b) is meshed in full runs only)",
                            f"(a) {a.stats['closed']}", a.closed))
        return claims
    b = surface3d.mesh(ctx, skeleton_b, 1.0, 0.04, "fig16b", method="grid")
    height = np.abs(b.vertices[:, 2])
    colours = surface3d.plot.plt.get_cmap("viridis")((height - min(TAU_B)) / (max(TAU_B) - min(TAU_B)))[:, :3]
    surface3d.panels(ctx, [(a, f"(a) constant τ = {TAU_A:g}, folded pair, {a.stats['triangles']} triangles"),
                           (b, f"(b) τ = {', '.join(f'{t:g}' for t in TAU_B)} at the vertices; colour: height "
                               f"{min(TAU_B):g} (violet) to {max(TAU_B):g} (yellow)", colours)],
                     FIGURE.size, view=VIEW)
    claims.append(Claim("(ours) both surfaces are closed manifolds", f"(a) {a.stats['closed']}, (b) {b.stats['closed']}",
                        a.closed and b.closed))
    return claims
