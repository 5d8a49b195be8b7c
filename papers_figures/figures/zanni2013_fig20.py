"""Zanni et al. 2013, Figure 20: a branching (a trunk of radius τ splitting
into two branches τ1 = τ2), summed: (a) classical convolution with
τ1 + τ2 = τ (weights), (b) SCALIS with τ1 + τ2 = τ, (c) SCALIS with
τ1² + τ2² = τ². Measured on the meshes: the width of the shape across the
trunk just below the fork (y = −0.3) against the trunk's designed width 2τ
(a bulge makes the ratio exceed 1, a pinch makes it fall below), and the
trunk's width far from the fork (y = −2.5) for reference. The paper states
no number; its §6.2.2 says classical convolution is superposable (no bulge
with τ1 + τ2 = τ) and SCALIS is not, which lets one choose what the fork
preserves.

The classical branches must exist at the classical level, or (a) shows no fork
at all: a line of weight w has a surface only if w ≥ τ_min = τ(1 + τ²/σ²)^(-3/2)
(the field on the axis reaches the iso of the trunk), so with w = τ/2 the
classical kernel's scale must satisfy (1 + τ²/σ²)^(3/2) > 2, i.e. τ/σ > 0.766.
We take σ = τ/1.2 for the classical kernel (σ = 1 for SCALIS, which is scale
invariant and has no τ_min). The fork is then checked as what it is: the cut
y = FORK_CUT above the fork meets the iso-surface (plane z = 0) in two
separate components, one per branch, in every panel."""
import numpy as np

from figlib import surface3d
from figlib.claims import Claim, fmt
from figlib.figure import Figure
from figlib.zanni import classical_cauchy_line, classical_segment, scalis_segment

DEGREE, SIGMA = 4, 1.0
TAU = 0.6
FORK, TRUNK_END, BRANCH_END = (0.0, 0.0, 0.0), (0.0, -4.0, 0.0), (1.6, 3.0, 0.0)
STATIONS = np.array([-2.5, -0.3])                 # far down the trunk, just below the fork
# Classical kernel scale: τ/σ = 1.2 > 0.766, so a branch of weight τ/2 has a surface of radius ≈ 0.61 τ
# (see the docstring); with σ = 1 (τ/σ = 0.6) the branches would have none.
SIGMA_CLASSICAL = TAU / 1.2
ISO_CLASSICAL = classical_cauchy_line(TAU, TAU, DEGREE, SIGMA_CLASSICAL)   # radius τ around a line of weight τ
FORK_CUT = 2.5            # the cut y = 2.5, where the branches' axes are 2.67 apart (far more than 2 radii)
CUT_SAMPLES = 2001        # samples of f along x ∈ [−4, 4] on the cut (step 0.004, far below a branch's width)
SAME_WIDTH = 0.05         # |width at the fork / 2τ − 1| below this: the fork keeps the trunk's width
VIEW = [0.0, -0.3, 1.0]   # front-on: looking down on the fork's plane z = 0, tilted a little
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
            "summed (the paper's classical superposition)",
    kernel="Cauchy 4; SCALIS σ = 1; classical c_s⁴ with σ = τ/1.2 = 0.5 (s = 1/σ² = 4), weights τ: τ/2 is above "
           "the classical τ_min, so the branches exist",
    iso=f"SCALIS 1; classical {ISO_CLASSICAL:.5g} (radius τ around a line of weight τ)",
    view="front-on (from above the skeleton's plane z = 0), one scale for all panels", size=(1600, 760))


def branching(label, tau_branch):
    ends = [BRANCH_END, (-BRANCH_END[0], BRANCH_END[1], 0.0)]
    if label.startswith("(a)"):
        prims = [classical_segment(TRUNK_END, FORK, TAU, TAU, "cauchy", DEGREE, SIGMA_CLASSICAL)] + \
                [classical_segment(FORK, e, tau_branch, tau_branch, "cauchy", DEGREE, SIGMA_CLASSICAL) for e in ends]
        return {"primitives": prims}, ISO_CLASSICAL
    prims = [scalis_segment(TRUNK_END, FORK, TAU, TAU, "cauchy", DEGREE, SIGMA)] + \
            [scalis_segment(FORK, e, tau_branch, tau_branch, "cauchy", DEGREE, SIGMA) for e in ends]
    return {"primitives": prims}, 1.0


def cut_components(ctx, skeleton, iso):
    """Intervals of x on the line y = FORK_CUT, z = 0 where f > iso: the components of the
    iso-curve's inside in the cut (2 for a fork, 1 if the branches merged, 0 if they vanished)."""
    xs = np.linspace(-4.0, 4.0, CUT_SAMPLES)
    inside = ctx.field_of(skeleton["primitives"]).f(np.column_stack([xs, np.full_like(xs, FORK_CUT), 0 * xs])) > iso
    starts = np.flatnonzero(inside[1:] & ~inside[:-1]) + 1
    ends = np.flatnonzero(~inside[1:] & inside[:-1]) + 1
    if inside[0] or inside[-1]:
        return None                          # the cut does not reach outside the shape: not a fork
    return [(xs[a], xs[b - 1]) for a, b in zip(starts, ends)]


def draw(ctx):
    size = ctx.res(0.05, 0.12)
    meshes, ratios, texts, comps = [], {}, [], {}
    for label, tau_branch in BRANCHES.items():
        skeleton, iso = branching(label, tau_branch)
        comps[label[:3]] = cut_components(ctx, skeleton, iso)
        m = surface3d.mesh(ctx, skeleton, iso, size, f"fig20{label[1]}")
        w = surface3d.widths(m, 1, 0, STATIONS)
        ratios[label[:3]] = w[1] / (2 * TAU)
        texts.append(f"{label[:3]} {fmt(w[1] / (2 * TAU))} (trunk at y = {STATIONS[0]:g}: {fmt(w[0] / (2 * TAU))}; "
                     f"{m.stats['triangles']} triangles, closed {m.stats['closed']})")
        meshes.append((m, f"{label}: width at the fork {w[1] / (2 * TAU):.2f} × 2τ"))
    surface3d.panels(ctx, meshes, FIGURE.size, view=VIEW)
    measured = f"width at y = {STATIONS[1]:g} / 2τ: " + "; ".join(texts)
    closed = all(m.closed for m, _ in meshes)
    def describe(c):
        return "cut not closed" if c is None else f"{len(c)} (" + ", ".join(f"x ∈ [{a:.2f}, {b:.2f}]" for a, b in c) + ")"
    forks = all(c is not None and len(c) == 2 for c in comps.values())
    return [
        Claim(f"(ours) each panel is a fork: the cut y = {FORK_CUT:g} above it meets the shape in two components, one per branch",
              "; ".join(f"{k} {describe(c)}" for k, c in comps.items()), forks),
        Claim("(a) classical convolution is superposable: τ1 + τ2 = τ keeps the trunk's width at the fork",
              measured, abs(ratios["(a)"] - 1) < SAME_WIDTH and closed),
        Claim("(b) SCALIS is not superposable (§6.2.2): with τ1 + τ2 = τ the fork is thinner than the trunk",
              f"(b) {fmt(ratios['(b)'])} (pinch: below {1 - SAME_WIDTH:g})", ratios["(b)"] < 1 - SAME_WIDTH),
        Claim("(c) SCALIS with τ1² + τ2² = τ² (conserving the cross-section area) keeps the width at the fork",
              f"(c) {fmt(ratios['(c)'])} (within {SAME_WIDTH:.0%} of 1)", abs(ratios["(c)"] - 1) < SAME_WIDTH),
    ]
