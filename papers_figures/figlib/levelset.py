"""Measuring level sets: where a ray crosses f = level, the curvature of a
level curve, and the distance between two curves."""
import numpy as np

# Bisection halves the bracket each round: 60 rounds take any bracket of
# size ≤ 1e3 below 1e-15 (relative to its size, below double rounding).
BISECTION_ROUNDS = 60


def crossing(field, origins, directions, level, t_inside, t_outside, rounds=BISECTION_ROUNDS):
    """For each ray origin + t·direction, the t in [t_inside, t_outside] where
    f crosses `level`, by bisection (one `skelconv eval` per round for all rays).

    f(t_inside) ≥ level > f(t_outside) is required for every ray; a ray that
    does not bracket the level gets NaN (the caller decides what that means:
    e.g. no surface there)."""
    origins = np.atleast_2d(np.asarray(origins, float))
    directions = np.atleast_2d(np.asarray(directions, float))
    n = max(len(origins), len(directions))
    origins = np.broadcast_to(origins, (n, 3))
    directions = np.broadcast_to(directions, (n, 3))
    lo = np.broadcast_to(np.asarray(t_inside, float), (n,)).copy()
    hi = np.broadcast_to(np.asarray(t_outside, float), (n,)).copy()
    f_lo = field.f(origins + lo[:, None] * directions)
    f_hi = field.f(origins + hi[:, None] * directions)
    bracketed = (f_lo >= level) & (f_hi < level)
    for _ in range(rounds):
        mid = 0.5 * (lo + hi)
        inside = field.f(origins + mid[:, None] * directions) >= level
        lo = np.where(inside, mid, lo)
        hi = np.where(inside, hi, mid)
    return np.where(bracketed, 0.5 * (lo + hi), np.nan)


def curvature_2d(field, point, step=1e-4):
    """Curvature of the level curve of f through `point`, in the xy plane:
    div(∇f/|∇f|), by central differences of the exact gradient with `step`
    (error O(step²) relative to the curvature scale)."""
    p = np.asarray(point, float)
    offsets = np.array([[step, 0, 0], [-step, 0, 0], [0, step, 0], [0, -step, 0]])
    _, grad = field.eval(p + offsets)
    unit = grad / np.linalg.norm(grad[:, :2], axis=1)[:, None]
    return (unit[0, 0] - unit[1, 0]) / (2 * step) + (unit[2, 1] - unit[3, 1]) / (2 * step)


def hausdorff(curve_a, curve_b):
    """Symmetric Hausdorff distance between two point sets (N×2 and M×2)."""
    a = np.asarray(curve_a)
    b = np.asarray(curve_b)
    d = np.sqrt(((a[:, None, :] - b[None, :, :]) ** 2).sum(axis=2))
    return max(d.min(axis=1).max(), d.min(axis=0).max())


def densify(polylines, spacing):
    """The points of polylines resampled at most `spacing` apart (for Hausdorff)."""
    points = []
    for line in polylines:
        for p, q in zip(line[:-1], line[1:]):
            k = max(1, int(np.ceil(np.linalg.norm(q - p) / spacing)))
            t = np.arange(k)[:, None] / k
            points.append(p + t * (q - p))
        points.append(line[-1:])
    return np.concatenate(points) if points else np.zeros((0, 2))
