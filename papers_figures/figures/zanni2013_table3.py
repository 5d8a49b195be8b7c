"""Zanni et al. 2013, Table 3: the integrals of the SCALIS segment with a linearly
varying radius, C (Cauchy), P (inverse), R (compact polynomial) and their
gradients, in the table's own variables l² = |AB|²/σ², uv = AB·AP/σ²,
d² = |AP|²/σ², h(t, P) = AB t − AP, Δτ = τ1 − τ0.

Checked: each formula as printed, integrated by Gauss–Legendre quadrature
(figlib.quadrature; the compact one over [l1, l2] ∩ [0, 1], the roots of its
quadratic), divided by the normalisation h of eq. (14) (∫ K(√(1 + u²)) du, by
quadrature), is the field and gradient `skelconv eval` gives for the same
scalis_segment (closed forms of generated/ and scalis_compact.hpp)."""
import numpy as np

from figlib.claims import Claim, fmt
from figlib.figure import Figure
from figlib.quadrature import gauss_legendre, over_real_line
from figlib.zanni import scalis_segment

FIGURE = Figure(
    paper="Zanni et al. 2013", kind="Table", number="3",
    caption="Integrals for homothetic segments with linearly varying radius. Intermediate variables: "
            "l² = |AB|²/σ², uv = AB·AP/σ², d(P)² = |AP|²/σ² and h(t, P) = AB t − AP. For the compact polynomial "
            "kernel, l1 and l2 are the parametric coordinates of the segment's points at the limit of the "
            "kernel's support.",
    original_caption="Intégrales pour les segments homothétiques à variation de rayon linéaire. Nous utilisons les "
                     "variables intermédiaires suivantes : l² = |AB|²/σ², uv = AB·AP/σ², d(P)² = |AP|²/σ² et "
                     "h(t, P) = AB t − AP. Dans le cas du noyau polynomial compact, l1 et l2 correspondent aux "
                     "coordonnées paramétriques des points du segment à la limite du support du noyau.",
    kernel="Cauchy 4 (σ = 0.7), inverse 3 (σ = 1.3), compact 4 and 6 (σ = 1.5); segment (0,0,0)–(2,0.5,0), radius "
           "0.3 → 0.8",
    size=None)

A, B = np.array([0.0, 0.0, 0.0]), np.array([2.0, 0.5, 0.0])
TAU0, TAU1 = 0.3, 0.8
KERNELS = (("cauchy", 4, 0.7), ("inverse", 3, 1.3), ("compact", 4, 1.5), ("compact", 6, 1.5))   # σ ≠ 1: its powers show
# points around the segment: near the thin end, beside it, beyond the thick end, above it
POINTS = np.array([[-0.2, 0.1, 0.1], [0.5, 0.6, 0.0], [1.0, -0.3, 0.4], [1.9, 0.9, 0.2], [2.6, 0.5, -0.3],
                   [1.2, 0.3, 0.9], [0.3, -0.1, -0.35]])
AGREE = 1e-9      # closed forms and quadrature agree far below this when the formula is right


def printed(family, i, sigma, p):
    """Table 3 at P: (value, gradient), by quadrature of the printed integrands."""
    ab, ap = B - A, p - A
    l2, uv, d2, dt = ab @ ab / sigma ** 2, ab @ ap / sigma ** 2, ap @ ap / sigma ** 2, TAU1 - TAU0
    norm = np.linalg.norm(ab)
    tau = lambda t: dt * t + TAU0
    if family == "cauchy":
        q = lambda t: (l2 + dt ** 2) * t ** 2 - 2 * (uv - dt * TAU0) * t + d2 + TAU0 ** 2
        f = lambda t: tau(t) ** (i - 1) / q(t) ** (i / 2)
        g = lambda t: tau(t) ** (i - 1) / q(t) ** ((i + 2) / 2)
        lo, hi = 0.0, 1.0
    elif family == "inverse":
        q = lambda t: l2 * t ** 2 - 2 * uv * t + d2
        f = lambda t: tau(t) ** (i - 1) / q(t) ** (i / 2)
        g = lambda t: tau(t) ** (i - 1) / q(t) ** ((i + 2) / 2)
        lo, hi = 0.0, 1.0
    else:
        c2, c1, c0 = dt ** 2 - l2, -2 * (-dt * TAU0 - uv), TAU0 ** 2 - d2
        q = lambda t: c2 * t ** 2 + c1 * t + c0
        f = lambda t: q(t) ** (i / 2) / tau(t) ** (i + 1)
        g = lambda t: q(t) ** ((i - 2) / 2) / tau(t) ** (i + 1)
        roots = np.sort(np.roots([c2, c1, c0]).real) if c1 * c1 - 4 * c2 * c0 > 0 else None
        if roots is None:
            return 0.0, np.zeros(3)
        lo, hi = max(0.0, roots[0]), min(1.0, roots[1])      # l1, l2: where q > 0 (c2 < 0: the slope σ|Δτ'| < 1)
        if hi <= lo:
            return 0.0, np.zeros(3)
    value = norm * gauss_legendre(f, lo, hi)[0]
    grad = np.array([(i / sigma ** 2) * norm *
                     gauss_legendre(lambda t, k=k: g(t) * (ab[k] * t - ap[k]), lo, hi, rtol=1e-12)[0]
                     for k in range(3)])
    return value, grad


def normalisation(family, i, sigma):
    """h = ∫ K(√(1 + u²)) du (eq. 14's normalisation, docs/mathematics.md §4), by quadrature."""
    if family == "cauchy":
        return over_real_line(lambda u: (1 + (1 + u * u) / sigma ** 2) ** (-i / 2))[0]
    if family == "inverse":
        return over_real_line(lambda u: ((1 + u * u) / sigma ** 2) ** (-i / 2))[0]
    rho = np.sqrt(sigma ** 2 - 1)
    return gauss_legendre(lambda phi: (1 - (1 + (rho * np.sin(phi)) ** 2) / sigma ** 2) ** (i / 2) * rho * np.cos(phi),
                          -0.5 * np.pi, 0.5 * np.pi)[0]


def draw(ctx):
    rows = ["| kernel | points | worst \\|f_printed − f\\| / \\|f\\| | worst \\|∇_printed − ∇f\\| / \\|∇f\\| |", "|---|---|---|---|"]
    worst = {}
    for family, i, sigma in KERNELS:
        field = ctx.field_of([scalis_segment(A, B, TAU0, TAU1, family, i, sigma)])
        values, grads = field.eval(POINTS)
        h = normalisation(family, i, sigma)
        ef, eg, used = 0.0, 0.0, 0
        for p, v, gr in zip(POINTS, values, grads):
            pv, pg = printed(family, i, sigma, p)
            if v == 0 and pv == 0:
                continue            # outside the compact support: both vanish
            used += 1
            ef = max(ef, abs(pv / h - v) / abs(v))
            eg = max(eg, np.linalg.norm(pg / h - gr) / np.linalg.norm(gr))
        name = f"{family} {i}, σ = {sigma:g}"
        worst[name] = (ef, eg)
        rows.append(f"| {name} | {used} of {len(POINTS)} | {fmt(ef)} | {fmt(eg)} |")
    ctx.markdown = ("Segment (0,0,0)–(2,0.5,0), radius 0.3 → 0.8; f = c·F/h with c = 1. Points: " +
                    ", ".join("(" + ", ".join(f"{x:g}" for x in p) + ")" for p in POINTS) + ".\n\n" + "\n".join(rows))
    return [
        Claim("the integrals C, P, R of Table 3 (and their gradients, with the factor i/σ² and h(t, P)) are the "
              "SCALIS segment of linear radius",
              "printed formula by quadrature ÷ h against skelconv's closed form, worst relative difference (f, ∇f): " +
              ", ".join(f"{k}: {fmt(a)}, {fmt(b)}" for k, (a, b) in worst.items()) + f" (below {AGREE:g})",
              all(a < AGREE and b < AGREE for a, b in worst.values())),
    ]
