"""Measuring level sets: where a ray crosses f = level, the curvature of a
level curve, and the distance between two curves."""
import numpy as np

# Root finding along rays, in three steps that each cost one `skelconv eval`
# per round for all rays together:
#   1. a scan of SCAN_POINTS samples per ray keeps the first sign change from
#      the inside (the surface nearest the ray's origin);
#   2. regula falsi (Illinois variant) on g = ln(f / level), which is nearly
#      linear for the power-law and Cauchy fields (few rounds);
#   3. a bisection step whenever two rounds have not halved the bracket, so a
#      flat or non-smooth crossing (the edge of a compact support) still
#      converges at least like bisection.
# A ray is done when its bracket, or its last step, is below X_TOL·(1 + |t|)
# (regula falsi may keep one end of the bracket while the iterates converge);
# the loop stops when every ray is done, or after MAX_ROUNDS.
SCAN_POINTS = 16
X_TOL = 1e-15
MAX_ROUNDS = 200
LOG_CLIP = 745.0        # |ln| of the smallest/largest doubles: f = 0 and f = ∞ map to ∓LOG_CLIP


def _log_ratio(f, level):
    with np.errstate(divide="ignore", invalid="ignore"):
        g = np.log(np.where(f > 0, f, 0.0) / level)
    return np.clip(np.nan_to_num(g, nan=-LOG_CLIP, neginf=-LOG_CLIP, posinf=LOG_CLIP), -LOG_CLIP, LOG_CLIP)


def crossing(field, origins, directions, level, t_inside, t_outside, x_tol=X_TOL):
    """For each ray origin + t·direction, the first t from t_inside towards
    t_outside where f drops below `level` (> 0; one for all rays, or one per ray).

    f(t_inside) ≥ level > f(t_outside) is required for every ray; a ray that
    does not bracket the level gets NaN (the caller decides what that means:
    e.g. no surface there). x_tol: the relative accuracy wanted in t."""
    origins = np.atleast_2d(np.asarray(origins, float))
    directions = np.atleast_2d(np.asarray(directions, float))
    n = max(len(origins), len(directions))
    origins = np.broadcast_to(origins, (n, 3))
    directions = np.broadcast_to(directions, (n, 3))

    level = np.broadcast_to(np.asarray(level, float), (n,))     # one level per ray, or one for all

    def g(t):
        return _log_ratio(field.f(origins + t[:, None] * directions), level)

    start = np.broadcast_to(np.asarray(t_inside, float), (n,))
    stop = np.broadcast_to(np.asarray(t_outside, float), (n,))
    # 1. scan: samples s_0 = start … s_K = stop on every ray, in one evaluation
    fractions = np.linspace(0.0, 1.0, SCAN_POINTS + 1)
    samples = start[:, None] + fractions[None, :] * (stop - start)[:, None]
    values = _log_ratio(field.f((origins[:, None, :] + samples[:, :, None] * directions[:, None, :]).reshape(-1, 3))
                        .reshape(n, -1), level[:, None])
    bracketed = (values[:, 0] >= 0) & (values[:, -1] < 0)
    first_out = np.argmax(values < 0, axis=1)
    first_out = np.where(bracketed, first_out, 1)
    rows = np.arange(n)
    lo, hi = samples[rows, first_out - 1], samples[rows, first_out]
    g_lo, g_hi = values[rows, first_out - 1], values[rows, first_out]
    widths = [np.abs(hi - lo)] * 2
    last = np.zeros(n, dtype=int)       # which end moved last: 1 inside, −1 outside
    best = np.full(n, np.inf)           # the last iterate
    step = np.full(n, np.inf)           # how far it moved
    for _ in range(MAX_ROUNDS):
        width = np.abs(hi - lo)
        tol = x_tol * (1 + np.abs(lo))
        done = ~bracketed | (width <= tol) | (step <= tol)
        if np.all(done):
            break
        with np.errstate(divide="ignore", invalid="ignore"):
            secant = hi - g_hi * (hi - lo) / (g_hi - g_lo)
        bisect = (width > 0.5 * widths[-2]) | ~np.isfinite(secant)
        t = np.where(bisect, 0.5 * (lo + hi), secant)
        t = np.clip(t, np.minimum(lo, hi), np.maximum(lo, hi))
        g_t = g(t)
        step = np.where(done, 0.0, np.abs(t - best))
        best = np.where(done, best, t)
        inside = g_t >= 0
        # Illinois: when the same end moves twice in a row, halve the value kept at the other
        g_hi = np.where(inside & (last == 1), 0.5 * g_hi, g_hi)
        g_lo = np.where(~inside & (last == -1), 0.5 * g_lo, g_lo)
        g_lo = np.where(inside, g_t, g_lo)
        g_hi = np.where(inside, g_hi, g_t)
        lo = np.where(inside, t, lo)
        hi = np.where(inside, hi, t)
        last = np.where(inside, 1, -1)
        widths.append(width)
    best = np.where(np.abs(hi - lo) <= x_tol * (1 + np.abs(lo)), 0.5 * (lo + hi), best)
    return np.where(bracketed, best, np.nan)


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
