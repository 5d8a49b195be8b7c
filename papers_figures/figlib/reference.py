"""Reference values from the definitions (Python quadrature, independent of
skelconv's closed forms): kernels, and the field of a straight segment on
its perpendicular bisector (Hubert & Cani Prop. 4.1: the level giving
thickness τ)."""
import numpy as np

from .quadrature import gauss_legendre


def kernel(family, degree, s=None, R=None):
    """K(r) of SPEC §1 as a vectorised function."""
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
