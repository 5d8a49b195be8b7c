"""The drawing shared by Hubert 2012 Figures 6 and 7 (a polygon and its p⁴
convolution surface): the polygon with the surface's outline in its plane,
and the section through the centroid, plus the check of skelconv's field
against the paper's p⁴ formula (§6: 1/(2z²) Σ edge terms of D^{p²})."""
import numpy as np

from . import plot
from .claims import Claim, fmt
from .figure import load_skeleton
from .reference import polygon_edge_terms

TAU = 0.25          # the level: thickness τ above the centroid


def draw_polygon_p4(ctx, figure, skeleton_name):
    vertices = np.array(load_skeleton(skeleton_name)["primitives"][0]["vertices"], float)
    field = ctx.field(skeleton_name)
    centroid = vertices.mean(axis=0)
    level = field.f([centroid + [0, 0, TAU]])[0]
    fig, axes = plot.new_figure(figure.size, 1, 2, constrained_layout=True)
    xs = np.linspace(-2.6, 2.6, ctx.res(400, 80))
    ys = np.linspace(-2.2, 2.2, ctx.res(340, 70))
    closed = np.vstack([vertices, vertices[:1]])
    plane = field.on_grid(xs, ys, plane="xy", offset=0.0)
    plane[~np.isfinite(plane)] = 1e300                     # f = ∞ on the polygon (inverse kernel)
    axes[0].fill(closed[:, 0], closed[:, 1], color="0.85", edgecolor="black")
    plot.contour_segments(axes[0], xs, ys, plane, level, colors=["tab:blue"])
    axes[0].set_title(f"outline in the plane z = 0, κ = {level:.4g}")
    axes[0].set_xlabel("x")
    axes[0].set_ylabel("y")
    zs = np.linspace(-1.0, 1.0, ctx.res(160, 40))
    section = field.on_grid(xs, zs, plane="xz", offset=centroid[1])
    section[~np.isfinite(section)] = 1e300
    plot.contour_segments(axes[1], xs, zs, section, level, colors=["tab:blue"])
    inside = _chord(vertices, centroid[1])
    axes[1].plot(inside[:, 0], inside[:, 1], color="black", lw=2)
    axes[1].set_title(f"section y = {centroid[1] + 0.0:.2f} (τ = {TAU})")
    axes[1].set_xlabel("x")
    axes[1].set_ylabel("z")
    for ax in axes:
        ax.set_aspect("equal")
    plot.save(fig, ctx.image_path, figure.size)

    rng = np.random.default_rng(6)
    points = rng.uniform([-2.5, -2.5, 0.05], [2.5, 2.5, 1.5], size=(ctx.res(400, 60), 3))
    points[: len(points) // 2, 2] *= -1                    # both sides of the plane
    paper = sum(polygon_edge_terms(vertices, points, "inverse"))
    ours = field.f(points)
    diff = float(np.max(np.abs(paper - ours) / ours))
    return [Claim("the p⁴ field of the polygon is 1/(2z²) Σ_m ((Q_{m+1} − Q_m) × (P̄ − Q_m))·n D^{p²}_m(P) (§6)",
                  f"the paper's formula (Python) against skelconv at {len(points)} points 0.05–1.5 from the plane: "
                  f"max relative difference {fmt(diff)}", diff < 1e-11)]


def _chord(vertices, y):
    """The segments of the polygon's intersection with the line y = const (for the section), as x pairs."""
    xs = []
    for a, b in zip(vertices, np.roll(vertices, -1, axis=0)):
        if (a[1] - y) * (b[1] - y) < 0:
            xs.append(a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
    xs.sort()
    points = []
    for x0, x1 in zip(xs[::2], xs[1::2]):
        points += [(x0, 0.0), (x1, 0.0), (np.nan, np.nan)]
    return np.array(points) if points else np.zeros((0, 2))
