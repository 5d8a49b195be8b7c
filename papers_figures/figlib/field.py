"""Fields from the `skelconv eval` command: f and ∇f at many points at once.

A Field is a skeleton (a dict in the JSON format of docs/cli_skeleton.md) plus the
path of the skelconv binary. eval() pipes the points through one
`skelconv eval` process; points are written with 17 significant digits, so
the values are exactly those the command gives for those doubles.
"""
import io
import json
import os
import subprocess
import tempfile

import numpy as np


class EvalError(RuntimeError):
    pass


class Field:
    # Counters over every Field (run.py prints them per figure): eval calls, points.
    calls = 0
    points = 0

    def __init__(self, skelconv, skeleton):
        self.skelconv = skelconv
        self.skeleton = skeleton

    @staticmethod
    def from_file(skelconv, path):
        with open(path) as handle:
            return Field(skelconv, json.load(handle))

    def plus(self, other):
        """The field of both skeletons (the sum of their primitives)."""
        return Field(self.skelconv, {"primitives": self.skeleton["primitives"] + other.skeleton["primitives"]})

    def eval(self, points):
        """(f, grad) at points (N×3 array): f has shape N, grad N×3."""
        points = np.ascontiguousarray(np.asarray(points, dtype=float).reshape(-1, 3))
        if len(points) == 0:
            return np.zeros(0), np.zeros((0, 3))
        Field.calls += 1
        Field.points += len(points)
        buffer = io.BytesIO()
        np.savetxt(buffer, points, fmt="%.17g")
        with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as handle:
            json.dump(self.skeleton, handle)
            skeleton_path = handle.name
        try:
            run = subprocess.run([self.skelconv, "eval", skeleton_path], input=buffer.getvalue(),
                                 capture_output=True, check=False)
        finally:
            os.unlink(skeleton_path)
        if run.returncode != 0:
            raise EvalError(f"skelconv eval failed ({run.returncode}): {run.stderr.decode().strip()}")
        values = np.loadtxt(io.BytesIO(run.stdout), ndmin=2)
        if values.shape != (len(points), 4):
            raise EvalError(f"skelconv eval returned {values.shape}, expected ({len(points)}, 4)")
        return values[:, 0], values[:, 1:4]

    def f(self, points):
        return self.eval(points)[0]

    def on_grid(self, xs, ys, plane="xy", offset=0.0):
        """f on the grid xs × ys of a coordinate plane ('xy', 'xz' or 'yz'),
        the third coordinate = offset. Returns an array of shape (len(ys), len(xs))."""
        gx, gy = np.meshgrid(xs, ys)
        third = np.full_like(gx, offset)
        columns = {"xy": (gx, gy, third), "xz": (gx, third, gy), "yz": (third, gx, gy)}[plane]
        points = np.stack([c.ravel() for c in columns], axis=1)
        return self.f(points).reshape(gx.shape)
