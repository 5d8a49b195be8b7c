"""Zanni et al. 2013, Figure 7, shaded: the section figure's T skeleton and its
homothetic copies (scales 1, 1/3, 1/6), each meshed by `skelconv mesh` (facet
size in proportion) and drawn scaled back to size 1, classical (top row)
against SCALIS (bottom row). Measured: how far each scaled-back mesh is from
the unscaled surface, by the first-order distance |f − c| / |∇f| of its
vertices to the level set of the unscaled field (exact to second order for
points near the surface, and an estimate only when the shapes differ)."""
from dataclasses import replace

import numpy as np

from figlib import surface3d
from figlib.claims import Claim, fmt
from figlib.figure import load_skeleton, scaled_primitives
from figures.zanni2013_fig07 import FIGURE as SECTIONS, ISO_CLASSICAL, SCALES, SIZE, SKELETON, classical_from

# The vertices of a mesh are on its surface to 1e-9 × the box diagonal (~10 × scale):
# scaled back, on the unscaled surface to ~1e-8 / SIZE if the shapes are similar.
SIMILAR = 1e-6
DIFFERENT = 0.02            # the section figure's threshold for "not similar"

FIGURE = replace(
    SECTIONS, number="7 (3-D)",
    section="shaded surfaces of the section figure's T skeleton (our own) at scales 1, 1/3, 1/6, each drawn "
            "scaled back to size 1",
    view="the fixed camera of render3d, one framing for all six panels", size=(1600, 820))


def scaled_back(m, alpha):
    return surface3d.Mesh(m.vertices / alpha, m.normals, m.faces, m.stats, m.seconds, m.command)


def distance_to(field, level, points):
    """|f − level| / |∇f| at the points: their distance to the level set, to first order."""
    f, grad = field.eval(points)
    return np.abs(f - level) / np.linalg.norm(grad, axis=1)


def draw(ctx):
    base = load_skeleton(SKELETON)["primitives"]
    size = ctx.res(0.06, 0.2)
    items, measured = [], {}
    for kind in ("classical", "scalis"):
        level = ISO_CLASSICAL if kind == "classical" else 1.0
        unscaled = ctx.field_of(classical_from(base) if kind == "classical" else base)
        measured[kind] = []
        for alpha in SCALES:
            prims = scaled_primitives(base, alpha)
            prims = classical_from(prims) if kind == "classical" else prims
            m = scaled_back(surface3d.mesh(ctx, {"primitives": prims}, level, size * alpha,
                                           f"fig7_{kind}_{alpha:.3g}"), alpha)
            if alpha != 1.0:
                measured[kind].append((float(np.max(distance_to(unscaled, level, m.vertices))) / SIZE, m.closed))
            label = "(a) classical" if kind == "classical" else "(b) SCALIS"
            items.append((m, f"{label}, scale " + ("1" if alpha == 1 else f"1/{round(1 / alpha)} (drawn ×{round(1 / alpha)})")))
    frame = surface3d.common_frame([m for m, _ in items[:1]])
    surface3d.panels(ctx, items, FIGURE.size, rows=2, frame=frame)
    c, s = measured["classical"], measured["scalis"]
    return [
        Claim("(b) SCALIS: the homothetic shapes are similar",
              f"max distance of the scaled-back meshes (scales 1/3, 1/6) to the unscaled surface ÷ size: "
              f"{fmt(s[0][0])}, {fmt(s[1][0])}", max(d for d, _ in s) < SIMILAR and all(ok for _, ok in s)),
        Claim("(a) classical: the shapes are not similar",
              f"same distance (first-order estimate), scales 1/3, 1/6: {fmt(c[0][0])}, {fmt(c[1][0])}",
              min(d for d, _ in c) > DIFFERENT and all(ok for _, ok in c)),
    ]
