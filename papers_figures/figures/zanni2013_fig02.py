"""Zanni et al. 2013, Figure 2 (§2): blending two primitives by a sum.
Distance primitives f = K(dist(P, S_k)) bulge where their skeletons meet;
convolution primitives f = ∫_S K(|P − s|) ds do not, since the integral over
two abutting segments is the integral over their union.

Set-up (the paper gives none): two collinear segments (−2,0,0)–(0,0,0) and
(0,0,0)–(2,0,0), the compact kernel K(r) = (1 − r²/R²)³ (degree 6, R = 1,
the paper's practice), thickness τ = 0.5 away from the joint. Distance model:
iso K(τ), evaluated here from its definition (skelconv has no distance
primitive). Convolution: skelconv `segment` primitives, iso the closed-form
field of an infinite line of weight 1 at distance τ,
∫ (1 − (τ² + s²)/R²)³ ds = (32/35) (R² − τ²)^(7/2) / R⁶
(exact here: a point at distance τ from x = 0 or x = ±1 has its whole
support chord, 2√(R² − τ²) ≈ 1.73, on the skeleton).

The paper prints no size for the bulge; the expected one is exact: at the
joint both distances equal r, so 2K(r) = K(τ) gives
r = R √(1 − (1 − τ²/R²) 2^(−1/3)) (+27 % over τ)."""
import numpy as np

from figlib import plot
from figlib.claims import Claim, fmt
from figlib.figure import Figure
from figlib.zanni import classical_segment

DEGREE, R, TAU = 6, 1.0, 0.5
SEGMENTS = (((-2.0, 0.0, 0.0), (0.0, 0.0, 0.0)), ((0.0, 0.0, 0.0), (2.0, 0.0, 0.0)))
ISO_CONVOLUTION = 32 / 35 * (R * R - TAU * TAU) ** 3.5 / R ** 6
BULGE = R * np.sqrt(1 - (1 - TAU * TAU / R ** 2) * 2 ** (-1 / 3))   # the distance model's radius at the joint
RADIUS_TOL = 1e-6         # bisection of the radius to 1e-9; the closed forms hold to rounding
FLAT = 0.02               # the convolution's radius at the joint within 2 % of τ: "no bulge"
STATIONS = (-1.0, 0.0, 1.0)

FIGURE = Figure(
    paper="Zanni et al. 2013", kind="Figure", number="2",
    caption="Blending two primitives by summation: distance primitives (a) produce a bulge, unlike convolution "
            "primitives (b).",
    original_caption="Mélange par sommation de deux primitives : les primitives distances (a) entraînent "
                     "l'apparition d'un gonflement contrairement aux primitives de convolution (b).",
    section="our skeleton (the paper's is not given): two collinear segments meeting at the origin",
    kernel=f"compact (1 − r²/R²)³, R = {R:g}; (a) K(distance), (b) convolution, weight 1",
    iso=f"(a) K(τ) = {(1 - TAU ** 2) ** 3:.5g}; (b) {ISO_CONVOLUTION:.5g} (radius τ = {TAU:g} around an infinite line)",
    view="plane z = 0", size=(1600, 400))


def kernel(r):
    u = np.clip(1 - (r / R) ** 2, 0, None)
    return u ** (DEGREE // 2)


def segment_distance(p, a, b):
    a, b = np.asarray(a), np.asarray(b)
    t = np.clip(((p - a) @ (b - a)) / np.dot(b - a, b - a), 0, 1)
    return np.linalg.norm(p - (a + t[:, None] * (b - a)), axis=1)


def distance_field(points):
    points = np.asarray(points, float).reshape(-1, 3)
    return sum(kernel(segment_distance(points, a, b)) for a, b in SEGMENTS)


def radius(f, iso, x):
    """The surface's distance from the axis above abscissa x (bisection on y; f decreases in y here)."""
    lo, hi = 0.0, R
    for _ in range(40):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if f(np.array([[x, mid, 0.0]]))[0] > iso else (lo, mid)
    return 0.5 * (lo + hi)


def draw(ctx):
    conv = ctx.field_of([classical_segment(a, b, 1.0, 1.0, "compact", DEGREE, R) for a, b in SEGMENTS])
    iso_d = kernel(TAU)
    r_dist = {x: radius(distance_field, iso_d, x) for x in STATIONS}
    r_conv = {x: radius(conv.f, ISO_CONVOLUTION, x) for x in STATIONS}
    if ctx.image_path:
        xs = np.linspace(-3.2, 3.2, ctx.res(640, 100))
        ys = np.linspace(-1.1, 1.1, ctx.res(220, 40))
        gx, gy = np.meshgrid(xs, ys)
        grid = np.column_stack([gx.ravel(), gy.ravel(), 0 * gx.ravel()])
        fig, axes = plot.new_figure(FIGURE.size, 1, 2, constrained_layout=True, sharey=True)
        for ax, values, iso, colour, title in (
                (axes[0], distance_field(grid).reshape(gx.shape), iso_d, plot.CLASSICAL,
                 f"(a) distance primitives, summed: radius {BULGE:.3f} at the joint (τ = {TAU:g})"),
                (axes[1], conv.on_grid(xs, ys), ISO_CONVOLUTION, plot.SCALIS,
                 f"(b) convolution primitives, summed: radius {r_conv[0.0]:.3f} at the joint")):
            plot.contour_segments(ax, xs, ys, values, iso, colors=[colour])
            for a, b in SEGMENTS:
                plot.draw_segment(ax, a, b, lw=2.5)
            ax.plot([0], [0], "ko", ms=5)
            ax.axhline(TAU, color="0.6", ls=":", lw=1)
            ax.axhline(-TAU, color="0.6", ls=":", lw=1)
            ax.set_aspect("equal")
            ax.set_xlabel("x")
            ax.set_title(title)
        axes[0].set_ylabel("y  (dotted: ±τ)")
        plot.save(fig, ctx.image_path, FIGURE.size)
    return [
        Claim("(a) summed distance primitives bulge at the joint: radius R√(1 − (1 − τ²/R²)2^(−1/3)) there "
              "(2K(r) = K(τ)), τ away from it",
              f"radius at x = −1, 0, 1: {', '.join(fmt(r_dist[x], 6) for x in STATIONS)}; expected at the joint "
              f"{fmt(BULGE, 6)} (+{fmt((BULGE / TAU - 1) * 100, 3)} %)",
              abs(r_dist[0.0] - BULGE) < RADIUS_TOL and abs(r_dist[1.0] - TAU) < RADIUS_TOL
              and abs(r_dist[-1.0] - TAU) < RADIUS_TOL),
        Claim(f"(b) summed convolution primitives do not: radius τ at the joint (within {FLAT:.0%})",
              f"radius at x = −1, 0, 1: {', '.join(fmt(r_conv[x], 6) for x in STATIONS)} (τ = {TAU:g})",
              all(abs(r_conv[x] / TAU - 1) < FLAT for x in STATIONS)),
    ]
