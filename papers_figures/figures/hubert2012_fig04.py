"""Hubert 2012, Figure 4: curves around a polyline of segments for p², p³,
p⁴; sharpness at the angles increases with i. Measured at each angle, with
the level of thickness τ along the middle segment, against the exact offset
curve at distance τ (sharp in the concave side of the angle, a circular arc of
radius τ around the vertex on the convex side):
- concave side: the curvature of the curve on the angle's bisector, × τ
  (the offset curve has a corner there: −∞);
- convex side: the distance from the vertex to the curve on the bisector, ÷ τ
  (1 for the offset curve).
The top row is the paper's figure; the bottom row zooms on the two angles with
the three curves together and the exact offset curve (dashed), where the
sharpening the numbers measure is visible."""
import numpy as np

from figlib import plot
from figlib.claims import Claim, fmt
from figlib.figure import Figure, load_skeleton
from figlib.levelset import crossing, curvature_2d

TAU = 0.35                 # thickness at the middle of the middle segment
DEGREES = (2, 3, 4)
SKELETON = "polyline_zigzag.json"

FIGURE = Figure(
    paper="Hubert 2012", kind="Figure", number="4",
    caption="Convolution curves for a set of segments with power inverse kernel p², p³, p⁴. "
            "Sharpness increases from left to right.",
    skeletons=[SKELETON], kernel="p², p³, p⁴ (each segment weight 1, fields summed)",
    iso="for each kernel the level of thickness τ = 0.35 at the middle of the middle segment",
    view="plane z = 0; below: the two angles zoomed (±0.9 around each vertex)", size=(1600, 1050))
ZOOM = 0.9                 # half-width of the zoomed windows around each inner vertex
DEGREE_COLOURS = {2: "tab:green", 3: "tab:blue", 4: "tab:red"}


def with_degree(degree):
    prims = load_skeleton(SKELETON)["primitives"]
    for p in prims:
        p["kernel"]["degree"] = degree
    return prims


def vertices():
    prims = load_skeleton(SKELETON)["primitives"]
    return [np.array(prims[0]["a"], float)] + [np.array(p["b"], float) for p in prims]


def segment_distance(gx, gy, a, b):
    """Distance from the grid points (gx, gy) to the segment [a, b] of the plane."""
    d = b[:2] - a[:2]
    t = np.clip(((gx - a[0]) * d[0] + (gy - a[1]) * d[1]) / (d @ d), 0.0, 1.0)
    return np.hypot(gx - a[0] - t * d[0], gy - a[1] - t * d[1])


def apex_directions(points):
    """For each inner vertex, the unit vector pointing out of the convex side."""
    out = []
    for prev, v, nxt in zip(points[:-2], points[1:-1], points[2:]):
        u1 = (prev - v) / np.linalg.norm(prev - v)
        u2 = (nxt - v) / np.linalg.norm(nxt - v)
        bisector = -(u1 + u2)
        out.append((v, bisector / np.linalg.norm(bisector)))
    return out


def draw(ctx):
    points = vertices()
    mid_a, mid_b = points[1], points[2]
    middle = 0.5 * (mid_a + mid_b)
    tangent = (mid_b - mid_a) / np.linalg.norm(mid_b - mid_a)
    normal = np.array([-tangent[1], tangent[0], 0.0])
    xs = np.linspace(-3.2, 3.2, ctx.res(480, 120))
    ys = np.linspace(-1.8, 1.8, ctx.res(270, 70))
    fig = plot.plt.figure(figsize=(FIGURE.size[0] / plot.DPI, FIGURE.size[1] / plot.DPI), dpi=plot.DPI,
                          constrained_layout=True)
    mosaic = fig.subplot_mosaic([["p2", "p2", "p3", "p3", "p4", "p4"], ["z0", "z0", "z0", "z1", "z1", "z1"]],
                                gridspec_kw={"height_ratios": [1, 1.9]})
    axes = [mosaic["p2"], mosaic["p3"], mosaic["p4"]]
    inner = [v for v, _ in apex_directions(points)]
    zooms = [(mosaic[f"z{k}"], v) for k, v in enumerate(inner)]
    zoom_axes = [np.linspace(v[k] - ZOOM, v[k] + ZOOM, ctx.res(361, 41)) for v in inner for k in (0, 1)]
    sharpness = {}
    for ax, degree in zip(axes, DEGREES):
        field = ctx.field_of(with_degree(degree))
        level = field.f([middle + TAU * normal])[0]
        plot.contour_segments(ax, xs, ys, field.on_grid(xs, ys), level, colors=[DEGREE_COLOURS[degree]])
        for k, (zax, v) in enumerate(zooms):
            zx, zy = zoom_axes[2 * k], zoom_axes[2 * k + 1]
            plot.contour_segments(zax, zx, zy, field.on_grid(zx, zy), level, colors=[DEGREE_COLOURS[degree]],
                                  linewidths=1.8)
            zax.plot([], [], color=DEGREE_COLOURS[degree], lw=1.8, label=f"$p^{degree}$, κ = {level:.4g}")
        for a, b in zip(points[:-1], points[1:]):
            plot.draw_segment(ax, a, b, lw=1.5)
        values = []
        for v, d in apex_directions(points):
            t_in = crossing(field, [v], [-d], level, 1e-9, 3.0)[0]
            t_out = crossing(field, [v], [d], level, 1e-9, 3.0)[0]
            values.append((-curvature_2d(field, v - t_in * d) * TAU, t_out / TAU))
        sharpness[degree] = values
        ax.set_title(f"$p^{degree}$, κ = {level:.4g}")
        ax.set_aspect("equal")
        ax.set_xlabel("x")
    axes[0].set_ylabel("y")
    for k, (zax, v) in enumerate(zooms):
        zx, zy = zoom_axes[2 * k], zoom_axes[2 * k + 1]
        gx, gy = np.meshgrid(zx, zy)
        offset = np.min([segment_distance(gx, gy, a, b) for a, b in zip(points[:-1], points[1:])], axis=0)
        zax.contour(zx, zy, offset, levels=[TAU], colors=["black"], linestyles=["--"], linewidths=1.2)
        zax.plot([], [], "k--", lw=1.2, label="offset curve at distance τ (the sharp limit)")
        for a, b in zip(points[:-1], points[1:]):
            plot.draw_segment(zax, a, b, lw=1.5)
        zax.set_xlim(zx[0], zx[-1])
        zax.set_ylim(zy[0], zy[-1])
        zax.set_aspect("equal")
        zax.set_title(f"zoom on the angle at ({v[0]:g}, {v[1]:g}): p², p³, p⁴ together")
        zax.legend(loc="upper right" if k == 0 else "lower right", fontsize=9)   # the corners the curves leave free
    plot.save(fig, ctx.image_path, FIGURE.size)

    concave = {d: [c for c, _ in sharpness[d]] for d in DEGREES}
    convex = {d: [r for _, r in sharpness[d]] for d in DEGREES}
    angles = range(len(concave[2]))
    return [
        Claim("sharpness at the angles increases with i (p² < p³ < p⁴): the concave corner",
              "curvature × τ on the bisector inside each of the two angles: " +
              "; ".join(f"p^{d}: " + ", ".join(fmt(v) for v in concave[d]) for d in DEGREES),
              all(concave[2][k] > concave[3][k] > concave[4][k] for k in angles)),
        Claim("… and the convex corner (closer to the offset curve's arc of radius τ)",
              "distance from the vertex to the curve on the outer bisector ÷ τ: " +
              "; ".join(f"p^{d}: " + ", ".join(fmt(v) for v in convex[d]) for d in DEGREES),
              all(convex[2][k] < convex[3][k] < convex[4][k] < 1 for k in angles)),
    ]
