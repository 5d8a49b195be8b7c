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


def cut(ax, ctx, skeletons, primitives, extent, resolution, title):
    """Iso-curves f = 1 of (before, after) in the plane z = 0, with the skeleton and its radii."""
    (u0, u1), (v0, v1) = extent
    us = np.linspace(u0, u1, resolution[0])
    vs = np.linspace(v0, v1, resolution[1])
    for skeleton, colour, label in zip(skeletons, (plot.SCALIS, "tab:green"), ("before", "after")):
        values = ctx.field_of(skeleton["primitives"]).on_grid(us, vs, "xy")
        plot.contour_segments(ax, us, vs, values, 1.0, colors=[colour])
        ax.plot([], [], color=colour, label=label)
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
    ax.legend(loc="upper right", fontsize=8)


def plot_profiles(ax, named, title):
    """r/τ along every segment, before and after, for [(name, before profiles, after profiles)]."""
    for k, (name, before, after) in enumerate(named):
        offset = 0.0
        for j, ((s, tau, rb), (_, _, ra)) in enumerate(zip(before, after)):
            keep = tau > 0
            colour = f"C{k}"
            ax.plot(offset + s[keep], rb[keep] / tau[keep], ":", color=colour, lw=1,
                    label=f"{name}, before" if j == 0 else None)
            ax.plot(offset + s[keep], ra[keep] / tau[keep], "-", color=colour, lw=1.5,
                    label=f"{name}, after" if j == 0 else None)
            offset += float(s[-1])
    ax.set_xlabel("arc length along the graph's segments, one after the other")
    ax.set_ylabel("thickness r / τ(t) along the plane's normal")
    ax.set_title(title, fontsize=10)
