"""Hubert 2012, Figure 6, shaded: the regular pentagon and its p⁴ convolution
surface, meshed by `skelconv mesh` at the level of the section figure
(figlib/polygon_surface.py draws and checks it)."""
from figlib.figure import Figure
from figlib.polygon_figure import TAU
from figlib.polygon_surface import draw_polygon_p4_3d

SKELETON = "regular_pentagon_p4.json"
FIGURE = Figure(
    paper="Hubert 2012", kind="Figure", number="6 (3-D)",
    caption="Pentagon and convolution surface generated with the p⁴ kernel.",
    section="the pentagon and the shaded surface (`skelconv mesh`, POV-Ray), one framing for both panels",
    skeletons=[SKELETON], kernel="p⁴", iso=f"the level of thickness τ = {TAU} above the centroid",
    view="the fixed camera of render3d", size=(640, 260))


def draw(ctx):
    return draw_polygon_p4_3d(ctx, FIGURE, SKELETON)
