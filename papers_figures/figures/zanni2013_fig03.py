"""Zanni et al. 2013, Figure 3: how the two classical variable-thickness
convolutions modify the kernel with the wanted thickness τ: eq. (9) (Hornus)
scales the kernel's support, K(d/τ); eq. (10) scales its weight, τ K(d).
Drawn for the compact kernel (σ = 1, i = 4), from skelconv: eq. (10) is a
short classical segment of weight τ; eq. (9) is τ × SCALIS (eq. 13 is eq. 9
with the density 1/τ), de-normalised by h (docs/cli_skeleton.md)."""
import numpy as np

from figlib import plot
from figlib.claims import Claim, fmt
from figlib.figure import Figure
from figlib.levelset import crossing
from figlib.zanni import classical_segment, scalis_segment

DEGREE = 4
SHORT = 1e-4                     # a short segment: f/|AB| is the kernel at the distance
TAUS = (0.5, 1.0, 1.5)
TINY = np.finfo(float).tiny


def h_compact(degree, sigma):
    """SCALIS compact normalisation h = σ(1 − 1/σ²)^((i+1)/2) V_i (docs/mathematics.md §4); only σ > 1."""
    v = {0: 2.0, 1: np.pi / 2}
    for k in range(2, degree + 1):
        v[k] = k / (k + 1) * v[k - 2]
    return sigma * (1 - 1 / sigma ** 2) ** ((degree + 1) / 2) * v[degree]


FIGURE = Figure(
    paper="Zanni et al. 2013", kind="Figure", number="3",
    caption="Modification of the kernel according to the wanted thickness, for the two classical "
            "variable-thickness convolutions.",
    original_caption="Modification du noyau en fonction de l'épaisseur voulue pour les deux types de convolution "
                     "à épaisseur variable classiques.",
    kernel="compact, i = 4, σ = 1.5 (SCALIS needs σ > 1; classical: k_R⁴ with R = σ)",
    view="the kernel as a function of the distance d, τ = 0.5, 1, 1.5", size=(640, 260))


def draw(ctx):
    sigma = 1.5
    d = np.linspace(0.0, 2.6, ctx.res(300, 60))
    points = np.stack([np.zeros_like(d), d, np.zeros_like(d)], axis=1)
    a, b = (-SHORT / 2, 0, 0), (SHORT / 2, 0, 0)
    h = h_compact(DEGREE, sigma)
    fig, axes = plot.new_figure(FIGURE.size, 1, 2, constrained_layout=True, sharey=True)
    supports = {"eq9": [], "eq10": []}
    for tau in TAUS:
        weight = ctx.field_of([classical_segment(a, b, tau, tau, "compact", DEGREE, sigma)])
        support = ctx.field_of([scalis_segment(a, b, tau, tau, "compact", DEGREE, sigma)])
        axes[1].plot(d, weight.f(points) / SHORT, label=f"τ = {tau}")
        axes[0].plot(d, tau * h * support.f(points) / SHORT, label=f"τ = {tau}")   # iso = 1: f = F/h
        for key, field in (("eq10", weight), ("eq9", support)):
            supports[key].append(crossing(field, [[0, 0, 0]], [0, 1.0, 0], TINY, 0.0, 10.0, x_tol=1e-10)[0])
    axes[0].set_title("eq. (9): K(d/τ), the support scales")
    axes[1].set_title("eq. (10): τ K(d), the weight scales")
    for ax in axes:
        ax.set_xlabel("distance d")
        ax.legend(loc="upper right", fontsize=7)
    axes[0].set_ylabel("kernel seen at distance d")
    plot.save(fig, ctx.image_path, FIGURE.size)
    s9 = np.array(supports["eq9"])
    s10 = np.array(supports["eq10"])
    taus = np.array(TAUS)
    return [Claim(
        "eq. (9) changes the kernel's support with τ, eq. (10) only its weight",
        f"support radius for τ = {', '.join(map(str, TAUS))}: eq. (9) {', '.join(fmt(s, 6) for s in s9)} "
        f"(σ τ = {', '.join(fmt(sigma * t, 6) for t in taus)}); eq. (10) {', '.join(fmt(s, 6) for s in s10)} (σ = {sigma})",
        bool(np.all(np.abs(s9 - sigma * taus) < 1e-6) and np.all(np.abs(s10 - sigma) < 1e-6)),
        note="what the formulas and this figure show; the paper's text (§2.3) swaps the two words: \"eq. (9) and "
             "(10) correspond respectively to varying the weight of the kernel, or its support\", while eq. (9), "
             "K(d/τ), scales the support and eq. (10), τ K(d), the weight")]
