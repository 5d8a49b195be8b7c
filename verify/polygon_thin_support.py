#!/usr/bin/env python3
"""Compact polygon, support radius R much smaller than the diameter D: the
error of `skelconv eval` near an edge, against the exact half-plane field.

Usage: verify/polygon_thin_support.py build/release/src/skelconv

The unit square (D = √2, edges of length 1) with a compact kernel of degree
i and radius R; points P within R of the middle of the edge y = 0, so the
support ball meets that edge alone and the polygon there is the half-plane
y ≥ 0. With P = (x, −e, z) (e > 0 outside) and ρ² = R² − z²:

    f    = B/R^i ∫_{max(e, −ρ)}^{ρ} (ρ² − u²)^((i+1)/2) du,   B = ∫_{−1}^{1} (1 − s²)^(i/2) ds
    ∂f/∂y = B/R^i (ρ² − e²)^((i+1)/2)   (|e| < ρ),   ∂f/∂x = 0
    ∂f/∂z = −(i + 1) z B/R^i ∫_{max(e, −ρ)}^{ρ} (ρ² − u²)^((i−1)/2) du

(the inner integral over the edge's direction done in closed form), each
integral by mpmath at 40 digits on [−1, 1] scaled to ρ (an integrand of
1e-40 would fall below mpmath's absolute tolerance). Prints the markdown
table of docs/verify_accuracy.md ("Compact polygons with a thin support").
"""
import random
import subprocess
import sys

import mpmath as mp

mp.mp.dps = 40


def reference(i, R, e, z):
    R, e, z = mp.mpf(R), mp.mpf(e), mp.mpf(z)
    B = mp.quad(lambda s: (1 - s * s) ** (mp.mpf(i) / 2), [-1, 1])
    rho2 = R * R - z * z
    rho = mp.sqrt(rho2)
    low = max(e, -rho) / rho
    if low >= 1:
        return (mp.mpf(0),) * 4
    f = B / R**i * rho ** (i + 2) * mp.quad(lambda s: (1 - s * s) ** (mp.mpf(i + 1) / 2), [low, 1])
    gz = -(i + 1) * z * B / R**i * rho**i * mp.quad(lambda s: (1 - s * s) ** (mp.mpf(i - 1) / 2), [low, 1])
    gy = B / R**i * (rho2 - e * e) ** (mp.mpf(i + 1) / 2) if abs(e) < rho else mp.mpf(0)
    return (f, mp.mpf(0), gy, gz)


def evaluate(skelconv, i, R, points):
    skeleton = ('{"primitives": [{"type": "polygon", "vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]], '
                '"kernel": {"family": "compact", "degree": %d, "R": %r}}]}' % (i, R))
    with open("polygon_thin_support.json", "w") as out:
        out.write(skeleton)
    text = "".join("%r %r %r\n" % p for p in points)
    run = subprocess.run([skelconv, "eval", "polygon_thin_support.json"], input=text, capture_output=True,
                         text=True, check=True)
    return [list(map(float, line.split())) for line in run.stdout.splitlines()]


def main():
    skelconv = sys.argv[1]
    random.seed(1)
    print("| i | R/D | f: max error / f_plane | ∇f: max error / (f_plane/R) "
          "| f: max relative error where f > 1e-3 f_plane | ∇f: max relative error where |∇f| > 1e-3 f_plane/R |")
    print("|---|---|---|---|---|---|")
    for i in (4, 6, 8, 10, 12):
        for R in (1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6):
            points, references = [], []
            for _ in range(80):
                e = R * random.uniform(-0.999, 0.999)
                z = R * random.uniform(0, 0.9) * random.choice((1, 0.1, 0.01))
                points.append((0.5 + R * random.uniform(-0.5, 0.5), -e, z))
                references.append(reference(i, R, e, z))
            values = evaluate(skelconv, i, R, points)
            f_plane = mp.pi * R * R * 2 / (i + 2)  # f over the whole plane, at z = 0
            g_scale = f_plane / R
            worst = [0, 0, 0, 0]
            for ref, got in zip(references, values):
                df = abs(got[0] - ref[0])
                dg = max(abs(got[k] - ref[k]) for k in (1, 2, 3))
                norm = mp.sqrt(sum(ref[k] ** 2 for k in (1, 2, 3)))
                worst[0] = max(worst[0], df / f_plane)
                worst[1] = max(worst[1], dg / g_scale)
                if ref[0] > 1e-3 * f_plane:
                    worst[2] = max(worst[2], df / ref[0])
                if norm > 1e-3 * g_scale:
                    worst[3] = max(worst[3], dg / norm)
            # R/D with D = √2, the square's diameter.
            print("| %d | %.1e | %.1e | %.1e | %.1e | %.1e |" % (i, R / 2**0.5, *(float(w) for w in worst)))
            sys.stdout.flush()


if __name__ == "__main__":
    main()
