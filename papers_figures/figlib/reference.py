"""Reference values from the definitions (Python quadrature, independent of
skelconv's closed forms): kernels, and the field of a straight segment on
its perpendicular bisector (Hubert & Cani Prop. 4.1: the level giving
thickness τ)."""
import numpy as np

from .quadrature import gauss_legendre


def kernel(family, degree, s=None, R=None):
    """K(r) of docs/mathematics.md §1 as a vectorised function."""
    if family == "inverse":
        return lambda r: np.asarray(r, float) ** -degree
    if family == "cauchy":
        return lambda r: (1 + s * np.asarray(r, float) ** 2) ** (-degree / 2)
    if family == "compact":
        return lambda r: np.clip(1 - np.asarray(r, float) ** 2 / R ** 2, 0, None) ** (degree / 2)
    raise ValueError(family)


def segment_on_bisector(K, length, tau, weight=1.0, support=None, rtol=1e-13):
    """∫_{-l/2}^{l/2} weight·K(√(τ² + x²)) dx: the field of a segment of length l
    at distance τ from its middle. `support` = R for a compact kernel: the
    integral is then taken over |x| < √(R² − τ²) only, with x = ρ sin φ so that
    the integrand stays smooth at the support's edge."""
    half = 0.5 * length
    if support is None:
        value, _ = gauss_legendre(lambda x: K(np.sqrt(tau * tau + x * x)), -half, half, rtol=rtol)
        return weight * value
    if tau >= support:
        return 0.0
    rho = np.sqrt(support * support - tau * tau)
    phi_max = np.arcsin(min(1.0, half / rho))
    value, _ = gauss_legendre(
        lambda phi: K(np.sqrt(tau * tau + (rho * np.sin(phi)) ** 2)) * rho * np.cos(phi),
        -phi_max, phi_max, rtol=rtol)
    return weight * value


def j2(a, b, c):
    """J_2(a,b,c) = ∫_0^1 (a t² − 2 b t + c)^(-1) dt, its atan closed form (docs/mathematics.md §2), for ac − b² > 0."""
    root = np.sqrt(a * c - b * b)
    return (np.arctan((a - b) / root) + np.arctan(b / root)) / root


def polygon_edge_terms(vertices, points, family, s=None):
    """The edge terms of Hubert §6–7 for a planar polygon (counter-clockwise
    about +z, in the plane z = 0) at points (N×3), as printed in the paper:

        p⁴:   C = 1/(2z²)          Σ_m ((Q_{m+1} − Q_m) × (P̄ − Q_m))·n D^{p²}_m(P)
        c_s⁴: C = 1/(2(1 + s z²)) Σ_m ((Q_{m+1} − Q_m) × (P̄ − Q_m))·n D^{c_s²}_m(P)

    with D^{p²}_{[AB]}(P) = J_2(|AB|², AB·AP, |AP|²) and D^{c_s²} = J_2(s|AB|², s AB·AP, 1 + s|AP|²).
    Returns the list of the terms (each an array over the points)."""
    vertices = np.asarray(vertices, float)
    terms = []
    z = points[:, 2]
    for m in range(len(vertices)):
        A, B = vertices[m], vertices[(m + 1) % len(vertices)]
        AB, AP = B - A, points - A
        cross = AB[0] * AP[:, 1] - AB[1] * AP[:, 0]       # (AB × (P̄ − A))·z: P̄ − A has AP's x, y
        ab, bb, cc = AB @ AB, AP @ AB, np.einsum("ij,ij->i", AP, AP)
        if family == "inverse":
            terms.append(cross * j2(ab, bb, cc) / (2 * z * z))
        else:
            terms.append(cross * j2(s * ab, s * bb, 1 + s * cc) / (2 * (1 + s * z * z)))
    return terms
