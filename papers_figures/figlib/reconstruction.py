"""Ferley 1996 reconstruction figures (docs/reconstruction.md):
one test shape, meshed from its known skeleton, skeletonized by
`skelconv skeletonize`, the recovered (fitted) skeleton drawn over the
samples and the known skeleton, and, in a full run, the distances of every
stage from the input (`--report`). The figure modules ferley1996_*.py only
say which shape and what is known about it."""
import json
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

from . import plot
from .claims import Claim, fmt

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "render3d"))
from ply import read_ply  # noqa: E402

DATA = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))),
                    "tests", "data", "reconstruct")
HAUSDORFF_TARGET, RMS_TARGET = 0.02, 0.005   # the targets of docs/reconstruction_results.md, × the bounding-box diagonal
STAGES = ["raw", "pruned", "simplified", "simplified_3d", "smoothed", "fitted"]


def _run(args):
    run = subprocess.run(args, capture_output=True, text=True)
    if run.returncode != 0:
        raise RuntimeError(f"{' '.join(args)}: {run.stderr.strip()}")
    return run.stdout


def _input_mesh(ctx, name, mesh_args, tmp):
    """tests/data/reconstruct/NAME.ply, or NAME.json meshed with mesh_args."""
    stored = os.path.join(DATA, name + ".ply")
    if os.path.exists(stored):
        return stored
    out = os.path.join(tmp, name + ".ply")
    _run([ctx.skelconv, "mesh", os.path.join(DATA, name + ".json"), "-o", out] + mesh_args)
    return out


def _segments(path):
    """(a, b) of every scalis_segment of a skeleton file."""
    with open(path) as handle:
        skeleton = json.load(handle)
    out = []

    def walk(items):
        for item in items:
            if "children" in item:
                walk(item["children"])
            elif item.get("type") == "scalis_segment":
                out.append((np.array(item["a"]), np.array(item["b"])))
    walk(skeleton["primitives"])
    return out


def draw_shape(ctx, figure, name, known, plane, mesh_args=(), noise=0.0):
    """Draws the figure of shape NAME; known = (branches, ends, junctions);
    plane = the two coordinates shown, e.g. (0, 1) for x, y."""
    with tempfile.TemporaryDirectory() as tmp:
        mesh = _input_mesh(ctx, name, list(mesh_args), tmp)
        out, report = os.path.join(tmp, "out.json"), os.path.join(tmp, "report.json")
        args = [ctx.skelconv, "skeletonize", mesh, "-o", out, "--method", "curve", "--quiet"]
        if noise > 0:
            args += ["--noise", str(noise)]
        full = not ctx.quick
        summary = _run(args + (["--report", report, "--report-stages", "all"] if full else []))
        recovered = _segments(out)
        known_segments = _segments(os.path.join(DATA, name + ".json"))
        samples, _, _ = read_ply(mesh)
        # A stage over the measuring budget carries "not_measured" instead of
        # distances (docs/reconstruction_input.md, "The report"): not drawn.
        stages = [s for s in json.load(open(report))["stages"] if "hausdorff" in s] if full else []
    counts = {m[0]: tuple(int(x) for x in m[1:]) for m in
              re.findall(r"stage (\w+): branches (\d+), ends (\d+), junctions (\d+)", summary)}

    fig, axes = plot.new_figure(figure.size, 1, 2, gridspec_kw={"width_ratios": [3, 2]})
    ax = axes[0]
    u, v = plane
    ax.scatter(samples[:, u], samples[:, v], s=0.3, color="0.75", label="input samples")
    for k, (a, b) in enumerate(known_segments):
        ax.plot([a[u], b[u]], [a[v], b[v]], "k--", lw=1.0, label="known skeleton" if k == 0 else None)
    for k, (a, b) in enumerate(recovered):
        ax.plot([a[u], b[u]], [a[v], b[v]], color=plot.SCALIS, lw=1.6, label="recovered (fitted)" if k == 0 else None)
    axis = "xyz"
    ax.set_xlabel(axis[u]), ax.set_ylabel(axis[v]), ax.set_aspect("equal")
    # At the figure's foot, below every x label (an axes-anchored legend
    # overlapped the x label of a flat shape such as the segment).
    handles, labels = ax.get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower left", bbox_to_anchor=(0.01, 0.0), ncol=3, fontsize=7, frameon=False)
    ax.set_title(f"{name}: {counts['fitted'][0]} branches / {counts['fitted'][1]} ends / "
                 f"{counts['fitted'][2]} junctions" + (f" (noise {noise})" if noise else ""))
    ax = axes[1]
    if stages:
        x = np.arange(len(stages))
        ax.bar(x - 0.2, [100 * s["hausdorff"] for s in stages], 0.4, label="Hausdorff")
        ax.bar(x + 0.2, [100 * s["rms"] for s in stages], 0.4, label="RMS")
        ax.axhline(100 * HAUSDORFF_TARGET, color="tab:blue", ls=":", lw=1)
        ax.axhline(100 * RMS_TARGET, color="tab:orange", ls=":", lw=1)
        ax.set_xticks(x, [s["name"].replace("simplified_3d", "simpl. 3-D") for s in stages], rotation=45, ha="right")
        ax.set_ylabel("% of the diagonal")
        ax.set_yscale("log")
        ax.legend(loc="upper right")
        ax.set_title("distance to the input\n(dotted: 2 % and 0.5 % targets)")
    else:
        ax.text(0.5, 0.5, "quick run: distances not measured", ha="center", va="center", transform=ax.transAxes)
        ax.set_axis_off()
    fig.subplots_adjust(left=0.08, right=0.98, bottom=0.3, top=0.9, wspace=0.35)
    plot.save(fig, ctx.image_path, figure.size)

    claims = [Claim(f"after pruning, the skeleton has the known {known[0]} branches, {known[1]} ends and "
                    f"{known[2]} junctions",
                    f"pruned {counts['pruned']}, fitted {counts['fitted']} (branches, ends, junctions)",
                    counts["pruned"] == tuple(known) and counts["fitted"] == tuple(known))]
    if stages and noise == 0:
        fitted = stages[-1]
        claims.append(Claim("the fitted surface is within 2% (Hausdorff) and 0.5% (RMS) of the diagonal",
                            f"Hausdorff {fmt(100 * fitted['hausdorff'])}%, RMS {fmt(100 * fitted['rms'])}%",
                            fitted["hausdorff"] <= HAUSDORFF_TARGET and fitted["rms"] <= RMS_TARGET))
    return claims
