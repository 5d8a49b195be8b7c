"""Hubert 2012, Figure 7: a non-convex polygon and its p⁴ convolution
surface, drawn as the outline in the polygon's plane and a section (the
shaded surface: hubert2012_fig07_3d)."""
from figlib.figure import Figure
from figlib.polygon_figure import TAU, draw_polygon_p4

SKELETON = "nonconvex_polygon_p4.json"
FIGURE = Figure(
    paper="Hubert 2012", kind="Figure", number="7",
    caption="Non-convex polygon and convolution surface generated with the p⁴ kernel.",
    section="the surface's outline in the polygon's plane and its section through the centroid of the vertices "
            "(the paper's polygon is not given: a dart of our own)",
    skeletons=[SKELETON], kernel="p⁴", iso=f"the level of thickness τ = {TAU} above the vertices' centroid",
    view="plane z = 0 and plane y = centroid", size=(640, 280))


def draw(ctx):
    return draw_polygon_p4(ctx, FIGURE, SKELETON)
