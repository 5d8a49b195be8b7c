"""Experiment (not a figure of the paper): the limit that Zanni et al. 2013's
Figure 10 sketches (§4.1; the figure itself is a conceptual diagram, listed
in pending.txt with Figures 8, 9 and 13), checked in numbers.
A segment of varying radius is approximated by N segments of constant radius,
each a homothetic primitive of §3 (one homothety per piece); as N → ∞ their sum
becomes eq. (13), f(P) = ∫ K(|Γ(s)P| / τ(s)) ds / τ(s), which the runtime's
linear-radius SCALIS segment evaluates in closed form.

Checked: the sum of N constant-radius pieces (radius τ at each piece's middle:
a midpoint rule in s) converges to the closed form, with the midpoint rule's
order 2, at points around the segment; and the iso-curves f = 1 approach the
limit's. Both sides go through `skelconv eval`: N scalis_segment primitives of
constant radius against one of linear radius."""
import numpy as np

from figlib import plot
from figlib.claims import Claim, fmt
from figlib.figure import Figure
from figlib.zanni import scalis_segment

FAMILY, DEGREE, SIGMA = "cauchy", 4, 1.0
A, B = (0.0, 0.0, 0.0), (4.0, 0.0, 0.0)
TAU0, TAU1 = 1.0, 0.25      # radius decreasing linearly (non-zero at both ends: Cauchy diverges at a radius-0 end)
PIECES = (1, 2, 4, 8, 16, 32, 64)
FLOOR = 0.05                # error measured where f ≥ 0.05 (relative error of a vanishing field says nothing)
LIMIT_ERROR = 1e-4          # the limit, extrapolated from N = 32 and 64 (Richardson, order 2), within 1e-4 of eq. (13)
ORDER = (1.8, 2.2)          # the midpoint rule's order 2, from the last doublings

FIGURE = Figure(
    paper="Zanni et al. 2013", kind="Figure", number="the limit of §4.1 (Figure 10's space deformation)",
    experiment=True,
    caption="The space deformation of Figure 10 (\"Taking the space deformation to the limit\") in numbers: a "
            "segment of varying radius as N homothetic pieces of constant radius, against eq. (13) as N grows.",
    section="the limit drawn and measured: a linear-radius segment approximated by N homothetic constant-radius "
            "pieces; (a) iso-curves f = 1 for N = 1, 2, 4 and the limit eq. (13); (b) the largest relative "
            "difference to eq. (13) against N",
    kernel=f"SCALIS Cauchy {DEGREE}, σ = {SIGMA:g}; radius {TAU0:g} → {TAU1:g} along (0,0,0)–(4,0,0)",
    iso="1", view="(a) plane z = 0, y ≥ 0; (b) points of the grid of (a) where f ≥ 0.05",
    size=(1700, 520))


def pieces(n):
    """N constant-radius SCALIS segments; piece k has the radius τ at its middle."""
    out = []
    for k in range(n):
        u, v, mid = k / n, (k + 1) / n, (k + 0.5) / n
        tau = TAU0 + mid * (TAU1 - TAU0)
        out.append(scalis_segment((A[0] + u * (B[0] - A[0]), 0.0, 0.0), (A[0] + v * (B[0] - A[0]), 0.0, 0.0),
                                  tau, tau, FAMILY, DEGREE, SIGMA))
    return out


def draw(ctx):
    xs = np.linspace(-1.5, 5.5, ctx.res(420, 40))
    ys = np.linspace(0.0, 1.2, ctx.res(90, 10))
    limit = ctx.field_of([scalis_segment(A, B, TAU0, TAU1, FAMILY, DEGREE, SIGMA)]).on_grid(xs, ys, "xy")
    keep = limit >= FLOOR
    grids, errors = {}, []
    for n in PIECES:
        grids[n] = ctx.field_of(pieces(n)).on_grid(xs, ys, "xy")
        errors.append(float(np.max(np.abs(grids[n][keep] / limit[keep] - 1))))
    orders = [float(np.log2(errors[k] / errors[k + 1])) for k in range(len(errors) - 1)]
    # Richardson: the midpoint rule's error is c/N² + O(1/N⁴), so (4 f_2N − f_N)/3 is the limit to O(1/N⁴);
    # a closed form off by ε would show ε here.
    extrapolated = (4 * grids[PIECES[-1]] - grids[PIECES[-2]]) / 3
    limit_error = float(np.max(np.abs(extrapolated[keep] / limit[keep] - 1)))
    last = orders[-2:]
    if ctx.image_path:
        draw_image(ctx, xs, ys, limit, grids, errors)
    return [
        Claim("(§4.1) approximating a varying radius by constant-radius homothetic pieces and passing to the limit "
              "gives eq. (13) (the runtime's linear-radius closed form)",
              f"max |f_N / f − 1| where f ≥ {FLOOR:g}: " + ", ".join(f"N = {n}: {fmt(e)}" for n, e in zip(PIECES, errors))
              + f"; the limit extrapolated from N = {PIECES[-2]}, {PIECES[-1]}: {fmt(limit_error)} (below {LIMIT_ERROR:g})",
              limit_error < LIMIT_ERROR),
        Claim("(ours) the pieces are a midpoint rule in s, so the limit is approached at order 2",
              "log₂ of the error ratio per doubling of N, last two: " + ", ".join(fmt(o) for o in last) +
              f" (in [{ORDER[0]:g}, {ORDER[1]:g}])",
              all(ORDER[0] <= o <= ORDER[1] for o in last)),
    ]


def draw_image(ctx, xs, ys, limit, grids, errors):
    fig, axes = plot.new_figure(FIGURE.size, 1, 2, gridspec_kw={"width_ratios": [2.2, 1]}, constrained_layout=True)
    ax = axes[0]
    for n, colour in zip((1, 2, 4), ("tab:orange", "tab:purple", "tab:blue")):
        plot.contour_segments(ax, xs, ys, grids[n], 1.0, colors=[colour])
        ax.plot([], [], color=colour, label=f"N = {n} constant-radius pieces")
        for k in range(n):
            tau = TAU0 + (k + 0.5) / n * (TAU1 - TAU0)
            ax.plot([4 * k / n, 4 * (k + 1) / n], [tau, tau], ":", color=colour, lw=0.8)
    plot.contour_segments(ax, xs, ys, limit, 1.0, colors=[plot.SCALIS])
    ax.plot([], [], color=plot.SCALIS, lw=2, label="limit, eq. (13) (closed form)")
    ax.plot([A[0], B[0]], [0, 0], "k-", lw=2)
    ax.plot([A[0], B[0]], [TAU0, TAU1], "k--", lw=0.8, label="τ(s) (dotted: the pieces' radii)")
    ax.set_aspect("equal")
    ax.set_title("(a) iso-curves f = 1, section z = 0", fontsize=10)
    ax.legend(loc="upper right", fontsize=8)
    ax = axes[1]
    ax.loglog(PIECES, errors, "o-", color=plot.SCALIS, label="max |f_N / f − 1|")
    ref = errors[-1] * (np.asarray(PIECES, float) / PIECES[-1]) ** -2
    ax.loglog(PIECES, ref, "k:", label="slope −2")
    ax.set_xlabel("N, constant-radius pieces")
    ax.set_ylabel(f"largest relative difference to eq. (13) (f ≥ {FLOOR:g})")
    ax.set_title("(b) convergence to the limit", fontsize=10)
    ax.legend(fontsize=8)
    plot.save(fig, ctx.image_path, FIGURE.size)
