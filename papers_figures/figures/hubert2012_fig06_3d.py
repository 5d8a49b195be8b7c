"""Hubert 2012, Figure 6, shaded: the regular pentagon and its p⁴ convolution
surface, meshed by `skelconv mesh` at the level of the section figure
(figlib/polygon_surface.py draws and checks it)."""
from dataclasses import replace

from figlib.polygon_surface import draw_polygon_p4_3d
from figures.hubert2012_fig06 import FIGURE as SECTIONS, SKELETON

FIGURE = replace(SECTIONS, number="6 (3-D)", view="the fixed camera of render3d", size=(640, 260),
                 section="the pentagon and the shaded surface (`skelconv mesh`, POV-Ra"
                         "y), one framing for both panels")


def draw(ctx):
    return draw_polygon_p4_3d(ctx, FIGURE, SKELETON)
