"""The shaded drawing shared by Hubert 2012 Figures 6 and 7 (3-D): a planar
polygon (left) and its p⁴ convolution surface (right), meshed by
`skelconv mesh` at the level of the section figures (thickness τ above the
centroid, figlib/polygon_figure.py) and rendered with one framing.

The claims are measured on the mesh: it is one closed sphere-like surface
(Euler characteristic 2), its vertices lie on the level set of the paper's own
p⁴ formula (§6.4, evaluated in Python, independent of skelconv), and its
outline in the polygon's plane is as convex as the polygon: the depth of
the outline's deepest point inside its own convex hull is 0 (to the mesh's
accuracy) for a convex polygon, a notch for a non-convex one."""
import numpy as np

from . import surface3d
from .claims import Claim, fmt
from .figure import load_skeleton
from .polygon_figure import TAU
from .reference import polygon_edge_terms

# Vertices closer than this to the polygon's plane are left out of the check
# against the paper's formula: its edge terms carry 1/(2z²) and cancel each
# other as z → 0 (the sum is finite, each term is not), so rounding grows like 1/z².
FORMULA_MIN_Z = 0.02
# |f_paper(v) − κ| / κ at the mesh's vertices: skelconv mesh projects each vertex to
# |f − κ| / |∇f| ≤ 1e-9 × the box diagonal (~6 here), and |∇f| / f ≲ 4/τ = 16 on this
# surface (f ~ z^-2 near a face), so ≤ 1e-7; the formula itself agrees with skelconv to 1e-11.
ON_LEVEL = 1e-6
# The outline's points are where the mesh's edges cross z = 0: on chords of the
# surface, and the mesh of a convex surface need not be convex. A chord of length h
# sags h²/(8ρ) below a curve of curvature radius ρ; the rim around the polygon
# has ρ ≳ 0.1, so facets of size h leave dents up to ~h/6 deep. A convex outline
# then has depth ≤ h/5; a notch counts when it is at least half the polygon's own.
MESH_DISTANCE_PER_SIZE = 0.2
NOTCH_FRACTION = 0.5
CONVEX = 1e-12            # a polygon's own depth below this: convex (its vertices are its hull's)
POLYGON_GREY = (0.55, 0.55, 0.6)


def ear_clipping(polygon):
    """Triangles (index triples) of a simple counter-clockwise polygon (N×2)."""
    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    left, triangles = list(range(len(polygon))), []
    while len(left) > 3:
        for k in range(len(left)):
            i, j, m = left[k - 1], left[k], left[(k + 1) % len(left)]
            a, b, c = polygon[i], polygon[j], polygon[m]
            convex = cross(a, b, c) > 0
            others = (polygon[q] for q in left if q not in (i, j, m))
            if convex and not any(cross(a, b, p) >= 0 and cross(b, c, p) >= 0 and cross(c, a, p) >= 0 for p in others):
                triangles.append((i, j, m))
                left.pop(k)
                break
        else:
            raise ValueError("ear_clipping: not a simple counter-clockwise polygon")
    triangles.append(tuple(left))
    return np.array(triangles)


def convex_hull(points):
    """The convex hull of 2-D points, counter-clockwise (Andrew's monotone chain)."""
    pts = sorted(map(tuple, points))

    def half(seq):
        out = []
        for p in seq:
            while len(out) >= 2 and ((out[-1][0] - out[-2][0]) * (p[1] - out[-2][1])
                                     - (out[-1][1] - out[-2][1]) * (p[0] - out[-2][0])) <= 0:
                out.pop()
            out.append(p)
        return out[:-1]
    return np.array(half(pts) + half(pts[::-1]))


def hull_depth(points):
    """The largest distance from one of the 2-D points to the boundary of their convex
    hull: 0 for points in convex position, the depth of the deepest notch otherwise."""
    hull = convex_hull(points)
    edges = np.roll(hull, -1, axis=0) - hull
    normals = np.stack([edges[:, 1], -edges[:, 0]], axis=1) / np.linalg.norm(edges, axis=1)[:, None]   # outward
    inside = -((points[:, None, :] - hull[None, :, :]) * normals[None, :, :]).sum(axis=2)   # ≥ 0 inside
    return float(np.max(np.min(inside, axis=1)))


def polygon_mesh(vertices):
    """The polygon itself as a flat Mesh (normals +z) for its panel."""
    faces = ear_clipping(vertices[:, :2])
    normals = np.tile([0.0, 0.0, 1.0], (len(vertices), 1))
    return surface3d.Mesh(vertices, normals, faces, {"triangles": str(len(faces))}, 0.0, "")


def draw_polygon_p4_3d(ctx, figure, skeleton_name):
    vertices = np.array(load_skeleton(skeleton_name)["primitives"][0]["vertices"], float)
    field = ctx.field(skeleton_name)
    centroid = vertices.mean(axis=0)
    level = field.f([centroid + [0, 0, TAU]])[0]
    size = ctx.res(0.06, 0.2)
    m = surface3d.mesh(ctx, field.skeleton, level, size, skeleton_name.replace(".json", ""))
    flat = polygon_mesh(vertices)
    frame = surface3d.common_frame([m])
    grey = np.tile(POLYGON_GREY, (len(vertices), 1))
    surface3d.panels(ctx, [(flat, "the polygon", grey), (m, f"p⁴ surface, iso κ = {level:.4g} (τ = {TAU})")],
                     figure.size, frame=frame)

    off_plane = m.vertices[np.abs(m.vertices[:, 2]) >= FORMULA_MIN_Z]
    paper = sum(polygon_edge_terms(vertices, off_plane, "inverse"))
    on_level = float(np.max(np.abs(paper - level)) / level)
    outline = surface3d.section(m, 2, 0.0)[:, :2]
    depth, polygon_depth = hull_depth(outline), hull_depth(vertices[:, :2])
    mesh_distance = MESH_DISTANCE_PER_SIZE * size
    follows = depth <= mesh_distance if polygon_depth < CONVEX else depth >= NOTCH_FRACTION * polygon_depth
    return [
        Claim("(ours) the p⁴ convolution surface of the polygon is one closed surface around it",
              f"{m.stats['triangles']} triangles, components {m.stats['components']}, Euler characteristic "
              f"{m.stats['euler_characteristic']}, closed {m.stats['closed']}, manifold {m.stats['manifold']}",
              m.closed and m.stats["components"] == "1" and m.stats["euler_characteristic"] == "2"),
        Claim("(ours) the surface is the level set of the paper's p⁴ formula (§6.4: 1/(2|PP̄|²) Σ edge terms of D^{p²})",
              f"the formula (Python) at the {len(off_plane)} mesh vertices with |z| ≥ {FORMULA_MIN_Z:g}: "
              f"max |f − κ|/κ = {fmt(on_level)} (threshold {ON_LEVEL:g})", on_level < ON_LEVEL),
        Claim("(ours) the surface follows the polygon's shape: its outline in the polygon's plane is convex for a convex "
              "polygon and has the notch of a non-convex one",
              f"depth of the outline's deepest point inside its convex hull: {fmt(depth)} (the polygon's own: "
              f"{fmt(polygon_depth)}; " + (f"convex up to the mesh's chords, size/5 = {fmt(mesh_distance)})" if polygon_depth < CONVEX
                                           else f"a notch: at least {NOTCH_FRACTION:g} of the polygon's)"),
              follows),
    ]
