#!/usr/bin/env python3
"""Writes test meshes of `skelconv skeletonize --repair` (its boolean union of crossing parts) into the current
directory; standard library only, same bytes each run. Each is closed and consistently oriented, and crosses
itself somewhere, or nests:
  cubes_vertex_crossing.ply   cube [0,1]^3 and cube [1,2]^3 touching at the corner (1,1,1) (stored twice: two
                              vertex indices at one position), and a box crossing the first cube elsewhere
  cubes_edge_crossing.ply     cube [0,1]^3 and cube [1,2]x[1,2]x[0,1] sharing the edge x = y = 1, and a box
                              crossing the first cube elsewhere
  spheres_touching.ply        spheres_overlapping.ply and a third sphere, its mirror image through one of the
                              first sphere's vertices, touching it at that vertex only (one vertex index)
  spheres_duplicate_vertex.ply  spheres_overlapping.ply with one vertex stored twice (the triangles around it
                              split between the copies)
  spheres_nested.ply          a sphere of radius 1 and one of radius 0.5 inside it, both facing outwards:
                              nothing crosses, the inner one's inside is enclosed twice
  cubes_degenerate.ply        cubes [0,2]^3 and [1,3]^3 crossing, the first with a zero-area triangle: its edge
                              from (2,2,0) to (2,2,2) split at (2,2,1), on the second cube's face z = 1
  cubes_vertex_box.ply        cubes_vertex_crossing.ply's two cubes and the box [1,1.8]x[0.5,1]x[0.5,1.5], which
                              touches the first cube's face x = 1 and the second's y = 1, its edge through the
                              corner (1,1,1) where the cubes touch
  cubes_vertex_tetrahedron.ply  the two cubes and a tetrahedron crossing both, its edge from (0.5,0.5,0.5) to
                              (1.5,1.5,1.5) through the corner where they touch
  sphere_pleat.ply            an icosphere (level 2, radius 1) whose vertex 0 is dragged past its neighbour q (to
                              q + 0.6 (q - v0), back on the sphere): its star folds over q, a pleat whose crossing
                              curves end at q (one connected surface crossing itself, as CGAL's elk and cow)
"""
import math
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0] if "/" in __file__ else ".")
from make_sphere_meshes import icosphere, write  # noqa: E402

CUBE_FACES = [(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4), (1, 2, 6), (1, 6, 5), (2, 3, 7),
              (2, 7, 6), (3, 0, 4), (3, 4, 7)]


def box(lo, hi):
    (a, b, c), (d, e, f) = lo, hi
    return [(a, b, c), (d, b, c), (d, e, c), (a, e, c), (a, b, f), (d, b, f), (d, e, f), (a, e, f)], list(CUBE_FACES)


def join(*parts):
    V, F = [], []
    for pv, pf in parts:
        F += [tuple(i + len(V) for i in t) for t in pf]
        V += pv
    return V, F


def main():
    """Writes the meshes of the module docstring into the current directory (importing writes nothing)."""
    crossing = box((0.25, 0.25, -0.5), (0.75, 0.75, 0.5))  # crosses the bottom face z = 0 of [0,1]^3
    V, F = join(box((0, 0, 0), (1, 1, 1)), box((1, 1, 1), (2, 2, 2)), crossing)
    write("cubes_vertex_crossing.ply", V, F, "cubes touching at one corner (two vertex indices there), a box crossing one")
    V, F = join(box((0, 0, 0), (1, 1, 1)), box((1, 1, 0), (2, 2, 1)), crossing)
    write("cubes_edge_crossing.ply", V, F, "cubes sharing one edge, a box crossing one of them")

    V1, F1 = icosphere(2, 1.0, (0, 0, 0))
    V2, F2 = icosphere(2, 1.0, (1.2, 0, 0))
    # The third sphere: the first mirrored through its vertex p (v -> 2p - v, which reverses the orientation, so each
    # triangle is flipped); p itself is shared, so the two touch at p only (the first lies in x.p <= 1).
    p = max(range(len(V1)), key=lambda i: (-V1[i][0], V1[i][1], V1[i][2]))  # a vertex on the side away from sphere 2
    V3 = [tuple(2 * V1[p][k] - v[k] for k in range(3)) for v in V1]
    F3 = [tuple(p if i == p else i + len(V1) + len(V2) for i in (t[0], t[2], t[1])) for t in F1]
    V, F = join((V1, F1), (V2, F2))
    V += V3
    F += F3
    used = sorted({i for t in F for i in t})
    renumber = {v: k for k, v in enumerate(used)}
    write("spheres_touching.ply", [V[i] for i in used], [tuple(renumber[i] for i in t) for t in F],
          "two overlapping icospheres and a third touching the first at one vertex")

    V, F = join((V1, F1), (V2, F2))
    around = [k for k, t in enumerate(F) if 0 in t]
    V = V + [V[0]]
    F = [tuple(len(V) - 1 if (i == 0 and k in around[:2]) else i for i in t) for k, t in enumerate(F)]
    write("spheres_duplicate_vertex.ply", V, F, "spheres_overlapping.ply with vertex 0 stored twice")

    Vi, Fi = icosphere(2, 0.5, (0.1, 0, 0))
    V, F = join((V1, F1), (Vi, Fi))
    write("spheres_nested.ply", V, F, "a sphere inside another, both facing outwards, crossing nothing")

    A, FA = box((0, 0, 0), (2, 2, 2))
    B, FB = box((1, 1, 1), (3, 3, 3))
    # Split the edge 2 -> 6 ((2,2,0) -> (2,2,2)) at m: the triangle (2, 7, 6) that runs 6 -> 2 becomes (2, 7, m) and
    # (m, 7, 6); the triangle (1, 2, 6) that runs 2 -> 6 stays, and the zero-area triangle (2, m, 6) closes it.
    A.append((2, 2, 1))
    m = len(A) - 1
    FA = [t for t in FA if t != (2, 7, 6)] + [(2, 7, m), (m, 7, 6), (2, m, 6)]
    V, F = join((A, FA), (B, FB))
    write("cubes_degenerate.ply", V, F, "two crossing cubes, one with a zero-area triangle on the other's face")

    cubes = join(box((0, 0, 0), (1, 1, 1)), box((1, 1, 1), (2, 2, 2)))
    write("cubes_vertex_box.ply", *join(cubes, box((1, 0.5, 0.5), (1.8, 1, 1.5))),
          "cubes touching at a corner, a box touching both along faces, its edge through the corner")
    # Corners chosen with a positive volume for the faces below (outward).
    T = [(0.5, 0.5, 0.5), (1.5, 1.5, 1.5), (1.5, 0.25, 0.75), (0.25, 1.5, 0.75)]
    write("cubes_vertex_tetrahedron.ply", *join(cubes, (T, [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)])),
          "cubes touching at a corner, a tetrahedron crossing both through the corner")

    V, F = icosphere(2, 1.0, (0, 0, 0))
    q = min(i for t in F if 0 in t for i in t if i != 0)
    m = [V[q][k] + 0.6 * (V[q][k] - V[0][k]) for k in range(3)]
    V[0] = tuple(x / math.sqrt(sum(y * y for y in m)) for x in m)
    write("sphere_pleat.ply", V, F, "an icosphere with a vertex dragged past its neighbour: a pleat")


if __name__ == "__main__":
    main()
