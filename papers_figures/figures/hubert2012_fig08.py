"""Hubert 2012, Figure 8: the equilateral triangle [(2,0,0), (−1,√3,0),
(−1,−√3,0)], the graph of its Cauchy c_s⁴ field on the plane z = 0, and the
step-function-like contribution of one side: the m-th term of Hubert §7,

    C = 1/(2(1 + s z²)) Σ_m ((Q_{m+1} − Q_m) × (P̄ − Q_m))·n D^{c_s²}_{[Q_m Q_{m+1}]}(P),
    D^{c_s²}_{[AB]}(P) = J_2(s|AB|², s AB·AP, 1 + s|AP|²),

written in Python from the paper (figlib/reference.py, J_2 by its atan
closed form, docs/mathematics.md §2) and checked against skelconv's polygon field."""
import numpy as np

from figlib import plot
from figlib.claims import Claim, fmt
from figlib.figure import Figure
from figlib.reference import polygon_edge_terms

S = 1.0
SQ3 = np.sqrt(3.0)
VERTICES = np.array([[2.0, 0, 0], [-1.0, SQ3, 0], [-1.0, -SQ3, 0]])
SKELETON = "equilateral_triangle_cauchy4.json"

FIGURE = Figure(
    paper="Hubert 2012", kind="Figure", number="8",
    caption="An equilateral triangle (left), the graph of the convolution function above it (middle) and "
            "the step-function like contribution of a side of the triangle to it (right).",
    skeletons=[SKELETON], kernel="classical Cauchy c_s⁴, s = 1", view="f on the plane z = 0, x, y in [−3, 3]",
    size=(1600, 560))
# Where the three panels sit (figure fractions: left, bottom, width, height): the two 3-D
# graphs get most of the width.
PANELS = ([0.04, 0.12, 0.2, 0.76], [0.25, 0.02, 0.37, 0.93], [0.62, 0.02, 0.37, 0.93])
BOX_ZOOM = 1.0


def edge_term(m, points):
    """The m-th term of Hubert §7's sum for c_s⁴ at points (N×3)."""
    return polygon_edge_terms(VERTICES, points, "cauchy", s=S)[m]


def draw(ctx):
    n = ctx.res(121, 31)
    g = np.linspace(-3, 3, n)
    gx, gy = np.meshgrid(g, g)
    points = np.stack([gx.ravel(), gy.ravel(), np.zeros(gx.size)], axis=1)
    field = ctx.field(SKELETON)
    f = field.f(points)
    terms = [edge_term(m, points) for m in range(3)]
    total = sum(terms)
    mismatch = float(np.max(np.abs(total - f)) / np.max(np.abs(f)))
    # a few points off the plane too
    off = points[:: max(1, len(points) // 200)] + np.array([0, 0, 0.7])
    mismatch_off = float(np.max(np.abs(sum(edge_term(m, off) for m in range(3)) - field.f(off))) / np.max(f))

    fig = plot.plt.figure(figsize=(FIGURE.size[0] / plot.DPI, FIGURE.size[1] / plot.DPI), dpi=plot.DPI)
    ax0 = fig.add_axes(PANELS[0])
    closed = np.vstack([VERTICES, VERTICES[:1]])
    ax0.fill(closed[:, 0], closed[:, 1], color="0.85", edgecolor="black")
    ax0.plot(closed[1:3, 0], closed[1:3, 1], color="tab:red", lw=2.5, label="the side of the right plot")
    ax0.set_aspect("equal")
    ax0.set_xlim(-3, 3)
    ax0.set_ylim(-3, 3)
    ax0.set_xlabel("x")
    ax0.set_ylabel("y")
    ax0.set_title("triangle Ω")
    ax0.legend(loc="lower center", fontsize=8)
    for k, (values, title) in enumerate(((f, "f(x, y, 0), $c_s^4$, s = 1"),
                                         (terms[1], "contribution of one side"))):
        ax = fig.add_axes(PANELS[1 + k], projection="3d")
        ax.set_box_aspect(None, zoom=BOX_ZOOM)
        ax.plot_surface(gx, gy, values.reshape(gx.shape), cmap="viridis", linewidth=0, antialiased=False,
                        rcount=n, ccount=n)
        ax.view_init(elev=30, azim=-60)
        ax.set_xlabel("x")
        ax.set_ylabel("y")
        ax.tick_params(labelsize=8)
        ax.set_title(title, fontsize=10, y=0.98)
    plot.save(fig, ctx.image_path, FIGURE.size)

    # Across the side [Q1 Q2] (x = −1), along y = 0, at distances ±d from it.
    d = np.array([0.25, 0.5, 1.0, 2.0])
    inside = np.stack([-1 + d, np.zeros_like(d), np.zeros_like(d)], axis=1)
    outside = np.stack([-1 - d, np.zeros_like(d), np.zeros_like(d)], axis=1)
    t_in, t_out = edge_term(1, inside), edge_term(1, outside)
    odd = float(np.max(np.abs(t_in + t_out)) / np.max(np.abs(t_in)))
    return [
        Claim("the convolution function of c_s⁴ over the polygon is the sum of the edge terms of §7",
              f"Σ of the 3 terms (paper's formula, Python) vs skelconv's polygon field: max difference "
              f"{fmt(mismatch)} × max f on z = 0, {fmt(mismatch_off)} at z = 0.7", mismatch < 1e-12 and mismatch_off < 1e-12),
        Claim("each side contributes a step-function-like term (Sherstyuk's remark)",
              "term of the side x = −1, along y = 0, at distance d = " + ", ".join(fmt(x) for x in d) +
              " inside: " + ", ".join(fmt(v) for v in t_in) + "; outside: " + ", ".join(fmt(v) for v in t_out) +
              f" (a smoothed step from −c to +c across the side, odd to {fmt(odd)}; f at the centre "
              f"{fmt(field.f([[0, 0, 0]])[0])})",
              odd < 1e-12 and t_in[2] > 0.8 * t_in.max() and np.all(np.diff(t_in[:3]) > 0)),
    ]
