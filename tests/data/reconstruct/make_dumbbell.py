#!/usr/bin/env python3
"""Writes dumbbell.off into the current directory: two balls of radius 0.5 whose
centres are 2 apart, joined by a bar of radius 0.08 (2.4% of the bounding-box
diagonal) that meets them at a sharp crease; one closed triangle mesh of genus 0.

A shape to measure `skelconv skeletonize` on (docs/reconstruction_medial.md, the
untuned shapes): a thin neck between two thick parts, the case where a fit that
only thickens or thins spheres pinches the neck off. Not a test input: the mesh
(6 MB) is not kept in the repository. The surface is the zero set of a signed
distance (the balls and the bar joined by a plain minimum), polygonised as
make_disc_ears.py does on a grid 0.02 apart. numpy and the standard library
only; same bytes each run.
  python3 make_dumbbell.py [output.off]
"""
import sys

import numpy as np

from make_disc_ears import axis, polygonise

BALL_RADIUS = 0.5
BAR_RADIUS = 0.08
CENTRES = (-1.0, 1.0)  # on the x axis
STEP = 0.02


def field(p):
    balls = np.minimum(*(np.linalg.norm(p - np.array([cx, 0.0, 0.0]), axis=-1) - BALL_RADIUS for cx in CENTRES))
    radial = np.hypot(p[..., 1], p[..., 2]) - BAR_RADIUS
    along = np.abs(p[..., 0]) - CENTRES[1]
    bar = np.hypot(np.maximum(radial, 0.0), np.maximum(along, 0.0)) + np.minimum(np.maximum(radial, along), 0.0)
    return np.minimum(balls, bar)


def main(path):
    half = CENTRES[1] + BALL_RADIUS + 0.05
    xs = axis(-half, half, STEP)
    ys = axis(-BALL_RADIUS - 0.05, BALL_RADIUS + 0.05, STEP)
    polygonise(field, xs, ys, ys, path)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "dumbbell.off")
