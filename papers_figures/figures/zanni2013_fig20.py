"""Zanni et al. 2013, Figure 20: a branching (a trunk of radius τ splitting
into two branches τ1 = τ2), summed: (a) classical convolution with
τ1 + τ2 = τ (weights), (b) SCALIS with τ1 + τ2 = τ, (c) SCALIS with
τ1² + τ2² = τ². Measured on the meshes: the width of the shape across the
trunk just below the fork (y = −0.3) against the trunk's designed width 2τ
(a bulge makes the ratio exceed 1, a pinch makes it fall below), and the
trunk's width far from the fork (y = −2.5) for reference. The paper states
no number; its §6.2.2 says classical convolution is superposable (no bulge
with τ1 + τ2 = τ) and SCALIS is not, which lets one choose what the fork
preserves."""
import numpy as np

from figlib import surface3d
from figlib.claims import Claim, fmt
from figlib.figure import Figure
from figlib.zanni import classical_cauchy_line, classical_segment, scalis_segment

DEGREE, SIGMA = 4, 1.0
TAU = 0.6
FORK, TRUNK_END, BRANCH_END = (0.0, 0.0, 0.0), (0.0, -4.0, 0.0), (1.6, 3.0, 0.0)
STATIONS = np.array([-2.5, -0.3])                 # far down the trunk, just below the fork
ISO_CLASSICAL = classical_cauchy_line(TAU, TAU, DEGREE, SIGMA)   # radius τ around a line of weight τ
SAME_WIDTH = 0.05         # |width at the fork / 2τ − 1| below this: the fork keeps the trunk's width
BRANCHES = {"(a) classical, τ1 + τ2 = τ": TAU / 2, "(b) SCALIS, τ1 + τ2 = τ": TAU / 2,
            "(c) SCALIS, τ1² + τ2² = τ²": TAU / np.sqrt(2)}

FIGURE = Figure(
    paper="Zanni et al. 2013", kind="Figure", number="20",
    caption="Comparison of branching types: (a) convolution surfaces with τ1 + τ2 = τ, (b) homothetic surfaces "
            "with τ1 + τ2 = τ, (c) homothetic surfaces with τ1² + τ2² = τ².",
    original_caption="Comparaison entre différents types de branchement : (a) surfaces de convolution avec "
                     "τ1 + τ2 = τ, (b) surfaces homothétiques avec τ1 + τ2 = τ, (c) surfaces homothétiques avec "
                     "τ1² + τ2² = τ².",
    section=f"our branching (the paper's is not given): trunk (0,−4,0)–(0,0,0), branches to (±1.6, 3, 0), τ = {TAU}; "
            "summed (the paper's classical superposition). In (a) the branches of weight τ/2 have no surface of "
            "their own at the classical level (as in fig. 4a): only stubs at the fork",
    kernel="Cauchy 4, σ = 1 (classical: c_s⁴, s = 1, weights τ)",
    iso=f"SCALIS 1; classical {ISO_CLASSICAL:.5g} (radius τ around a line of weight τ)",
    view="the fixed camera of render3d, one scale for all panels", size=(640, 260))


def branching(label, tau_branch):
    ends = [BRANCH_END, (-BRANCH_END[0], BRANCH_END[1], 0.0)]
    if label.startswith("(a)"):
        prims = [classical_segment(TRUNK_END, FORK, TAU, TAU, "cauchy", DEGREE, SIGMA)] + \
                [classical_segment(FORK, e, tau_branch, tau_branch, "cauchy", DEGREE, SIGMA) for e in ends]
        return {"primitives": prims}, ISO_CLASSICAL
    prims = [scalis_segment(TRUNK_END, FORK, TAU, TAU, "cauchy", DEGREE, SIGMA)] + \
            [scalis_segment(FORK, e, tau_branch, tau_branch, "cauchy", DEGREE, SIGMA) for e in ends]
    return {"primitives": prims}, 1.0


def draw(ctx):
    size = ctx.res(0.05, 0.12)
    meshes, ratios, texts = [], {}, []
    for label, tau_branch in BRANCHES.items():
        skeleton, iso = branching(label, tau_branch)
        m = surface3d.mesh(ctx, skeleton, iso, size, f"fig20{label[1]}")
        w = surface3d.widths(m, 1, 0, STATIONS)
        ratios[label[:3]] = w[1] / (2 * TAU)
        texts.append(f"{label[:3]} {fmt(w[1] / (2 * TAU))} (trunk at y = {STATIONS[0]:g}: {fmt(w[0] / (2 * TAU))}; "
                     f"{m.stats['triangles']} triangles, closed {m.stats['closed']})")
        meshes.append((m, label))
    surface3d.panels(ctx, meshes, FIGURE.size)
    measured = f"width at y = {STATIONS[1]:g} / 2τ: " + "; ".join(texts)
    closed = all(m.closed for m, _ in meshes)
    return [
        Claim("(a) classical convolution is superposable: τ1 + τ2 = τ keeps the trunk's width at the fork",
              measured, abs(ratios["(a)"] - 1) < SAME_WIDTH and closed),
        Claim("(b) SCALIS is not superposable (§6.2.2): with τ1 + τ2 = τ the fork is thinner than the trunk",
              f"(b) {fmt(ratios['(b)'])} (pinch: below {1 - SAME_WIDTH:g})", ratios["(b)"] < 1 - SAME_WIDTH),
        Claim("(c) SCALIS with τ1² + τ2² = τ² (conserving the cross-section area) keeps the width at the fork",
              f"(c) {fmt(ratios['(c)'])} (within {SAME_WIDTH:.0%} of 1)", abs(ratios["(c)"] - 1) < SAME_WIDTH),
    ]
