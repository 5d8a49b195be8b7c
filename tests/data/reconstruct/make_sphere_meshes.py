#!/usr/bin/env python3
"""Writes small test meshes of `skelconv skeletonize` (ASCII
PLY) into the current directory; standard library only, same bytes each run:
  sphere.ply               icosphere (3 subdivisions), radius 1: a ball, no curve skeleton
  cube.ply                 unit cube, 8 vertices, 12 triangles: a low-poly mesh
  spheres_overlapping.ply  two icospheres (2 subdivisions) overlapping, one mesh: self-intersecting
  spheres_close.ply        two icospheres (2 subdivisions), radius 1, 0.02 apart, one mesh: two separate
                           parts that a sum of fields would fuse
  parts_close.ply          a flat ellipsoid (semi-axes 1, 0.6, 0.12; icosphere of 3 subdivisions) and four small
                           ones (0.25, 0.08, 0.08; 2 subdivisions) side by side beyond its x end, 0.04 from it
                           and from each other: one large part and four small ones close together
  sphere_open.ply          sphere.ply without the triangles whose centroid is within 25 degrees of the
                           pole (0, 0, 1): an open mesh of one hole, for `skeletonize --repair`
  sphere_and_shell.ply     sphere.ply and, beside it, a small thin curved shell: a square 0.6 across and 0.01
                           thick, bent to a sphere of radius 50 (4 x 4 vertices a side), centred at (2, 0, 0):
                           a flat part whose least-squares sphere is far wider than the whole input
"""
import math


def icosphere(level, r=1.0, c=(0, 0, 0)):
    t = (1 + 5**0.5) / 2
    V = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
         (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    V = [tuple(x / math.sqrt(sum(y * y for y in v)) for x in v) for v in V]
    F = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6),
         (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10),
         (8, 6, 7), (9, 8, 1)]
    for _ in range(level):
        cache, NF = {}, []

        def mid(a, b):
            k = (min(a, b), max(a, b))
            if k not in cache:
                m = [(V[a][i] + V[b][i]) / 2 for i in range(3)]
                n = math.sqrt(sum(x * x for x in m))
                V.append(tuple(x / n for x in m))
                cache[k] = len(V) - 1
            return cache[k]

        for a, b, cc in F:
            ab, bc, ca = mid(a, b), mid(b, cc), mid(cc, a)
            NF += [(a, ab, ca), (b, bc, ab), (cc, ca, bc), (ab, bc, ca)]
        F = NF
    return [tuple(c[i] + r * v[i] for i in range(3)) for v in V], F


def write(path, V, F, comment):
    with open(path, 'w') as f:
        f.write(f"ply\nformat ascii 1.0\ncomment {comment}\nelement vertex {len(V)}\nproperty float x\n"
                f"property float y\nproperty float z\nelement face {len(F)}\n"
                "property list uchar int vertex_indices\nend_header\n")
        for v in V:
            f.write(" ".join(f"{x:.6g}" for x in v) + "\n")
        for t in F:
            f.write("3 " + " ".join(map(str, t)) + "\n")


def main():
    """Writes the meshes of the module docstring into the current directory (importing writes nothing)."""
    V, F = icosphere(3)
    write("sphere.ply", V, F, "icosphere (3 subdivisions of an icosahedron), radius 1: skeletonize's ball case")
    cube = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    CF = [(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4), (1, 2, 6), (1, 6, 5), (2, 3, 7), (2, 7, 6),
          (3, 0, 4), (3, 4, 7)]
    write("cube.ply", cube, CF, "unit cube, 8 vertices, 12 triangles, outward: skeletonize's low-poly case")
    V1, F1 = icosphere(2, 1.0, (0, 0, 0))
    V2, F2 = icosphere(2, 1.0, (1.2, 0, 0))
    write("spheres_overlapping.ply", V1 + V2, F1 + [tuple(i + len(V1) for i in t) for t in F2],
          "two overlapping icospheres (radius 1, centres 1.2 apart) in one mesh, no boolean: self-intersecting")
    V3, F3 = icosphere(2, 1.0, (2.02, 0, 0))
    write("spheres_close.ply", V1 + V3, F1 + [tuple(i + len(V1) for i in t) for t in F3],
          "two icospheres (radius 1, centres 2.02 apart: 0.02 between them) in one mesh: two separate parts")
    PV, PF = [], []
    for level, centre, axes in [(3, (0, 0, 0), (1.0, 0.6, 0.12))] + [(2, (1.29, -0.3 + 0.2 * k, 0), (0.25, 0.08, 0.08))
                                                                      for k in range(4)]:
        EV, EF = icosphere(level)
        PF += [tuple(i + len(PV) for i in t) for t in EF]
        PV += [tuple(centre[i] + axes[i] * v[i] for i in range(3)) for v in EV]
    write("parts_close.ply", PV, PF, "a flat ellipsoid and four small ones beside it, 0.04 apart: five separate parts")
    cap = math.cos(math.radians(25))
    kept = [t for t in F if sum(V[i][2] for i in t) / 3 / math.sqrt(sum((sum(V[i][k] for i in t) / 3) ** 2
                                                                       for k in range(3))) < cap]
    used = sorted({i for t in kept for i in t})
    renumber = {v: k for k, v in enumerate(used)}
    write("sphere_open.ply", [V[i] for i in used], [tuple(renumber[i] for i in t) for t in kept],
          "sphere.ply without a polar cap of 25 degrees (the vertices of no triangle left out): one hole")

    shell, SF = thin_shell(50.0, 0.6, 0.01, 4, (2.0, 0.0, 0.0))
    write("sphere_and_shell.ply", V + shell, F + [tuple(i + len(V) for i in t) for t in SF],
          "sphere.ply and a thin shell 0.6 across, 0.01 thick, bent to radius 50, at (2, 0, 0): a flat part")


def thin_shell(R, width, thickness, n, c):
    """A closed shell: two n x n grids over a square `width` across, on the spheres of radius R -/+ thickness/2
    about c - (0, 0, R) (the upper facing up, the lower down), joined at their rims; outward."""
    g = [-width / 2 + width * k / (n - 1) for k in range(n)]
    V, F = [], []
    for offset in (thickness / 2, -thickness / 2):
        for x in g:
            for y in g:
                V.append((c[0] + x, c[1] + y, c[2] + math.sqrt(R * R - x * x - y * y) - R + offset))

    def vid(layer, i, j):
        return layer * n * n + i * n + j

    for i in range(n - 1):
        for j in range(n - 1):
            a, b, cc, d = vid(0, i, j), vid(0, i + 1, j), vid(0, i + 1, j + 1), vid(0, i, j + 1)
            F += [(a, b, cc), (a, cc, d)]
            a, b, cc, d = vid(1, i, j), vid(1, i + 1, j), vid(1, i + 1, j + 1), vid(1, i, j + 1)
            F += [(a, cc, b), (a, d, cc)]
    rim = ([(i, 0) for i in range(n - 1)] + [(n - 1, j) for j in range(n - 1)] +
           [(i, n - 1) for i in range(n - 1, 0, -1)] + [(0, j) for j in range(n - 1, 0, -1)])
    for k in range(len(rim)):
        (i0, j0), (i1, j1) = rim[k], rim[(k + 1) % len(rim)]
        a, b, cc, d = vid(0, i0, j0), vid(0, i1, j1), vid(1, i1, j1), vid(1, i0, j0)
        F += [(a, d, cc), (a, cc, b)]
    return V, F


if __name__ == "__main__":
    main()
