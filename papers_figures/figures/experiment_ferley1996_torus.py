"""Experiment (not a figure of the Ferley report): reconstruction of the test shape 'torus' by the method after Ferley 1996: a ring of 16 SCALIS segments of radius 0.4 on a circle of radius 2,
meshed, skeletonized, joined back (figlib/reconstruction.py draws it)."""
from figlib.figure import Figure
from figlib.reconstruction import draw_shape

FIGURE = Figure(
    paper="skeleton-based reconstruction (method after Ferley 1996)", kind="Figure", number="test shape 'torus'",
    experiment=True,
    caption="Reconstruction of a ring of 16 SCALIS segments of radius 0.4 on a circle of radius 2: samples, known and recovered skeleton, and the distance of every "
            "stage's surface from the input (docs/reconstruction.md).",
    kernel="SCALIS Cauchy 4, σ = 1.5", iso="1", view="projection on the plane shown", size=(640, 360))


def draw(ctx):
    return draw_shape(ctx, FIGURE, "torus", (1, 0, 0), (0, 1), mesh_args=())
