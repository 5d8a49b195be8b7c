#!/usr/bin/env python3
"""Writes disc_ears.off into the current directory: a toy with thin disc-shaped ears
(an ellipsoid body, a ball of a head and two flat discs 0.03 thick, 1.5% of the
bounding-box diagonal, 0.4 across), one closed triangle mesh of genus 0.

The surface is the zero set of a signed distance (the body and head joined by a
smooth minimum, the discs by a plain one), polygonised by marching tetrahedra
(six per cell, the same diagonal in every cell, so that neighbouring cells agree
and the mesh is closed) on a rectilinear grid 0.04 apart (2% of the diagonal),
0.006 apart across the discs' thickness: 14,614 vertices, 29,224 triangles. A
shape to measure `skelconv skeletonize` on (docs/reconstruction_medial.md, "Thin
walls"), not a test input: the mesh (1.1 MB) is not kept in the repository.
numpy and the standard library only; same bytes each run.
  python3 make_disc_ears.py [output.off]
"""
import sys

import numpy as np

EAR_THICKNESS = 0.03
EAR_RADIUS = 0.2
STEP = 0.04  # the grid, but across the discs
EARS = [(-0.32, 0.95), (0.32, 0.95)]  # (x, z) centres, in the plane y = 0


def ellipsoid(p, c, r):
    q = (p - np.asarray(c)) / np.asarray(r)
    return (np.linalg.norm(q, axis=-1) - 1.0) * min(r)


def disc(p, cx, cz):
    radial = np.hypot(p[..., 0] - cx, p[..., 2] - cz) - EAR_RADIUS
    across = np.abs(p[..., 1]) - EAR_THICKNESS / 2
    outside = np.hypot(np.maximum(radial, 0.0), np.maximum(across, 0.0))
    return outside + np.minimum(np.maximum(radial, across), 0.0)


def smooth_min(a, b, k):
    h = np.clip(0.5 + 0.5 * (b - a) / k, 0.0, 1.0)
    return b * (1 - h) + a * h - k * h * (1 - h)


def field(p):
    body = ellipsoid(p, (0, 0, 0), (0.45, 0.35, 0.4))
    head = ellipsoid(p, (0, 0, 0.62), (0.3, 0.3, 0.3))
    d = smooth_min(body, head, 0.08)
    for cx, cz in EARS:
        d = np.minimum(d, disc(p, cx, cz))
    return d


def axis(lo, hi, step):
    n = int(round((hi - lo) / step))
    return lo + (hi - lo) * np.arange(n + 1) / n


def main(path):
    xs = axis(-0.56, 0.56, STEP)
    zs = axis(-0.46, 1.22, STEP)
    fine = axis(-0.03, 0.03, 0.006)
    ys = np.concatenate([axis(-0.39, -0.05, STEP), axis(-0.05, -0.03, 0.01)[1:-1], fine,
                         axis(0.03, 0.05, 0.01)[1:-1], axis(0.05, 0.39, STEP)])
    polygonise(field, xs, ys, zs, path)


def polygonise(field, xs, ys, zs, path):
    """Writes the closed surface field = 0 on the rectilinear grid xs × ys × zs
    (the field negative inside, positive on the grid's boundary) to `path` as OFF."""
    X, Y, Z = np.meshgrid(xs, ys, zs, indexing="ij")
    P = np.stack([X, Y, Z], axis=-1)
    F = field(P)
    F[F == 0.0] = 1e-12  # no grid point on the surface: every crossing is inside an edge
    shape = F.shape
    # The six tetrahedra of a cell around its diagonal (0,0,0)-(1,1,1).
    corners = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0), (0, 0, 1), (1, 0, 1), (0, 1, 1), (1, 1, 1)]
    tets = [(0, 1, 3, 7), (0, 3, 2, 7), (0, 2, 6, 7), (0, 6, 4, 7), (0, 4, 5, 7), (0, 5, 1, 7)]
    inside = F < 0
    mixed = np.zeros(tuple(s - 1 for s in shape), dtype=bool)
    any_in = np.zeros_like(mixed)
    all_in = np.ones_like(mixed)
    for c in corners:
        sl = inside[c[0]:shape[0] - 1 + c[0], c[1]:shape[1] - 1 + c[1], c[2]:shape[2] - 1 + c[2]]
        any_in |= sl
        all_in &= sl
    mixed = any_in & ~all_in
    vertices, index, triangles = [], {}, []

    def flat(ijk):
        return (ijk[0] * shape[1] + ijk[1]) * shape[2] + ijk[2]

    def crossing(a, b):
        key = (min(a[0], b[0]), max(a[0], b[0]))
        if key not in index:
            fa, fb = F[a[1]], F[b[1]]
            # Not at a grid point: crossings of the edges round it stay apart.
            t = min(max(fa / (fa - fb), 0.01), 0.99)
            index[key] = len(vertices)
            vertices.append(P[a[1]] + t * (P[b[1]] - P[a[1]]))
        return index[key]

    def emit(cycle, corners4):
        # Oriented from the grid's corners, never from the crossings (a
        # triangle of them may have no area): with corners (a, b, c, d) of
        # positive volume, the crossings from a to b, c, d in that order
        # turn anticlockwise seen from outside a, and so do those of a, b to
        # c, d in the order ac, ad, bd, bc.
        a, b, c, d = (P[v[1]] for v in corners4)
        if np.linalg.det(np.array([b - a, c - a, d - a])) < 0:
            cycle = cycle[::-1]
        for m in range(1, len(cycle) - 1):
            triangles.append((cycle[0], cycle[m], cycle[m + 1]))

    for i, j, k in zip(*np.nonzero(mixed)):
        cell = [(i + c[0], j + c[1], k + c[2]) for c in corners]
        for tet in tets:
            ids = [(flat(cell[t]), cell[t]) for t in tet]
            ins = [v for v in ids if F[v[1]] < 0]
            outs = [v for v in ids if F[v[1]] >= 0]
            if len(ins) == 1:
                emit([crossing(ins[0], o) for o in outs], [ins[0]] + outs)
            elif len(ins) == 3:
                # The lone outside corner's triangle, turned to face it.
                emit([crossing(outs[0], v) for v in ins][::-1], [outs[0]] + ins)
            elif len(ins) == 2:
                a, b = ins
                c, d = outs
                emit([crossing(a, c), crossing(a, d), crossing(b, d), crossing(b, c)], [a, b, c, d])
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(vertices), len(triangles)))
        for v in vertices:
            f.write("%.9f %.9f %.9f\n" % tuple(v))
        for t in triangles:
            f.write("3 %d %d %d\n" % t)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "disc_ears.off")
