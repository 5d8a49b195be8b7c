"""Zanni et al. 2013, Figure 4 (a, b), shaded: segments of length 4 with
constant τ = 1, 0.7, 0.5, 0.4, 0.3 (the section figure's), meshed by
`skelconv mesh` and stacked from top (τ = 1) to bottom, classical (a) and
SCALIS (b). Measured on the meshes: the half-length (largest |x|) and the
radius at the middle (half the width of the section x = 0); the field is
then evaluated just inside and just outside those extents on the axes (one
`skelconv eval` per shape), so the shaded shapes are those of the section
figure to the mesher's accuracy."""
from dataclasses import replace

import numpy as np

from figlib import surface3d
from figlib.claims import Claim, fmt
from figures.zanni2013_fig04 import DEGREE, ISO_CLASSICAL, LENGTH, SIGMA, TAUS_AB, FIGURE as SECTIONS
from figlib.zanni import classical_segment, scalis_segment

STACK = 2.6                 # vertical distance between the stacked shapes (radius ≤ 1.1: no overlap)
# A mesh vertex lies on the surface (to 1e-9 × the box); the largest |x| of the vertices
# and a section's width are then within the mesher's facet distance, size/10, of the
# surface's: f must be above the level that far inside them on the axes and below it
# that far outside (f decreases along both axes from the centre, so the crossing is there).
MESH_DISTANCE_PER_SIZE = 0.1

FIGURE = replace(
    SECTIONS, number="4 (3-D)",
    section="(a), (b) shaded: the section figure's segments (length 4, constant τ), stacked from τ = 1 (top) "
            "to τ = 0.3 (bottom); an empty row is a surface that has disappeared; (c) is the section figure's",
    view="the fixed camera of render3d, one framing for both panels", size=(640, 400))


def primitive(kind, tau):
    a, b = (-LENGTH / 2, 0, 0), (LENGTH / 2, 0, 0)
    if kind == "classical":
        return classical_segment(a, b, tau, tau, "cauchy", DEGREE, SIGMA), ISO_CLASSICAL
    return scalis_segment(a, b, tau, tau, "cauchy", DEGREE, SIGMA), 1.0


def measure(ctx, kind, tau, size):
    """(mesh or None when the field stays below the level, {half-length, middle radius, and
    whether f brackets the level within ±tolerance of both on the axes})."""
    prim, level = primitive(kind, tau)
    field = ctx.field_of([prim])
    if not field.f([[0, 0, 0]])[0] >= level:         # the field's maximum is at the centre: no surface
        return None, dict(half=np.nan, radius=np.nan, bracketed=True)
    m = surface3d.mesh(ctx, {"primitives": [prim]}, level, size, f"fig4_{kind}_{tau:g}")
    half = float(np.max(np.abs(m.vertices[:, 0])))
    radius = 0.5 * surface3d.widths(m, 0, 1, [0.0])[0]
    d = MESH_DISTANCE_PER_SIZE * size
    f = field.f([[half - d, 0, 0], [half + d, 0, 0], [0, radius - d, 0], [0, radius + d, 0]])
    return m, dict(half=half, radius=radius, bracketed=bool(f[0] >= level > f[1] and f[2] >= level > f[3]))


def stacked(meshes):
    """One Mesh of the shapes moved down by STACK per row (empty rows keep their place)."""
    vertices, normals, faces, count = [], [], [], 0
    for row, m in enumerate(meshes):
        if m is None:
            continue
        vertices.append(m.vertices - [0, 0, STACK * row])
        normals.append(m.normals)
        faces.append(m.faces + count)
        count += len(m.vertices)
    return surface3d.Mesh(np.concatenate(vertices), np.concatenate(normals), np.concatenate(faces), {}, 0.0, "")


def draw(ctx):
    size = ctx.res(0.06, 0.2)
    tolerance = MESH_DISTANCE_PER_SIZE * size
    results = {kind: [measure(ctx, kind, tau, size) for tau in TAUS_AB] for kind in ("classical", "scalis")}
    panels = {kind: stacked([m for m, _ in rows]) for kind, rows in results.items()}
    # a frame holding the tallest stack (τ = 1 on top, 5 rows), shared by both panels
    centre, radius = surface3d.common_frame([panels["scalis"]])
    surface3d.panels(ctx, [(panels["classical"], f"(a) classical, iso {ISO_CLASSICAL:.4g}: τ = 1 … 0.3 ↓"),
                           (panels["scalis"], "(b) SCALIS, iso 1: τ = 1 … 0.3 ↓")],
                     FIGURE.size, frame=(centre, radius))
    c = [r for _, r in results["classical"]]
    s = [r for _, r in results["scalis"]]
    meshes = [m for rows in results.values() for m, _ in rows if m is not None]
    agree = all(r["bracketed"] for r in c + s)
    gone = [np.isnan(r["half"]) for r in c]
    taus = ", ".join(map(str, TAUS_AB))
    return [
        Claim("(a) classical: as τ decreases the surface contracts towards the centre, then disappears",
              f"mesh half-length (segment half-length {LENGTH / 2:g}) for τ = {taus}: " +
              ", ".join("gone" if np.isnan(r["half"]) else fmt(r["half"]) for r in c),
              bool(gone[-1] and all(a > b for a, b in zip([r["half"] for r in c[:3]], [r["half"] for r in c[1:3]]))
                   and all(g or r["half"] < LENGTH / 2 for g, r in zip(gone[2:], c[2:])))),
        Claim("(b) SCALIS: the surface only gets thinner (longer than the segment, radius ≈ τ)",
              "mesh half-length: " + ", ".join(fmt(r["half"]) for r in s) + "; radius at the middle: " +
              ", ".join(fmt(r["radius"]) for r in s),
              all(r["half"] > LENGTH / 2 and abs(r["radius"] - t) < 0.1 * t for r, t in zip(s, TAUS_AB))),
        Claim("(ours) the shaded shapes are the section figure's (the meshes' extents against the field)",
              f"{len(meshes)} meshes, all closed: {all(m.closed for m in meshes)}; f ≥ iso at {fmt(tolerance)} "
              f"(the facet distance) inside each half-length and middle radius on the axes, f < iso that far "
              f"outside: {agree}",
              agree and all(m.closed for m in meshes)),
    ]
