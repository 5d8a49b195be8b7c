"""Experiment: reconstruction by a medial mesh (docs/reconstruction_medial.md). Three shapes whose
medial axis is made of sheets, not curves: a cube, a plate (the cube flattened to 1 × 1 × 0.2) and a
tetrahedron. Per shape: the input, the medial mesh `skelconv skeletonize --method medial` builds
(triangles: sheets; red lines: tubes), and its surface meshed back, coloured by the distance of each
vertex to the input."""
import json
import os
import subprocess
import tempfile

import numpy as np

from figlib import plot
from figlib.claims import Claim, fmt
from figlib.figure import Figure
from figlib.reconstruction import DATA, read_ply

FIGURE = Figure(
    paper="skeleton-based reconstruction", kind="Figure", number="medial meshes", experiment=True,
    caption="A cube, a plate and a tetrahedron: the input, the medial mesh of SCALIS triangles (sheets) and "
            "segments (tubes) built by `skelconv skeletonize --method medial`, and its surface coloured by the "
            "distance to the input (% of the bounding-box diagonal); the titles give the two-sided Hausdorff "
            "distance of the medial path and of the curve path (docs/reconstruction_medial.md).",
    kernel="SCALIS compact 4, σ = 2 (medial); Cauchy 4, σ = 1.5 (curve)", iso="1", view="axonometric",
    size=(960, 900))

SHAPES = [("cube", "cube.ply", 1.0), ("plate", "cube.ply", 0.2), ("tetrahedron", "tetrahedron.obj", 1.0)]


def _run(args):
    run = subprocess.run(args, capture_output=True, text=True)
    if run.returncode != 0:
        raise RuntimeError(f"{' '.join(args)}: {run.stderr.strip()}")
    return run.stdout


def _read_input(name, z_scale, tmp):
    """The input mesh as (vertices, triangles), written to tmp as PLY (the plate is scaled)."""
    if name.endswith(".obj"):
        lines = [line.split() for line in open(os.path.join(DATA, name))]
        v = np.array([[float(x) for x in w[1:4]] for w in lines if w and w[0] == "v"])
        f = np.array([[int(x) - 1 for x in w[1:4]] for w in lines if w and w[0] == "f"])
    else:
        v, _, f = read_ply(os.path.join(DATA, name))
    v = v * np.array([1.0, 1.0, z_scale])
    path = os.path.join(tmp, f"input_{z_scale}_{os.path.splitext(name)[0]}.ply")
    with open(path, "w") as out:
        out.write(f"ply\nformat ascii 1.0\nelement vertex {len(v)}\nproperty double x\nproperty double y\n"
                  f"property double z\nelement face {len(f)}\nproperty list uchar int vertex_indices\nend_header\n")
        out.writelines(f"{a:.17g} {b:.17g} {c:.17g}\n" for a, b, c in v)
        out.writelines(f"3 {a} {b} {c}\n" for a, b, c in f)
    return path, v, f


def _surface_points(v, f, n=60):
    """Points spread evenly over every triangle (a barycentric grid of n steps)."""
    out = []
    for a, b, c in v[f]:
        for i in range(n + 1):
            for j in range(n + 1 - i):
                out.append(a + (b - a) * i / n + (c - a) * j / n)
    return np.array(out)


def _distances(points, surface):
    """Distance of each point to the nearest of `surface`'s points (chunked brute force)."""
    out = np.empty(len(points))
    for start in range(0, len(points), 2000):
        chunk = points[start:start + 2000]
        d2 = ((chunk[:, None, :] - surface[None, :, :]) ** 2).sum(-1)
        out[start:start + 2000] = np.sqrt(d2.min(1))
    return out


def _medial_primitives(path):
    with open(path) as handle:
        children = json.load(handle)["primitives"][0]["children"]
    triangles = [np.array(c["vertices"]) for c in children if c["type"] == "scalis_triangle"]
    segments = [(np.array(c["a"]), np.array(c["b"])) for c in children if c["type"] == "scalis_segment"]
    return triangles, segments


def _report(ctx, mesh, method, tmp):
    out, report = os.path.join(tmp, f"{method}.json"), os.path.join(tmp, f"{method}_report.json")
    _run([ctx.skelconv, "skeletonize", mesh, "-o", out, "--method", method, "--report", report,
          "--report-stages", "result", "--quiet"])
    with open(report) as handle:
        r = json.load(handle)
    return out, r["stages"][-1], r["input_euler_characteristic"]


def _box(ax, v):
    lo, hi = v.min(0), v.max(0)
    centre, half = (lo + hi) / 2, (hi - lo).max() / 2
    ax.set_xlim(centre[0] - half, centre[0] + half), ax.set_ylim(centre[1] - half, centre[1] + half)
    ax.set_zlim(centre[2] - half, centre[2] + half)
    ax.set_axis_off()
    ax.view_init(24, 35)


def _shade(v, f):
    n = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
    n /= np.linalg.norm(n, axis=1, keepdims=True) + 1e-300
    light = np.array([0.3, -0.5, 0.8]) / np.linalg.norm([0.3, -0.5, 0.8])
    return 0.35 + 0.65 * np.clip(n @ light, 0, 1)


def draw(ctx):
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection
    import matplotlib.pyplot as plt
    fig = plt.figure(figsize=(FIGURE.size[0] / plot.DPI, FIGURE.size[1] / plot.DPI), dpi=plot.DPI)
    claims = []
    norm = plt.Normalize(0.0, 6.0)
    with tempfile.TemporaryDirectory() as tmp:
        for row, (label, name, z_scale) in enumerate(SHAPES):
            path, v, f = _read_input(name, z_scale, tmp)
            diagonal = np.linalg.norm(v.max(0) - v.min(0))
            medial, m, chi_in = _report(ctx, path, "medial", tmp)
            _, c, _ = _report(ctx, path, "curve", tmp)
            rec = os.path.join(tmp, "rec.ply")
            _run([ctx.skelconv, "mesh", medial, "-o", rec, "--method", "grid", "--size", f"{diagonal / 100:.17g}"])
            rv, _, rf = read_ply(rec)
            error = 100 * _distances(rv[rf].mean(1), _surface_points(v, f)) / diagonal
            ax = fig.add_subplot(3, 3, 3 * row + 1, projection="3d")
            ax.add_collection3d(Poly3DCollection(v[f], facecolors=plt.cm.gray(_shade(v, f)), edgecolor="0.4", lw=0.3))
            _box(ax, v), ax.set_title(f"{label}: input", fontsize=9)
            ax = fig.add_subplot(3, 3, 3 * row + 2, projection="3d")
            triangles, segments = _medial_primitives(medial)
            ax.add_collection3d(Poly3DCollection(triangles, facecolor="tab:blue", alpha=0.35, edgecolor="k", lw=0.2))
            for a, b in segments:
                ax.plot(*zip(a, b), color="tab:red", lw=1.0)
            _box(ax, v), ax.set_title(f"medial mesh: {len(triangles)} triangles, {len(segments)} segments", fontsize=9)
            ax = fig.add_subplot(3, 3, 3 * row + 3, projection="3d")
            colours = plt.cm.viridis(norm(error))
            colours[:, :3] *= _shade(rv, rf)[:, None]
            ax.add_collection3d(Poly3DCollection(rv[rf], facecolors=colours, edgecolor="none"))
            _box(ax, v)
            ax.set_title(f"H {100 * m['hausdorff']:.2f}% (curve path {100 * c['hausdorff']:.2f}%), "
                         f"χ {m['euler_characteristic']}", fontsize=9)
            claims.append(Claim(f"{label}: the medial mesh's surface is nearer the input than the curve path's "
                                f"(two-sided Hausdorff) and keeps its Euler characteristic",
                                f"medial {fmt(100 * m['hausdorff'])}%, curve {fmt(100 * c['hausdorff'])}%, "
                                f"χ {chi_in} → {m['euler_characteristic']}",
                                m["hausdorff"] < c["hausdorff"] and m["euler_characteristic"] == chi_in))
    bar = fig.add_axes([0.3, 0.06, 0.4, 0.015])
    fig.colorbar(plt.cm.ScalarMappable(norm=norm, cmap="viridis"), cax=bar, orientation="horizontal",
                 label="distance to the input, % of the diagonal")
    fig.subplots_adjust(left=0.0, right=1.0, bottom=0.1, top=0.96, wspace=0.0, hspace=0.12)
    plot.save(fig, ctx.image_path, FIGURE.size)
    return claims
