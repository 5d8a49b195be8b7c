"""Hubert 2012, Figure 6: a regular pentagon and its p⁴ convolution surface,
drawn as the outline in the pentagon's plane and a section (the shaded
surface: hubert2012_fig06_3d)."""
from figlib.figure import Figure
from figlib.polygon_figure import TAU, draw_polygon_p4

SKELETON = "regular_pentagon_p4.json"
FIGURE = Figure(
    paper="Hubert 2012", kind="Figure", number="6",
    caption="Pentagon and convolution surface generated with the p⁴ kernel.",
    section="the surface's outline in the pentagon's plane and its section through the centroid",
    skeletons=[SKELETON], kernel="p⁴", iso=f"the level of thickness τ = {TAU} above the centroid",
    view="plane z = 0 and plane y = centroid", size=(640, 280))


def draw(ctx):
    return draw_polygon_p4(ctx, FIGURE, SKELETON)
