"""The SCALIS thickness correction (`skelconv thickness` on a file of
scalis_segment primitives, docs/thickness_correction.md) for the figures of
Zanni et al. 2013 §5.1, and what they measure on it: the thickness along the
skeleton, the extent of a shape beyond a node along its axis, cuts.

Thickness is measured independently of the command's optimiser: through
`skelconv eval` of the written skeleton (figlib.levelset.crossing: a scan and
a safeguarded secant on log f), at points every `step` along each segment,
along the normal of the skeleton's plane (+z: every graph here lies in z = 0)."""
import json
import os
import subprocess
import tempfile

import numpy as np

from figlib import plot
from figlib.levelset import X_TOL, crossing

DEGREE, SIGMA = 6, 2.0          # Zanni §4.3's practice: compact kernel of degree 6, support σ τ with σ = 2
KERNEL = {"family": "compact", "degree": DEGREE, "sigma": SIGMA}
NORMAL = (0.0, 0.0, 1.0)
# Root-finding tolerance of the quick (ctest) runs: the claims are at the 1e-2 level, so 1e-9 of
# the thickness is plenty and halves the `skelconv eval` rounds; full runs keep levelset's default.
QUICK_X_TOL = 1e-9


def x_tol(ctx):
    return ctx.res(X_TOL, QUICK_X_TOL)


def scalis(a, b, r0, r1):
    """A scalis_segment dict in the plane z = 0."""
    return {"type": "scalis_segment", "a": [float(a[0]), float(a[1]), 0.0], "b": [float(b[0]), float(b[1]), 0.0],
            "radius": [float(r0), float(r1)], "kernel": KERNEL}


def correct(ctx, primitives):
    """Runs `skelconv thickness`: returns (before, after) skeleton dicts and the command's report lines."""
    with tempfile.TemporaryDirectory() as tmp:
        source, target = os.path.join(tmp, "in.json"), os.path.join(tmp, "out.json")
        with open(source, "w") as handle:
            json.dump({"primitives": primitives}, handle)
        run = subprocess.run([ctx.skelconv, "thickness", source, "-o", target], capture_output=True, text=True,
                             check=True)
        with open(target) as handle:
            after = json.load(handle)
    return {"primitives": primitives}, after, run.stdout


# The paper's correction as §5.1 describes it (Zanni et al. 2013): point primitives at the
# graph nodes that need one (free ends of non-zero radius and nodes of maximal radius), mixed
# with each other by a symmetric Barthe blend "set to limit their blend", and the result mixed
# with the SCALIS surfaces by an asymmetric Barthe blend. The text gives neither the Barthe
# operators (docs/mathematics.md §6) nor their parameters, nor how the points' influence is chosen beyond
# "from the radius variations of the segments leaving the node" (Figure 13). Built here with
# what skelconv has of that family: Rockwood's super-elliptic blend (a Barthe blend's special
# case, docs/cli_blends.md), exponent BLEND_T, and band widths (in field units, level 1) that
# limit the points' mixing (POINT_BAND) and let the SCALIS part blend more widely than the
# points (SCALIS_BAND against POINT_BAND: the asymmetry). Each point is a compact kernel of the
# SCALIS support σ τ_n whose sphere at level 1 has the node's radius τ_n: it puts back, as a
# round cap of radius τ_n, the skeleton missing at the node. These four choices are ours.
BLEND_T = 2.0
POINT_BAND = 0.25
SCALIS_BAND = 0.6


def graph_nodes(primitives):
    """{node (x, y, z) rounded: [radius of each segment end there, the radius at its other end]}."""
    nodes = {}
    for p in primitives:
        for end, other in ((0, 1), (1, 0)):
            key = tuple(round(float(c), 9) for c in p["a" if end == 0 else "b"])
            nodes.setdefault(key, []).append((p["radius"][end], p["radius"][other]))
    return nodes


def paper_nodes(primitives):
    """[(node, τ_n)] the paper corrects: free ends of non-zero radius, and nodes whose radius is
    larger than at the other end of every segment leaving them (a thickness maximum)."""
    out = []
    for node, ends in graph_nodes(primitives).items():
        tau_n = max(r for r, _ in ends)
        free_end = len(ends) == 1 and tau_n > 0
        maximum = len(ends) > 1 and all(r > other for r, other in ends)
        if free_end or maximum:
            out.append((np.array(node), tau_n))
    return out


def paper_correction(primitives):
    """The skeleton dict of the paper's correction of a SCALIS graph (see POINT_BAND above)."""
    weight = 1.0 / (1.0 - 1.0 / SIGMA ** 2) ** (DEGREE / 2)     # w (1 − τ²/(σ τ)²)^(i/2) = 1: radius τ_n
    points = [{"type": "point", "center": [float(c) for c in node],
               "kernel": {"family": "compact", "degree": DEGREE, "R": SIGMA * tau_n}, "weight": weight}
              for node, tau_n in paper_nodes(primitives)]
    if not points:
        return {"primitives": list(primitives)}
    mixed_points = {"blend": "super_elliptic", "t": BLEND_T, "r": POINT_BAND, "iso": 1.0, "children": points}
    return {"primitives": [{"blend": "super_elliptic", "t": BLEND_T, "r": [SCALIS_BAND, POINT_BAND], "iso": 1.0,
                            "children": [{"blend": "sum", "children": list(primitives)}, mixed_points]}]}


def reach_of(primitives):
    """A distance beyond every support of the corrected skeleton (points reach 1.25 σ τ_n)."""
    return 2 * SIGMA * max(max(p["radius"]) for p in primitives)


def profile(ctx, skeleton, primitives, step):
    """[(arc length, τ(t), r)] per segment of `primitives`, measured on `skeleton` every `step`."""
    field = ctx.field_of(skeleton["primitives"])
    reach = reach_of(primitives)
    out = []
    for p in primitives:
        a, b = np.asarray(p["a"]), np.asarray(p["b"])
        length = float(np.linalg.norm(b - a))
        s = np.linspace(0.0, length, int(np.ceil(length / step)) + 1)
        feet = a[None, :] + (s / length)[:, None] * (b - a)[None, :]
        tau = p["radius"][0] + (s / length) * (p["radius"][1] - p["radius"][0])
        r = np.nan_to_num(crossing(field, feet, NORMAL, 1.0, 0.0, reach, x_tol=x_tol(ctx)), nan=0.0)
        out.append((s, tau, r))
    return out


def worst_departure(profiles):
    """max |r/τ − 1| over the points of positive τ (a tip, τ = 0, has no relative thickness)."""
    return max(float(np.max(np.abs(r[tau > 0] / tau[tau > 0] - 1))) for _, tau, r in profiles)


def extent_beyond(ctx, skeleton, node, direction, reach):
    """How far the surface reaches from `node` along the unit `direction` (in the skeleton's plane)."""
    field = ctx.field_of(skeleton["primitives"])
    r = crossing(field, np.asarray([node], float), np.asarray(direction, float), 1.0, 0.0, reach, x_tol=x_tol(ctx))
    return float(np.nan_to_num(r[0], nan=0.0))


# The versions a figure compares: (label, colour, line style), in the order of the skeletons given.
VERSIONS = (("before", plot.SCALIS, "-"), ("after: ours (`skelconv thickness`)", "tab:green", "-"),
            ("after: the paper's (points, blends)", "tab:purple", "--"))


def cut(ax, ctx, skeletons, primitives, extent, resolution, title, legend_loc="upper right", legend_columns=1):
    """Iso-curves f = 1 of (before, ours[, the paper's]) in the plane z = 0, with the skeleton and its radii."""
    (u0, u1), (v0, v1) = extent
    us = np.linspace(u0, u1, resolution[0])
    vs = np.linspace(v0, v1, resolution[1])
    for skeleton, (label, colour, style) in zip(skeletons, VERSIONS):
        values = ctx.field_of(skeleton["primitives"]).on_grid(us, vs, "xy")
        plot.contour_segments(ax, us, vs, values, 1.0, colors=[colour], linestyles=[style])
        ax.plot([], [], color=colour, ls=style, label=label)
    for p in primitives:
        ax.plot([p["a"][0], p["b"][0]], [p["a"][1], p["b"][1]], "k-", lw=1.2)
        # the requested radius τ(t) on either side of the segment (dotted)
        a, b = np.asarray(p["a"][:2]), np.asarray(p["b"][:2])
        d = (b - a) / np.linalg.norm(b - a)
        n = np.array([-d[1], d[0]])
        for sign in (1, -1):
            ends = [a + sign * p["radius"][0] * n, b + sign * p["radius"][1] * n]
            ax.plot([ends[0][0], ends[1][0]], [ends[0][1], ends[1][1]], "k:", lw=0.8)
    ax.set_aspect("equal")
    ax.set_title(title, fontsize=10)
    ax.legend(loc=legend_loc, fontsize=8, ncol=legend_columns)


def plot_profiles(ax, named, title):
    """r/τ along every segment for [(name, before, ours[, the paper's]) profiles]: dotted, solid, dashed."""
    for k, (name, *versions) in enumerate(named):
        colour = f"C{k}"
        for profiles, (label, _, _), style, width in zip(versions, VERSIONS, (":", "-", "--"), (1, 1.5, 1.2)):
            offset = 0.0
            for j, (s, tau, r) in enumerate(profiles):
                keep = tau > 0
                ax.plot(offset + s[keep], r[keep] / tau[keep], style, color=colour, lw=width,
                        label=f"{name}, {label}" if j == 0 else None)
                offset += float(s[-1])
    ax.set_xlabel("arc length along the graph's segments, one after the other")
    ax.set_ylabel("thickness r / τ(t) along the plane's normal")
    ax.set_title(title, fontsize=10)


def paper_claim(names, before, paper, ours):
    """The claim on the paper's correction as built here: it brings every shape closer to its radii than
    no correction does (the paper admits "slight unwanted swellings"; ours is printed beside it)."""
    from .claims import Claim, fmt
    return Claim("the paper's correction (point primitives at the ends and thickness maxima, Barthe-type blends; "
                 "built from §5.1's text, blend parameters ours) brings each shape closer to its radii",
                 "max |r/τ(t) − 1|, before → the paper's (ours): " +
                 "; ".join(f"{n}: {fmt(b)} → {fmt(p)} ({fmt(o)})" for n, b, p, o in zip(names, before, paper, ours)),
                 all(p < b for b, p in zip(before, paper)),
                 note="§5.1: \"our correction is not perfect in that it may cause slight unwanted swellings\"")
