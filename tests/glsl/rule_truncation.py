#!/usr/bin/python3
"""The truncation error of the GLSL target's Gauss-Legendre rule
(codegen/glsl_rule.cpp, skelconv_segment_rule) in double, against the
graded reference quadrature of check_glsl_numeric.py: what justifies its
node count. A measurement, not a test.

    rule_truncation.py [--nodes 8,12,16,20,24,32] [--points 20]

For each least distance h (in |AB|: 0.1, 0.01, 1e-3, 1e-4), the worst relative
error of F and grad F over SCALIS segments (inverse and Cauchy, degrees 2, 4,
6, 8, 10) with P beside AB, beyond an end and far (check_glsl_numeric.py's
regions, its distances scaled down to h), for each node count per side.
The rule here is a transliteration of the GLSL one (same map, same
choices), in double so that only truncation is left.
"""
import argparse
import math
import pathlib
import sys

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import check_glsl_numeric as numeric  # noqa: E402


def rule(family, degree, row, nodes):
    """skelconv_segment_rule for a SCALIS segment, in double."""
    a, b, p, tau0, tau1, sigma = row[0:3], row[3:6], row[6:9], row[9], row[10], row[11]
    ab, ap = b - a, p - a
    gamma = sigma * sigma if family == "cauchy" else 0.0
    dtau = tau1 - tau0
    qa = ab @ ab + gamma * dtau * dtau
    qb = ab @ ap - gamma * tau0 * dtau
    disc = np.cross(ab, ap) @ np.cross(ab, ap) + gamma * (tau0 * ab + dtau * ap) @ (tau0 * ab + dtau * ap)
    centre = qb / qa
    c = min(1.0, max(0.0, centre))
    h = max(math.hypot(centre - c, math.sqrt(disc) / qa), 1e-20)
    x, w = np.polynomial.legendre.leggauss(nodes)
    f, g = 0.0, np.zeros(3)
    for side in (-1, 1):
        span = c if side < 0 else 1 - c
        if span <= 0:
            continue
        linear = span <= h
        u_max = span if linear else math.asinh(span / h)
        u = 0.5 * u_max * (1 + x)
        s = u if linear else h * np.sinh(u)
        weight = 0.5 * u_max * (1.0 if linear else h * np.cosh(u)) * w
        t = c + side * s
        d = p[None, :] - (a[None, :] + t[:, None] * ab[None, :])
        tau = tau0 * (1 - t) + tau1 * t
        q = np.einsum("ij,ij->i", d, d) + gamma * tau * tau
        v = sigma ** degree * weight * tau ** (degree - 1)
        f += np.sum(v * q ** (-degree / 2))
        g += -degree * np.sum((v * q ** (-degree / 2 - 1))[:, None] * d, axis=0)
    length = math.sqrt(ab @ ab)
    return f * length, g * length


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--nodes", default="8,12,16,20,24,32")
    ap.add_argument("--points", type=int, default=20)
    args = ap.parse_args()
    counts = [int(n) for n in args.nodes.split(",")]
    print("least distance h / |AB|, then the worst relative error of F and grad F for", counts, "nodes per side")
    for h in (0.1, 0.01, 1e-3, 1e-4):
        numeric.DISTANCES["beside"] = numeric.DISTANCES["beyond"] = (h, 3)
        rng = np.random.default_rng(1)
        cases = [(family, degree, row) for family in ("inverse", "cauchy") for degree in (2, 4, 6, 8, 10)
                 for region in ("beside", "beyond", "far")
                 for row in numeric.draw_scalis(rng, family, args.points, region)]
        worst = []
        for nodes in counts:
            e = 0.0
            for family, degree, row in cases:
                f, g = numeric.scalis_reference(family, degree, row)
                rf, rg = rule(family, degree, row, nodes)
                e = max(e, abs(rf - f) / abs(f), np.linalg.norm(rg - g) / np.linalg.norm(g))
            worst.append(f"{e:.1e}")
        print(f"  h >= {h:g}: " + "  ".join(worst))


if __name__ == "__main__":
    main()
