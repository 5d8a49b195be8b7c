// Implementation of scalis_triangle_quadrature.hpp (the method is described
// there).
#include "scalis_triangle_quadrature.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <vector>

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "skelconv/detail/integer_power.hpp"
#include "skelconv/kernels/kernel_list.hpp"
#include "../detail/infinity.hpp"

namespace skelconv::detail {
namespace {

// Kronrod 31 points; the even-indexed abscissae are those of Gauss 15.
using Kronrod = boost::math::quadrature::gauss_kronrod<double, 31>;
using Gauss = boost::math::quadrature::gauss<double, 15>;

/// Most panels per adaptive integral. A smooth ray needs 1–4, a ray through
/// a near-singular peak ~log2(ρ_max / width); beyond these the integral is
/// declared unconverged (and the caller throws) rather than run on.
constexpr int max_inner_panels = 200;
constexpr int max_outer_panels = 400;

template <std::size_t N>
using Values = std::array<double, N>;

template <std::size_t N>
struct Panel {
  int piece;  ///< which integrand (outer level: which sub-triangle)
  double a, b;
  Values<N> value;
  Values<N> error;        ///< |K31 − G15|: this level's discretisation error
  Values<N> inner_error;  ///< the integrand values' own errors, integrated
};

template <std::size_t N>
struct Adaptive {
  Values<N> value{}, error{};
  bool converged = false;
};

/// An integral that is exactly zero (a ray outside the compact support).
template <std::size_t N>
Adaptive<N> exact_zero() {
  Adaptive<N> zero;
  zero.converged = true;
  return zero;
}

/// Gauss–Kronrod 15/31 on [a, b]. integrand(piece, x, value, error) gives the
/// integrand at x and the error of that value (non-zero for an inner
/// integral); the panel's error is |K31 − G15| plus the Kronrod-weighted
/// inner errors.
template <std::size_t N, class Integrand>
Panel<N> gauss_kronrod_panel(int piece, double a, double b, Integrand& integrand) {
  const auto& x = Kronrod::abscissa();
  const auto& wk = Kronrod::weights();
  const auto& wg = Gauss::weights();
  const double half = (b - a) / 2;
  const double mid = (a + b) / 2;
  Values<N> kronrod{}, gauss{}, inner_error{};
  Values<N> value, error;
  auto add = [&](double node, double weight_kronrod, double weight_gauss) {
    integrand(piece, mid + half * node, value, error);
    for (std::size_t c = 0; c < N; ++c) {
      kronrod[c] += weight_kronrod * value[c];
      gauss[c] += weight_gauss * value[c];
      inner_error[c] += weight_kronrod * error[c];
    }
  };
  add(0.0, wk[0], wg[0]);
  for (std::size_t j = 1; j < x.size(); ++j) {
    const double weight_gauss = j % 2 == 0 ? wg[j / 2] : 0.0;
    add(x[j], wk[j], weight_gauss);
    add(-x[j], wk[j], weight_gauss);
  }
  Panel<N> panel{piece, a, b, {}, {}, {}};
  for (std::size_t c = 0; c < N; ++c) {
    panel.value[c] = half * kronrod[c];
    panel.error[c] = std::abs(half) * std::abs(kronrod[c] - gauss[c]);
    panel.inner_error[c] = std::abs(half) * inner_error[c];
  }
  return panel;
}

/// Global adaptive quadrature: starts with one panel per piece [a, b], then
/// bisects the panel with the largest error relative to its component's
/// allowance until every component's summed discretisation error is within
/// allowance(totals) (absolute allowances; infinity: no demand) or within
/// the summed inner errors (bisecting cannot remove those: refining below
/// them gains nothing). The result's error is the sum of both.
struct Interval {
  double a, b;
};

template <std::size_t N, class Integrand, class Allowance>
Adaptive<N> integrate_adaptive(std::span<const Interval> pieces, Integrand& integrand, Allowance& allowance,
                               int max_panels, const bool* abort = nullptr) {
  Adaptive<N> result;
  if (pieces.empty()) {  // nothing to integrate: exactly 0 (and no panel to bisect below)
    result.converged = true;
    return result;
  }
  std::vector<Panel<N>> panels;
  panels.reserve(pieces.size() + 16);
  for (std::size_t k = 0; k < pieces.size(); ++k)
    panels.push_back(gauss_kronrod_panel<N>(int(k), pieces[k].a, pieces[k].b, integrand));
  for (;;) {
    result.value = {};
    Values<N> discretisation{}, inner{};
    for (const auto& p : panels)
      for (std::size_t c = 0; c < N; ++c) {
        result.value[c] += p.value[c];
        discretisation[c] += p.error[c];
        inner[c] += p.inner_error[c];
      }
    for (std::size_t c = 0; c < N; ++c) result.error[c] = discretisation[c] + inner[c];
    const Values<N> allowed = allowance(result.value);
    bool ok = true;
    for (std::size_t c = 0; c < N; ++c) ok = ok && discretisation[c] <= std::max(allowed[c], inner[c]);
    if (ok) {
      result.converged = true;
      return result;
    }
    if (int(panels.size()) >= max_panels || (abort != nullptr && *abort)) return result;
    std::size_t worst = 0;
    double worst_ratio = -1.0;
    for (std::size_t k = 0; k < panels.size(); ++k) {
      double ratio = 0.0;
      for (std::size_t c = 0; c < N; ++c) {
        if (panels[k].error[c] == 0.0) continue;
        ratio = std::max(ratio, allowed[c] > 0.0 ? panels[k].error[c] / allowed[c] : infinity);
      }
      if (ratio > worst_ratio) {
        worst_ratio = ratio;
        worst = k;
      }
    }
    const Panel<N> split = panels[worst];
    const double mid = (split.a + split.b) / 2;
    if (!(split.a < mid && mid < split.b)) return result;  // cannot bisect further
    panels[worst] = gauss_kronrod_panel<N>(split.piece, split.a, mid, integrand);
    panels.push_back(gauss_kronrod_panel<N>(split.piece, mid, split.b, integrand));
  }
}

using Vec2 = Eigen::Vector2d;

double cross(const Vec2& u, const Vec2& v) { return u.x() * v.y() - u.y() * v.x(); }

/// The point of the CCW triangle v nearest to p, and where it lies.
struct Nearest {
  Vec2 point;
  double tau;           ///< τ there (exact at a vertex, interpolated along an edge)
  int vertex = -1;      ///< k when the point is vertex k
  int edge = -1;        ///< k when the point is inside edge k (from vertex k to k + 1)
};

/// Ericson, Real-Time Collision Detection §5.1.5 (Voronoi regions).
Nearest nearest_point(const std::array<Vec2, 3>& v, const std::array<double, 3>& tau, const Vec2& p,
                      const Vec2& gradient_tau) {
  const Vec2 ab = v[1] - v[0], ac = v[2] - v[0];
  const Vec2 ap = p - v[0];
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return {v[0], tau[0], 0, -1};
  const Vec2 bp = p - v[1];
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return {v[1], tau[1], 1, -1};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double t = d1 / (d1 - d3);
    return {v[0] + t * ab, tau[0] + t * (tau[1] - tau[0]), -1, 0};
  }
  const Vec2 cp = p - v[2];
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return {v[2], tau[2], 2, -1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double t = d2 / (d2 - d6);  // from vertex 0 towards vertex 2: edge 2 runs 2 → 0
    return {v[0] + t * ac, tau[0] + t * (tau[2] - tau[0]), -1, 2};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {v[1] + t * (v[2] - v[1]), tau[1] + t * (tau[2] - tau[1]), -1, 1};
  }
  // Inside: τ from the plane of the radii.
  return {p, std::max(0.0, tau[0] + gradient_tau.dot(p - v[0])), -1, -1};
}

/// One fan triangle (O, A, B) in the angular variable v (see the header).
struct FanTriangle {
  Vec2 tangent;      ///< unit vector from A to B
  Vec2 towards_edge; ///< unit normal from O towards the line AB
  double h;          ///< distance from O to the line AB
  double sA, sB;     ///< arc lengths of A and B from the foot of the perpendicular
  double tauA, tauB;
};

/// Everything a ray needs, in the scaled local frame (see the header).
struct Setup {
  /// The kernel vanishes where q = σ²τ² − d² ≤ 0 (compact): each ray is
  /// integrated over its support only (radial_integral_compact).
  bool finite_support;
  /// Otherwise the integrand is τ^(i−2) D^(−i/2), D = d² + c σ²τ², with the
  /// family's c (scalis_radius_term: 0 inverse, 1 Cauchy).
  double radius_term;
  int degree;
  double sigma2;
  Vec2 O;          ///< apex
  Vec2 offset;     ///< O − P̄
  double w2;       ///< |P − O|²
  double tauO;
  bool with_gradient;
  long evaluations = 0;
};

/// What one ray's integral may be off by: `tolerance` relative to each of
/// its three parts (the gradient parts only when they are asked for).
Values<3> ray_allowance(const Setup& s, const Values<3>& total, double tolerance) {
  return Values<3>{tolerance * std::abs(total[0]), s.with_gradient ? tolerance * std::abs(total[1]) : infinity,
                   s.with_gradient ? tolerance * std::abs(total[2]) : infinity};
}

/// The radial integral of a kernel of infinite support (inverse, Cauchy):
/// the integrand τ^(i−2) D^(−i/2) ρ with D(ρ) = |P − Q|² + c σ²τ² =
/// D2 ρ² + 2 D1 ρ + D0 (c = s.radius_term) peaks where D is smallest, over
/// a width of the modulus of D's complex zeros; ρ = scale · sinh u spreads
/// that peak evenly in u.
Adaptive<3> radial_integral_infinite(Setup& s, double b, double rho_max, double a, double tolerance) {
  const int i = s.degree;
  const bool with_gradient = s.with_gradient;
  const double D2 = 1.0 + s.radius_term * s.sigma2 * a * a;
  const double D0 = s.w2 + s.radius_term * s.sigma2 * s.tauO * s.tauO;
  const double scale = std::sqrt(D0 / D2);
  const Interval piece{0.0, std::asinh(rho_max / scale)};
  auto integrand = [&](int, double u, Values<3>& value, Values<3>& error) {
    ++s.evaluations;
    error = {};
    const double rho = scale * std::sinh(u);
    const double jacobian = rho * scale * std::cosh(u);  // ρ dρ/du
    const double tau = s.tauO + a * rho;
    if (!(tau > 0.0)) {
      value = {};
      return;
    }
    const double r2 = s.w2 + rho * (rho + 2 * b);
    const double D = r2 + s.radius_term * s.sigma2 * tau * tau;
    // τ^(i−2) D^(−i/2) as (τ/√D)^(i−2) / D: no under- or overflow of D^(i/2).
    const double f = integer_power(tau / std::sqrt(D), i - 2) / D * jacobian;
    value[0] = f;
    if (with_gradient) {
      value[1] = -i * f / D;
      value[2] = value[1] * rho;
    } else {
      value[1] = value[2] = 0.0;
    }
  };
  auto allowance = [&](const Values<3>& total) { return ray_allowance(s, total, tolerance); };
  return integrate_adaptive<3>(std::span(&piece, 1), integrand, allowance, max_inner_panels);
}

/// The part [lo, hi] of [0, ρ_max] where a ray of the compact kernel is
/// inside the support q(ρ) = A ρ² + 2 B ρ + C > 0 (q = σ²τ² − d²), and which
/// of its ends are roots of q (where the integrand vanishes like √q).
struct SupportOnRay {
  double lo = 0.0, hi = 0.0;
  bool lo_root = false, hi_root = false;
};

/// SupportOnRay of the ray, or nullopt where q ≤ 0 on all of it.
std::optional<SupportOnRay> support_on_ray(const Setup& s, double b, double rho_max, double a) {
  const double A = s.sigma2 * a * a - 1.0;
  const double B = s.sigma2 * s.tauO * a - b;
  const double C = s.sigma2 * s.tauO * s.tauO - s.w2;
  SupportOnRay support{0.0, rho_max, false, false};
  auto keep_above = [&](double root) {  // q > 0 for ρ > root
    if (root > support.lo) {
      support.lo = root;
      support.lo_root = true;
    }
  };
  auto keep_below = [&](double root) {  // q > 0 for ρ < root
    if (root < support.hi) {
      support.hi = root;
      support.hi_root = true;
    }
  };
  const double disc = B * B - A * C;
  if (A == 0.0) {
    if (B == 0.0) {
      if (!(C > 0.0)) return std::nullopt;
    } else if (B > 0.0) {
      keep_above(-C / (2 * B));
    } else {
      keep_below(-C / (2 * B));
    }
  } else if (!(disc > 0.0)) {
    if (A < 0.0) return std::nullopt;  // q ≤ 0 everywhere (A > 0: q ≥ 0 everywhere)
  } else {
    const double q = -(B + std::copysign(std::sqrt(disc), B));
    double r1 = C / q, r2 = q / A;
    if (r2 < r1) std::swap(r1, r2);
    if (A < 0.0) {
      keep_above(r1);
      keep_below(r2);
    } else if (r1 > 0.0) {
      // q > 0 outside [r1, r2]: on [0, ρ_max] only one side can occur (the
      // tip τ = 0, where q < 0, lies between the roots and outside (0, ρ_max)).
      keep_below(r1);
    } else {
      keep_above(r2);
    }
  }
  if (!(support.lo < support.hi)) return std::nullopt;
  return support;
}

/// The radial integral of the compact kernel over the ray's support, in a
/// variable t ∈ [0, 1] whose dρ/dt vanishes at the ends that are roots of q
/// (q ~ t² there, so the √q ends become smooth). The integrand is
/// σ^(−i) (q/τ²)^(i/2) / τ² (its σ^(−i) left to the caller); values 3–5
/// bound the rounding noise of values 0–2 (below), which counts as error.
Adaptive<3> radial_integral_compact(Setup& s, double b, double rho_max, double a, double tolerance) {
  const std::optional<SupportOnRay> support = support_on_ray(s, b, rho_max, a);
  if (!support) return exact_zero<3>();
  const int i = s.degree;
  const bool with_gradient = s.with_gradient;
  const double lo = support->lo, hi = support->hi, width = hi - lo;
  auto integrand = [&](int, double t, Values<6>& value, Values<6>& error) {
    ++s.evaluations;
    error = {};
    double rho, drho;
    if (support->lo_root && support->hi_root) {
      rho = lo + width * t * t * (3 - 2 * t);
      drho = width * 6 * t * (1 - t);
    } else if (support->lo_root) {
      rho = lo + width * t * t;
      drho = 2 * width * t;
    } else if (support->hi_root) {
      rho = hi - width * (1 - t) * (1 - t);
      drho = 2 * width * (1 - t);
    } else {
      rho = lo + width * t;
      drho = width;
    }
    const double tau = s.tauO + a * rho;
    const double r2 = s.w2 + rho * (rho + 2 * b);
    const double sigma_tau = std::sqrt(s.sigma2) * tau, r = std::sqrt(r2);
    const double q = (sigma_tau - r) * (sigma_tau + r);
    if (!(tau > 0.0) || !(q > 0.0)) {
      value = {};
      return;
    }
    // K/τ² = σ^(−i) (q/τ²)^(i/2) / τ², (K'/d)/τ⁴ = −i σ^(−i) (q/τ²)^(i/2−1) / τ⁴.
    const double xi = q / (tau * tau);
    const double xi_grad_power = integer_power(xi, (i - 2) / 2) * (i % 2 == 1 ? std::sqrt(xi) : 1.0);
    const double inv_tau2 = 1.0 / (tau * tau);
    const double jacobian = rho * drho;
    value[0] = xi_grad_power * xi * inv_tau2 * jacobian;
    if (with_gradient) {
      value[1] = -i * xi_grad_power * inv_tau2 * inv_tau2 * jacobian;
      value[2] = value[1] * rho;
    } else {
      value[1] = value[2] = 0.0;
    }
    // Rounding noise: q is a difference, known only to δq ≈ 4ε (στ + r)²
    // (the inputs' rounding shifts it by as much), so a value ∝ q^k carries
    // a relative error ~k δq / q (at most 1) that no quadrature removes. On a
    // ray that only grazes the support q stays small, and its integral cannot
    // reach a relative `tolerance` of its own (it matters little to F).
    const double dq = 4 * std::numeric_limits<double>::epsilon() * (sigma_tau + r) * (sigma_tau + r);
    value[3] = std::abs(value[0]) * std::min(1.0, 0.5 * i * dq / q);
    value[4] = std::abs(value[1]) * std::min(1.0, 0.5 * (i - 2) * dq / q);
    value[5] = std::abs(value[2]) * std::min(1.0, 0.5 * (i - 2) * dq / q);
  };
  // Each part within `tolerance` of itself, or within twice its noise.
  auto allowance_with_noise = [&](const Values<6>& total) {
    const Values<3> relative = ray_allowance(s, Values<3>{total[0], total[1], total[2]}, tolerance);
    return Values<6>{std::max(relative[0], 2 * total[3]), std::max(relative[1], 2 * total[4]),
                     std::max(relative[2], 2 * total[5]), infinity, infinity, infinity};
  };
  const Interval piece{0.0, 1.0};
  const Adaptive<6> ray = integrate_adaptive<6>(std::span(&piece, 1), integrand, allowance_with_noise,
                                                max_inner_panels);
  Adaptive<3> result;
  result.converged = ray.converged;
  for (int c = 0; c < 3; ++c) {
    result.value[c] = ray.value[c];
    result.error[c] = ray.error[c] + ray.value[c + 3];  // the noise is an error too
  }
  return result;
}

/// The inner (radial) integral along the ray from O in direction e, of
/// length rho_max, with τ = tauO + a ρ. Values: ∫ K/τ² ρ dρ, ∫ (K'/d)/τ⁴ ρ dρ
/// and ∫ (K'/d)/τ⁴ ρ² dρ, without the constant factor σ^(±i).
Adaptive<3> radial_integral(Setup& s, const Vec2& e, double rho_max, double a, double tolerance) {
  const double b = s.offset.dot(e);  // d² = w² + ρ (ρ + 2b) along the ray
  return s.finite_support ? radial_integral_compact(s, b, rho_max, a, tolerance)
                          : radial_integral_infinite(s, b, rho_max, a, tolerance);
}

/// Real roots of c2 x² + 2 c1 x + c0 = 0 (none when c2 = c1 = 0).
void add_quadratic_roots(double c2, double c1, double c0, std::vector<double>& roots) {
  if (c2 == 0.0) {
    if (c1 != 0.0) roots.push_back(-c0 / (2 * c1));
    return;
  }
  const double disc = c1 * c1 - c2 * c0;
  if (disc < 0.0) return;
  const double q = -(c1 + std::copysign(std::sqrt(disc), c1));
  roots.push_back(q / c2);
  if (q != 0.0) roots.push_back(c0 / q);
}

/// Compact kernel: the values of a fan's angular variable v (s = h sinh v)
/// where the radial integral is not smooth (it behaves like a power
/// |v − v_c|^((i+2)/2) or so there), appended to `cuts` when inside the
/// fan's range: where the support's boundary (the conic σ²τ(Q)² = |P − Q|²)
/// crosses the far edge, and where a ray is tangent to it (the support on
/// the ray shrinks to nothing). Putting them at panel ends keeps
/// Gauss–Kronrod's error estimate reliable.
void compact_breakpoints(const Setup& s, const FanTriangle& fan, const Vec2& foot, double z, const Vec2& gradient_tau,
                         std::vector<double>& cuts) {
  const double v_lo = cuts[0], v_hi = cuts[1];
  std::vector<double> x;  // x = sinh v = arc / h
  // 1. On the far edge E(x) = F + h x t̂: τ = α0 + α1 h x, and
  //    σ²τ² − z² − |E − P̄|² is a quadratic in x.
  const Vec2 F = s.O + fan.h * fan.towards_edge;
  const Vec2 d = F - foot;
  const double slope = (fan.tauB - fan.tauA) / (fan.sB - fan.sA);  // dτ/ds
  const double a0 = fan.tauA - slope * fan.sA, a1 = slope * fan.h;
  add_quadratic_roots(s.sigma2 * a1 * a1 - fan.h * fan.h, s.sigma2 * a0 * a1 - fan.h * fan.tangent.dot(d),
                      s.sigma2 * a0 * a0 - z * z - d.squaredNorm(), x);
  // 2. Tangent rays: the discriminant of q(ρ) along e is the quadratic form
  //    eᵀ M e, M = u uᵀ − C σ² g gᵀ + C I with u = σ²τ_O g − (O − P̄),
  //    C = σ²τ_O² − w², g = ∇τ; along e ∝ n̂ + x t̂ a quadratic in x.
  const Vec2 u = s.sigma2 * s.tauO * gradient_tau - s.offset;
  const double C = s.sigma2 * s.tauO * s.tauO - s.w2;
  auto form = [&](const Vec2& e1, const Vec2& e2) {
    return u.dot(e1) * u.dot(e2) - C * s.sigma2 * gradient_tau.dot(e1) * gradient_tau.dot(e2) + C * e1.dot(e2);
  };
  add_quadratic_roots(form(fan.tangent, fan.tangent), form(fan.towards_edge, fan.tangent),
                      form(fan.towards_edge, fan.towards_edge), x);
  for (double root : x) {
    const double v = std::asinh(root);
    if (v > v_lo && v < v_hi) cuts.push_back(v);
  }
}

/// Compact kernel, P = O in the plane with τ(O) = 0: the integral diverges
/// iff σ |∇τ · e| > 1 for a direction e into one of the fan triangles.
bool compact_tip_diverges(const std::vector<FanTriangle>& fans, const Vec2& O, const std::array<Vec2, 3>& v,
                          const std::vector<int>& fan_edges, const Vec2& gradient_tau, double sigma) {
  double largest = 0.0;
  const double g = gradient_tau.norm();
  for (std::size_t k = 0; k < fans.size(); ++k) {
    const Vec2 ea = (v[fan_edges[k]] - O).normalized();
    const Vec2 eb = (v[(fan_edges[k] + 1) % 3] - O).normalized();
    largest = std::max({largest, std::abs(gradient_tau.dot(ea)), std::abs(gradient_tau.dot(eb))});
    if (g > 0.0) {
      const Vec2 gh = gradient_tau / g;
      for (const Vec2& d : {gh, Vec2(-gh)})
        if (cross(ea, d) >= 0.0 && cross(d, eb) >= 0.0) largest = g;
    }
  }
  return sigma * largest > 1.0;
}

/// The triangle and P in the local frame: origin V0, x along V0V1, z along
/// the normal (the vertices are then counter-clockwise), lengths scaled by
/// 2^−exponent so that the largest radius is in [1/2, 1) (exact; F is scale
/// invariant).
struct LocalTriangle {
  int exponent = 0;
  Vec3 e1, e2, normal;       ///< the frame's axes, in world coordinates
  std::array<Vec2, 3> v;     ///< the vertices (v[0] = 0, v[1] on the x axis)
  std::array<double, 3> tau; ///< the radii
  Vec2 foot;                 ///< P̄, P's projection on the plane
  double z = 0.0;            ///< P's height above the plane
  Vec2 gradient_tau;         ///< ∇τ in the plane (for τ inside T and the compact tip test)
};

LocalTriangle local_triangle(const std::array<Vec3, 3>& vertices, const std::array<double, 3>& radii, const Vec3& p) {
  LocalTriangle t;
  (void)std::frexp(std::max({radii[0], radii[1], radii[2]}), &t.exponent);
  auto scaled = [&](const Vec3& x) { return Vec3(std::ldexp(x.x(), -t.exponent), std::ldexp(x.y(), -t.exponent),
                                                 std::ldexp(x.z(), -t.exponent)); };
  const Vec3 origin = scaled(vertices[0]);
  t.e1 = (scaled(vertices[1]) - origin).normalized();
  t.normal = (scaled(vertices[1]) - origin).cross(scaled(vertices[2]) - origin).normalized();
  t.e2 = t.normal.cross(t.e1);
  auto local = [&](const Vec3& x) {
    const Vec3 d = scaled(x) - origin;
    return Vec3(d.dot(t.e1), d.dot(t.e2), d.dot(t.normal));
  };
  for (int k = 0; k < 3; ++k) {
    const Vec3 q = local(vertices[k]);
    t.v[k] = {q.x(), q.y()};
    t.tau[k] = std::ldexp(radii[k], -t.exponent);
  }
  t.v[0] = {0.0, 0.0};
  t.v[1].y() = 0.0;
  const Vec3 pl = local(p);
  t.foot = Vec2(pl.x(), pl.y());
  t.z = pl.z();
  const double gx = (t.tau[1] - t.tau[0]) / t.v[1].x();
  t.gradient_tau = Vec2(gx, (t.tau[2] - t.tau[0] - gx * t.v[2].x()) / t.v[2].y());
  return t;
}

/// The fan triangles (O, V_k, V_k+1) with a non-empty interior, and the
/// edge k of each.
struct Fans {
  std::vector<FanTriangle> triangles;
  std::vector<int> edges;
};

Fans fan_triangles(const LocalTriangle& t, const Nearest& nearest, const Vec2& O) {
  Fans fans;
  for (int k = 0; k < 3; ++k) {
    const int next = (k + 1) % 3;
    if (nearest.edge == k || nearest.vertex == k || nearest.vertex == next) continue;
    const Vec2 tangent = (t.v[next] - t.v[k]).normalized();
    const Vec2 left(-tangent.y(), tangent.x());
    const double h = (O - t.v[k]).dot(left);
    if (!(h > 0.0)) continue;
    fans.triangles.push_back(
        {tangent, -left, h, (t.v[k] - O).dot(tangent), (t.v[next] - O).dot(tangent), t.tau[k], t.tau[next]});
    fans.edges.push_back(k);
  }
  return fans;
}

/// Whether F diverges at P = O (w = 0; see the header): everywhere in T
/// for a kernel singular on the skeleton, at a point of radius 0 for one
/// singular at zero radius, and for the compact kernel at a radius-0 tip
/// steep enough (compact_tip_diverges).
bool diverges_at_apex(kernels::ScalisSingularity singularity, const Setup& s, const Fans& fans,
                      const LocalTriangle& t, double sigma) {
  if (singularity == kernels::ScalisSingularity::on_segment) return true;
  if (s.tauO != 0.0) return false;
  return singularity == kernels::ScalisSingularity::at_zero_radius ||
         (s.finite_support && compact_tip_diverges(fans.triangles, s.O, t.v, fans.edges, t.gradient_tau, sigma));
}

/// The outer pieces: each fan's v range, for the compact kernel cut at its
/// breakpoints (compact_breakpoints), where the radial integral is not
/// smooth in v. False when a cut is not a number (coordinates whose products
/// overflow, e.g. a vertex 1e300 away): that would drop its piece silently
/// and give a wrong 0, so the caller reports the evaluation as failed.
bool outer_pieces(const Setup& s, const Fans& fans, const LocalTriangle& t, std::vector<Interval>& pieces,
                  std::vector<int>& piece_fan) {
  for (std::size_t k = 0; k < fans.triangles.size(); ++k) {
    const FanTriangle& fan = fans.triangles[k];
    std::vector<double> cuts{std::asinh(fan.sA / fan.h), std::asinh(fan.sB / fan.h)};
    if (s.finite_support) compact_breakpoints(s, fan, t.foot, t.z, t.gradient_tau, cuts);
    if (!std::all_of(cuts.begin(), cuts.end(), [](double c) { return std::isfinite(c); })) return false;
    std::sort(cuts.begin(), cuts.end());
    for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
      if (!(cuts[c] < cuts[c + 1])) continue;
      pieces.push_back({cuts[c], cuts[c + 1]});
      piece_fan.push_back(int(k));
    }
  }
  return true;
}

/// ∇F in the local frame, up to the constant factor, from the outer values
/// t = (∫ F_ray, ∫ G0_ray, ∫ G1_ray e (2 components), ∫ |G1_ray|):
/// ∇F = (P̄ − O, z) G0 − (G1x, G1y, 0).
struct OuterGradient {
  Vec2 offset;   ///< O − P̄
  double z;
  double lever;  ///< |(P̄ − O, z)|

  Vec3 of(const Values<5>& t) const {
    return Vec3(-offset.x() * t[1] - t[2], -offset.y() * t[1] - t[3], z * t[1]);
  }
  /// The sum of the magnitudes of ∇F's parts, |(P̄ − O, z)| |G0| and
  /// ∫ |G1| dφ, however they cancel in ∇F, floored (the header).
  double scale(const Values<5>& t) const {
    const double magnitude_sum = lever * std::abs(t[1]) + t[4];
    return std::max(of(t).norm(), scalis_triangle_gradient_floor * magnitude_sum);
  }
};

/// The outer integral over the pieces of the fans' angular variable of the
/// rays' integrals (radial_integral). Compact pieces are integrated in
/// w ∈ [0, 1], v = c0 + (c1 − c0)(3w² − 2w³): at a breakpoint the radial
/// integral behaves like |v − c|^(n + 1/2), which v − c ~ w² turns into a
/// smooth function of w (as the √ ends of a ray).
Adaptive<5> integrate_fans(Setup& s, const Fans& fans, const std::vector<Interval>& pieces,
                           const std::vector<int>& piece_fan, const OuterGradient& gradient, double tolerance) {
  const bool smoothstep = s.finite_support;
  std::vector<Interval> panel_ranges = pieces;
  if (smoothstep) std::fill(panel_ranges.begin(), panel_ranges.end(), Interval{0.0, 1.0});
  bool ray_failed = false;
  auto integrand = [&](int piece, double panel_variable, Values<5>& value, Values<5>& error) {
    const FanTriangle& fan = fans.triangles[piece_fan[piece]];
    double angle_variable = panel_variable, jacobian = 1.0;
    if (smoothstep) {
      const double w = panel_variable, width = pieces[piece].b - pieces[piece].a;
      angle_variable = pieces[piece].a + width * w * w * (3 - 2 * w);
      jacobian = width * 6 * w * (1 - w);
    }
    const double sh = std::sinh(angle_variable), ch = std::cosh(angle_variable);
    const double arc = fan.h * sh;
    const double rho_max = fan.h * ch;
    const Vec2 e = fan.towards_edge / ch + fan.tangent * (sh / ch);
    const double tauE = fan.tauA + (fan.tauB - fan.tauA) * ((arc - fan.sA) / (fan.sB - fan.sA));
    const double slope = (std::max(0.0, tauE) - s.tauO) / rho_max;
    const Adaptive<3> ray = radial_integral(s, e, rho_max, slope, tolerance);
    const double dphi = jacobian / ch;
    value = {ray.value[0] * dphi, ray.value[1] * dphi, ray.value[2] * e.x() * dphi, ray.value[2] * e.y() * dphi,
             std::abs(ray.value[2]) * dphi};
    error = {ray.error[0] * dphi, ray.error[1] * dphi, ray.error[2] * std::abs(e.x()) * dphi,
             ray.error[2] * std::abs(e.y()) * dphi, 0.0};
    // An unconverged ray poisons the estimate, and ends the integration:
    // the result could not be certified anyway.
    if (!ray.converged) {
      error[0] = infinity;
      ray_failed = true;
    }
  };
  auto allowance = [&](const Values<5>& t) {
    if (!s.with_gradient) return Values<5>{tolerance * std::abs(t[0]), infinity, infinity, infinity, infinity};
    const double g = tolerance * gradient.scale(t);
    return Values<5>{tolerance * std::abs(t[0]), gradient.lever > 0.0 ? g / (2 * gradient.lever) : infinity,
                     g / (2 * std::sqrt(2.0)), g / (2 * std::sqrt(2.0)), infinity};
  };
  return integrate_adaptive<5>(panel_ranges, integrand, allowance, max_outer_panels, &ray_failed);
}

}  // namespace

ScalisTriangleIntegral integrate_scalis_triangle(const std::array<Vec3, 3>& vertices, const std::array<double, 3>& radii,
                                                 KernelFamily family, int degree, double sigma, const Vec3& p,
                                                 bool with_gradient, double tolerance) {
  ScalisTriangleIntegral result;
  const LocalTriangle t = local_triangle(vertices, radii, p);
  const kernels::FamilyFacts facts = kernels::family_facts(family);
  const Nearest nearest = nearest_point(t.v, t.tau, t.foot, t.gradient_tau);
  Setup s{facts.finite_support, facts.scalis_radius_term, degree,         sigma * sigma, nearest.point,
          nearest.point - t.foot, 0.0,                    nearest.tau,    with_gradient};
  s.w2 = t.z * t.z + s.offset.squaredNorm();
  const Fans fans = fan_triangles(t, nearest, s.O);

  if (s.w2 == 0.0 && diverges_at_apex(facts.scalis_singularity, s, fans, t, sigma)) {
    result.divergent = true;
    result.converged = true;
    result.F = infinity;
    result.gradient = Vec3::Constant(infinity);
    return result;
  }
  std::vector<Interval> pieces;
  std::vector<int> piece_fan;
  if (!outer_pieces(s, fans, t, pieces, piece_fan)) {
    result.F = std::numeric_limits<double>::quiet_NaN();
    return result;
  }
  const OuterGradient gradient{s.offset, t.z, std::sqrt(s.w2)};
  const Adaptive<5> total = integrate_fans(s, fans, pieces, piece_fan, gradient, tolerance);

  // The constant factor σ^i (infinite support: the integrand τ^(i−2) D^(−i/2)
  // of radial_integral_infinite) or σ^(−i) (radial_integral_compact).
  const double factor = std::pow(sigma, s.finite_support ? -degree : degree);
  result.F = factor * total.value[0];
  result.F_error = factor * total.error[0];
  result.evaluations = s.evaluations;
  result.converged = total.converged;
  if (with_gradient) {
    const Vec3 g = gradient.of(total.value);
    const double undo_scale = std::ldexp(factor, -t.exponent);
    result.gradient = undo_scale * (g.x() * t.e1 + g.y() * t.e2 + g.z() * t.normal);
    result.gradient_error = undo_scale * (gradient.lever * total.error[1] + std::hypot(total.error[2], total.error[3]));
    result.gradient_scale = undo_scale * gradient.scale(total.value);
  }
  return result;
}

}  // namespace skelconv::detail
