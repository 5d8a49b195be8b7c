"""The ant of Zanni et al. 2013, Figures 1 and 17 and Table 1: our hand-built
skeleton of the paper's class (SCALIS segments and SCALIS triangles, the
compact kernel of degree 6 the paper uses "in practice", §4.3), on a branch.
The paper prints no skeleton for its ant; ours (skeletons/zanni_fig01_ant.json)
has a gaster, a petiole with its node, a thorax, a head of two triangles of
one radius, two triangle mandibles, elbowed antennae, six three-segment legs
whose tarsi rest on the branch, and the branch (one segment of radius 3).

What the figures measure, and the wrong model they compare with:
- the thickness where the compact guarantee applies (probe_is_clear): f = iso
  exactly at distance τ from a long-enough constant-radius primitive that no
  other primitive's support reaches (Zanni §4.3, fig. 11; docs/cli_skeleton.md
  for triangles), measured by ray casting with skelconv eval;
- the same skeleton as a classical convolution (Zanni eq. 10) with one
  compact kernel k_R^6 for every primitive and the weight that gives each
  primitive, alone and infinite, its radius τ (the most favourable classical
  set-up: classical_ant)."""
import numpy as np

from .figure import load_skeleton
from .levelset import crossing

ANT = "zanni_fig01_ant.json"
SIGMA = 1.5                 # the skeleton file's σ (every primitive): supports of radius 1.5 τ
DEGREE = 6
# The classical kernel's support: σ times the ant's thickest radius (the gaster, 0.8), so that every
# part of the ant can have its radius with it (a classical primitive of radius τ needs R > τ). The
# branch (radius 3) cannot, and is left out of the classical model.
CLASSICAL_R = SIGMA * 0.8
RAYS = 8                    # rays per probe, evenly around the segment (or both sides of a triangle)


def primitives():
    return load_skeleton(ANT)["primitives"]


def point_segment_distance(p, a, b):
    a, b, p = (np.asarray(v, float) for v in (a, b, p))
    ab = b - a
    t = np.clip(np.dot(p - a, ab) / np.dot(ab, ab), 0.0, 1.0)
    return float(np.linalg.norm(p - (a + t * ab)))


def point_triangle_distance(p, vertices):
    """Distance from p to a filled triangle: to its plane when the foot is inside, else to the nearest edge."""
    v = np.asarray(vertices, float)
    p = np.asarray(p, float)
    n = np.cross(v[1] - v[0], v[2] - v[0])
    n /= np.linalg.norm(n)
    foot = p - np.dot(p - v[0], n) * n
    inside = all(np.dot(np.cross(v[(k + 1) % 3] - v[k], foot - v[k]), n) >= 0 for k in range(3)) or \
        all(np.dot(np.cross(v[(k + 1) % 3] - v[k], foot - v[k]), n) <= 0 for k in range(3))
    if inside:
        return float(abs(np.dot(p - v[0], n)))
    return min(point_segment_distance(p, v[k], v[(k + 1) % 3]) for k in range(3))


def distance(p, primitive):
    if "vertices" in primitive:
        return point_triangle_distance(p, primitive["vertices"])
    return point_segment_distance(p, primitive["a"], primitive["b"])


def support(primitive):
    """The radius of its support around its skeleton: σ times its largest radius."""
    return primitive["kernel"]["sigma"] * max(primitive["radius"])


def probe_is_clear(prims, index, point, tau, own_room):
    """True when the compact guarantee gives f = iso exactly at distance τ from `point` on
    primitive `index`: no other primitive's support comes within 1.1 τ of the point (the rays
    stop at 1.1 τ), and the primitive's own support around the point, own_room, is inside it."""
    others = all(distance(point, q) >= support(q) + 1.1 * tau for k, q in enumerate(prims) if k != index)
    return others and own_room


def segment_probe(prims, index, t):
    """(point, τ, unit axis, clear) at parameter t of a constant-radius segment."""
    p = prims[index]
    a, b = np.asarray(p["a"], float), np.asarray(p["b"], float)
    tau = p["radius"][0] + t * (p["radius"][1] - p["radius"][0])
    point = a + t * (b - a)
    length = np.linalg.norm(b - a)
    half_support = tau * np.sqrt(p["kernel"]["sigma"] ** 2 - 1)   # the support's half-length along the segment
    own = p["radius"][0] == p["radius"][1] and min(t, 1 - t) * length >= half_support
    return point, tau, (b - a) / length, probe_is_clear(prims, index, point, tau, own)


def triangle_probe(prims, index, bary):
    """(point, τ, unit normal, clear) at barycentric coordinates `bary` of a constant-radius triangle."""
    p = prims[index]
    v = np.asarray(p["vertices"], float)
    tau = p["radius"][0]
    point = np.asarray(bary, float) @ v
    n = np.cross(v[1] - v[0], v[2] - v[0])
    n /= np.linalg.norm(n)
    room = tau * np.sqrt(p["kernel"]["sigma"] ** 2 - 1)        # the support disc's radius in the plane
    edges = [np.linalg.norm(np.cross(v[(k + 1) % 3] - v[k], point - v[k])) / np.linalg.norm(v[(k + 1) % 3] - v[k])
             for k in range(3)]
    own = len(set(p["radius"])) == 1 and min(edges) >= room
    return point, tau, n, probe_is_clear(prims, index, point, tau, own)


def perpendicular_rays(axis, count):
    """`count` unit directions perpendicular to `axis`, evenly spaced."""
    axis = np.asarray(axis, float)
    helper = np.array([0.0, 0.0, 1.0]) if abs(axis[2]) < 0.9 else np.array([1.0, 0.0, 0.0])
    u = np.cross(axis, helper)
    u /= np.linalg.norm(u)
    w = np.cross(axis, u)
    angles = 2 * np.pi * np.arange(count) / count
    return np.cos(angles)[:, None] * u + np.sin(angles)[:, None] * w


def radii(field, point, directions, level, reach):
    """Distance from `point` to the surface f = level along each direction (rays to `reach`;
    NaN where a ray does not cross: no surface there, or the point is outside)."""
    return crossing(field, point, directions, level, 0.0, reach)


def classical_weight_line(tau, radius):
    """The weight whose infinite line alone, with k_R^6 (R = radius), has f = 1 at distance τ:
    ∫ (1 − (τ² + s²)/R²)³ ds = R a⁷ · 32/35 with a² = 1 − τ²/R²."""
    a = np.sqrt(1 - (tau / radius) ** 2)
    return 1.0 / (radius * a ** 7 * 32 / 35)


def classical_weight_plane(tau, radius):
    """The same for an infinite plane: ∬ (1 − (τ² + r²)/R²)³ dA = π R² a⁸ / 4."""
    a = np.sqrt(1 - (tau / radius) ** 2)
    return 4.0 / (np.pi * radius ** 2 * a ** 8)


def scalis_compact_triangle_h(sigma, degree):
    """h of a compact SCALIS triangle (docs/cli_skeleton.md): 2π σ² (1 − 1/σ²)^((i+2)/2) / (i + 2)."""
    return 2 * np.pi * sigma ** 2 * (1 - 1 / sigma ** 2) ** ((degree + 2) / 2) / (degree + 2)


def classical_ant(prims, radius=CLASSICAL_R):
    """The ant as a classical convolution (eq. 10) with one kernel k_R^6 for all, at level 1:
    a segment gets the linear weight that is calibrated (classical_weight_line) at both ends;
    a triangle of radius τ gets the plane's calibrated weight w. skelconv's polygon has
    density 1, so the triangle is written as the constant-radius SCALIS triangle that equals
    it: radius R/σ (its kernel is then k_R^6) and iso = w h (R/σ)² (its f is iso F / (h τ²)).
    Primitives of radius ≥ R (the branch) have no classical counterpart and are left out."""
    out = []
    for p in prims:
        if max(p["radius"]) >= radius:
            continue
        if "vertices" in p:
            tau_eff = radius / SIGMA
            w = classical_weight_plane(p["radius"][0], radius)
            out.append({"type": "scalis_triangle", "vertices": p["vertices"], "radius": [tau_eff] * 3,
                        "kernel": {"family": "compact", "degree": DEGREE, "sigma": SIGMA},
                        "iso": w * scalis_compact_triangle_h(SIGMA, DEGREE) * tau_eff ** 2})
        else:
            w0, w1 = (classical_weight_line(t, radius) for t in p["radius"])
            out.append({"type": "segment", "a": p["a"], "b": p["b"], "weight": [w0, w1 - w0] if w1 != w0 else [w0],
                        "kernel": {"family": "compact", "degree": DEGREE, "R": radius}})
    return out
