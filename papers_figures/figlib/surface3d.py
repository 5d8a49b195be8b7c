"""The shaded 3-D figures: surfaces meshed by `skelconv mesh` (CGAL Mesh_3,
vertices projected onto f = iso, exact normals), rendered with POV-Ray
(render3d/povray.py: one camera direction, light and colour for all) and
put side by side with a title per panel.

A figure calls mesh() for each surface, measures its claim on the returned
Mesh (the vertices lie on the surface to 1e-9 × the mesh's size, so
distances and extents read off the vertices are those of the surface up to
the facet size), then panels() draws the picture (nothing is rendered in
ctest's --no-images runs)."""
import json
import os
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass

import numpy as np

from . import plot

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "render3d"))
from ply import read_ply  # noqa: E402
import povray  # noqa: E402


class MeshError(RuntimeError):
    pass


@dataclass
class Mesh:
    vertices: np.ndarray       # N×3, on the surface
    normals: np.ndarray        # N×3, −∇f/|∇f|
    faces: np.ndarray          # M×3
    stats: dict                # the `key: value` lines `skelconv mesh` prints (triangles, closed, time, ...)
    seconds: float             # wall time of the `skelconv mesh` process
    command: str               # the command, for the gallery

    def slab(self, axis, value, half_width):
        """The vertices with |x_axis − value| ≤ half_width."""
        return self.vertices[np.abs(self.vertices[:, axis] - value) <= half_width]

    @property
    def closed(self):
        return self.stats.get("closed") == "yes" and self.stats.get("manifold") == "yes"


def mesh(ctx, skeleton, iso, size, name, method="cgal", distance=None):
    """`skelconv mesh` of the skeleton (a dict, docs/cli_skeleton.md) at level iso and facet size `size`
    (distance: the facet-to-surface distance, skelconv's default size/10 when None).
    Raises MeshError with the command and skelconv's message when it fails."""
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, f"{name}.json")
        with open(path, "w") as handle:
            json.dump(skeleton, handle)
        out = os.path.join(tmp, f"{name}.ply")
        command = [ctx.skelconv, "mesh", path, "-o", out, "--iso", repr(float(iso)), "--size", repr(float(size)),
                   "--method", method, "--quiet"] + ([] if distance is None else ["--distance", repr(float(distance))])
        start = time.monotonic()
        run = subprocess.run(command, capture_output=True, text=True)
        seconds = time.monotonic() - start
        shown = f"skelconv mesh {name}.json -o {name}.ply --iso {float(iso):.6g} --size {float(size):g}" + \
            ("" if method == "cgal" else f" --method {method}") + ("" if distance is None else f" --distance {distance:g}")
        if run.returncode != 0:
            raise MeshError(f"{shown}: exit {run.returncode}: {run.stderr.strip()}")
        stats = dict(line.split(": ", 1) for line in run.stdout.splitlines() if ": " in line)
        vertices, normals, faces = read_ply(out)
    ctx.log(f"{shown}: {stats.get('triangles')} triangles, {seconds:.2f} s")
    return Mesh(vertices, normals, faces, stats, seconds, shown)


def common_frame(meshes):
    """One (centre, radius) framing every mesh at its place: the panels of a figure share a scale."""
    points = np.concatenate([m.vertices for m in meshes])
    return povray.framing(points)


def render_one(mesh_, png, width, height, frame=None, colours=None, view=None, overlay=None):
    povray.render(mesh_.vertices, mesh_.normals, mesh_.faces, png, width, height, frame=frame, colours=colours,
                  view=view, overlay=overlay)


def picture(ax, m, size, layout_px, frame=None, view=None, colours=None, title=None):
    """Renders mesh m into the matplotlib axes ax of a figure of layout size `size`, at
    layout_px = (width, height) layout pixels (enlarged like the saved image), no axes drawn."""
    scale = plot.print_scale(size)
    with tempfile.TemporaryDirectory() as tmp:
        png = os.path.join(tmp, "panel.png")
        render_one(m, png, round(layout_px[0] * scale), round(layout_px[1] * scale), frame, colours, view)
        ax.imshow(plot.plt.imread(png), interpolation="nearest")
    ax.set_axis_off()
    if title:
        ax.set_title(title)


def overlay(primitives, tube_radius):
    """The skeleton drawn inside a translucent surface (povray.skeleton_overlay): pass it to panels()."""
    return povray.skeleton_overlay(primitives, tube_radius)


def panels(ctx, items, size, shared_frame=True, rows=1, frame=None, view=None, overlays=None):
    """Renders [(Mesh, title), ...] (or (Mesh, title, per-vertex colours)) side by side
    (rows × ceil(n/rows) panels) into ctx.image_path at size (width, height) px.
    shared_frame: one camera framing radius for all panels, centred on each mesh's own
    centre, so that sizes compare; frame = (centre, radius): that framing for every panel.
    view: the figure's camera direction (povray.scene), the default one when None.
    overlays: per panel, a skeleton overlay (overlay()) or None."""
    if ctx.image_path is None:
        return
    cols = -(-len(items) // rows)
    title_px = 22
    width, height = size[0] // cols, size[1] // rows - title_px
    scale = plot.print_scale(size)            # POV-Ray renders at the saved image's pixel size
    radius = max(povray.framing(item[0].vertices)[1] for item in items)
    fig, axes = plot.new_figure(size, rows, cols, squeeze=False)
    fig.subplots_adjust(left=0, right=1, bottom=0, top=1 - title_px / size[1], wspace=0, hspace=title_px / height)
    with tempfile.TemporaryDirectory() as tmp:
        for k, (item, ax) in enumerate(zip(items, axes.flat)):
            m, title = item[0], item[1]
            colours = item[2] if len(item) > 2 else None
            png = os.path.join(tmp, f"panel{k}.png")
            own = frame if frame is not None else (povray.framing(m.vertices)[0], radius) if shared_frame else None
            render_one(m, png, round(width * scale), round(height * scale), own, colours, view,
                       overlays[k] if overlays else None)
            ax.imshow(plot.plt.imread(png), interpolation="nearest")
            ax.set_title(title)
    for ax in axes.flat:
        ax.set_axis_off()
    plot.save(fig, ctx.image_path, size)


def section(m, axis, value):
    """The points where the mesh's edges cross the plane x_axis = value (linear
    interpolation along each edge: the mesh's own cross-section)."""
    edges = np.concatenate([m.faces[:, [0, 1]], m.faces[:, [1, 2]], m.faces[:, [2, 0]]])
    p, q = m.vertices[edges[:, 0]], m.vertices[edges[:, 1]]
    a, b = p[:, axis] - value, q[:, axis] - value
    crossing = (a < 0) != (b < 0)
    s = a[crossing] / (a[crossing] - b[crossing])
    return p[crossing] + s[:, None] * (q[crossing] - p[crossing])


def widths(m, axis, across, stations, near=None, half_range=np.inf):
    """Extent along `across` of the mesh's section x_axis = s, for s in stations
    (0 where the section is empty); near: only section points with
    |x_across − near| < half_range."""
    out = []
    for s in stations:
        v = section(m, axis, s)
        if near is not None:
            v = v[np.abs(v[:, across] - near) < half_range]
        out.append(float(v[:, across].max() - v[:, across].min()) if len(v) else 0.0)
    return np.array(out)
