"""Shared pieces of the Zanni et al. 2013 figures: the two formulations of a
variable-thickness segment (classical eq. 10, weight τ(t); SCALIS eq. 14,
radius τ(t)) as skelconv primitives, and the thickness of a classical
infinite segment in closed form (for levels and checks)."""
import numpy as np

# W_i = ∫ (1 + u²)^(-i/2) du over ℝ (docs/mathematics.md §4): W_2 = π, W_3 = 2, W_i = (i−3)/(i−2) W_{i−2}.
def w_integral(i):
    w = {2: np.pi, 3: 2.0}
    for k in range(4, i + 1):
        w[k] = (k - 3) / (k - 2) * w[k - 2]
    return w[i]


def classical_segment(a, b, tau0, tau1, family, degree, sigma):
    """Eq. (10): f = ∫ τ(s) K(|PΓ(s)|) ds with Zanni's K (σ-scaled kernels):
    Cauchy (1 + (d/σ)²)^(-i/2) is c_s^i with s = 1/σ²; compact is k_R^i with R = σ.
    The weight is τ(t) = τ0 + (τ1 − τ0) t."""
    kernel = {"family": family, "degree": degree}
    if family == "cauchy":
        kernel["s"] = 1.0 / sigma ** 2
    elif family == "compact":
        kernel["R"] = sigma
    else:
        raise ValueError("classical_segment: cauchy or compact")
    weight = [tau0, tau1 - tau0] if tau1 != tau0 else [tau0]
    return {"type": "segment", "a": list(a), "b": list(b), "weight": weight, "kernel": kernel}


def scalis_segment(a, b, tau0, tau1, family, degree, sigma, iso=1.0):
    return {"type": "scalis_segment", "a": list(a), "b": list(b), "radius": [tau0, tau1],
            "kernel": {"family": family, "degree": degree, "sigma": sigma}, "iso": iso}


def classical_cauchy_line(d, tau, degree, sigma):
    """Eq. (10) field of an infinite line of weight τ with the Cauchy kernel, at distance d:
    τ ∫ (1 + (d² + s²)/σ²)^(-i/2) ds = τ σ (1 + d²/σ²)^((1−i)/2) W_i."""
    return tau * sigma * (1 + d * d / sigma ** 2) ** ((1 - degree) / 2) * w_integral(degree)


def classical_cauchy_radius(tau, iso, degree, sigma):
    """The radius of the classical infinite line at level iso (NaN where the surface is empty)."""
    base = tau * sigma * w_integral(degree) / iso        # (1 + r²/σ²)^((i−1)/2) = base
    with np.errstate(invalid="ignore"):
        inner = np.asarray(base, float) ** (2.0 / (degree - 1)) - 1.0
        return np.where(inner >= 0, sigma * np.sqrt(np.clip(inner, 0, None)), np.nan)


def classical_cauchy_weight(radius, iso, degree, sigma):
    """The weight that gives a classical infinite line the radius `radius` at level iso
    (the inverse of classical_cauchy_radius): iso / (field of a line of weight 1 at that
    distance). Thin classical primitives get this weight, not τ, so that each exists on its
    own with the requested radius (a weight τ can fall below τ_min and draw nothing)."""
    return iso / classical_cauchy_line(radius, 1.0, degree, sigma)
