"""Reference integrals computed from the definitions, independently of
skelconv's closed forms: Gauss–Legendre rules refined until two successive
rules agree to a requested tolerance."""
import numpy as np


def gauss_legendre(g, a, b, rtol=1e-13, start=32, max_nodes=8192):
    """∫_a^b g(x) dx for a smooth (vectorised) g: the node count doubles until
    two rules agree to rtol; returns (value, estimated error)."""
    n = start
    previous = None
    while n <= max_nodes:
        x, w = np.polynomial.legendre.leggauss(n)
        value = 0.5 * (b - a) * np.dot(w, g(0.5 * (b - a) * x + 0.5 * (a + b)))
        if previous is not None and abs(value - previous) <= rtol * abs(value):
            return value, abs(value - previous)
        previous = value
        n *= 2
    raise ArithmeticError(f"gauss_legendre: no convergence to {rtol} with {max_nodes} nodes")


def over_real_line(g, rtol=1e-13):
    """∫_{-∞}^{∞} g(s) ds for g decaying at least like |s|^-2, by s = tan θ."""
    def h(theta):
        c = np.cos(theta)
        return g(np.tan(theta)) / (c * c)
    half_pi = 0.5 * np.pi
    return gauss_legendre(h, -half_pi, half_pi, rtol=rtol)
