"""Experiment (not a figure of the Ferley report): reconstruction of the test shape 'tree' by the method after Ferley 1996: a binary tree of depth 3 (15 SCALIS segments, radius × 0.75 per level, branching 38°),
meshed, skeletonized, joined back (figlib/reconstruction.py draws it)."""
from figlib.figure import Figure
from figlib.reconstruction import draw_shape

FIGURE = Figure(
    paper="skeleton-based reconstruction (method after Ferley 1996)", kind="Figure", number="test shape 'tree'",
    experiment=True,
    caption="Reconstruction of a binary tree of depth 3 (15 SCALIS segments, radius × 0.75 per level, branching 38°): samples, known and recovered skeleton, and the distance of every "
            "stage's surface from the input (docs/reconstruction.md).",
    kernel="SCALIS Cauchy 4, σ = 1.5", iso="1", view="projection on the plane shown", size=(640, 360))


def draw(ctx):
    return draw_shape(ctx, FIGURE, "tree", (15, 9, 7), (0, 2), mesh_args=("--size", "0.1", "--distance", "0.02"))
