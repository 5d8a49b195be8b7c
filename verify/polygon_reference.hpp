// verify/polygon_reference.hpp — the reference value of a polygon field and its
// gradient, by adaptive 2-D quadrature of the DEFINITION integral (docs/mathematics.md §3)
//
//     f(P)  = ∬_Ω K(|P − Q|) dQ
//     ∇f(P) = ∬_Ω K'(r)/r (P − Q) dQ,        r = |P − Q|
//
// over a planar simple polygon Ω (any orientation, possibly non-convex), in
// any real type (long double, or `extended` = binary128), with the kernels of
// verify/kernel_definitions.hpp. Nothing here uses Green's theorem, G^K or any
// closed form: the integrand is K at the Euclidean distance |P − Q| formed
// from coordinates.
//
// Method.
//  * Partition. Ω is triangulated once (PolygonReferenceIntegrator's
//    constructor) with CGAL's constrained Delaunay triangulation of the
//    polygon projected on an orthonormal frame of its plane (Newell normal),
//    keeping the faces of odd nesting level (CGAL's "polygon triangulation"
//    example). Only the combinatorics come from CGAL's doubles: each triangle
//    is rebuilt in Real from the exact input vertices, and the constructor
//    checks that the triangles' areas add up to the polygon's.
//  * Peaks at vertices. Every kernel peaks at P̄, the foot of P on the plane.
//    For each triangle T we take V, the point of T nearest to P (Ericson's
//    closest point on a triangle), and split T at V into 1 (V a corner), 2 (V
//    on an edge) or 3 (V inside, V = P̄) sub-triangles with apex V. All rays
//    from V into T move away from P̄ (V is nearest), so along a ray
//        r² = ρ² + 2βρ + h²,   β = (V − P̄)·e ≥ 0,  h = |P − V|,
//    the peak is at ρ = 0. When the peak is at least as wide as T (inverse and
//    Cauchy only), T is not split and the apex is a corner.
//  * Polar coordinates about the apex X of a sub-triangle X B C. The angle is
//    parametrised by v, with the ray e(v) = (n̂ + sinh v t̂)/cosh v hitting
//    the line BC at F + d sinh(v) t̂ (F the foot of X on BC, d = |XF|):
//    dφ = dv / cosh v and the ray length is d cosh v. This is the sinh
//    substitution of reference_quadrature.hpp applied to the opposite edge:
//    a sliver (P̄ close to an edge, angles near 0 at B or C) is a v-range of
//    length ~log(|BC|/d) with an integrand of width O(1), not a near-singular
//    endpoint.
//  * Radius. ρ = w sinh(u) with w the width of the radial peak (h for p^i,
//    √(h² + 1/s) for c_s^i, whose poles sit at |ρ| = w), when w is smaller
//    than the ray; otherwise ρ = u. The singularities then sit near
//    u = ±iπ/2 only, so intervals may grow geometrically with u: heights
//    z = 1e-6 diam cost a few intervals, not a million nodes.
//  * Compact support k_R^i (even i only): the integrand is a polynomial in ρ
//    inside the support and 0 outside. The ray is cut at the support boundary
//    ρ₁(v) = (R² − h²)/(β + √(β² + R² − h²)) (V is inside the disc of radius
//    √(R² − z²) about P̄, or T is outside the support and contributes 0), and
//    the v-range is split where that circle crosses the opposite edge, where
//    the angular integrand has a kink.
//  * Quadrature. Nested adaptive Gauss–Kronrod (G20/K41, G10/K21 for the
//    polynomial radial integrand of k_R^i; Boost's tables for long double
//    and binary128), vector-valued: all degrees of one family
//    share the nodes, and each node gives, per degree, f, ∇f and ∫|K'| (the
//    scale against which ∇f's error is measured, ∇f itself cancels). The
//    inner (radial) integral is computed to tolerance/4 relative; the outer
//    (angular) integral propagates the inner error estimates with its
//    Kronrod weights and adds its own |K − G|.
//  * Error estimate. Per interval |K − G| + propagated inner error; once
//    |K − G| is down to rounding noise (noise_ulps·ε·L1), bisecting cannot
//    help and the interval is charged rounding_ulps·ε·L1 instead (see
//    there). The sums over intervals and triangles give the
//    relative error estimate of f and of |∇f| (norm of the component error
//    bounds over |∇f|). `trusted` is false when either exceeds the tolerance
//    asked for: the caller must not use such a reference.
//  * Reachable accuracy. The rounding charge puts a floor of ~12 ε under the
//    estimate: ≈1.3e-18 in long double (ask for ≥ 4e-18 to be trusted; the
//    measured errors against binary128 are ≤ 4e-19), ≈2e-33 in binary128.
//    Where ∇f cancels (|∇f| ≪ ∫|K'|, e.g. z → 0 above a symmetric region)
//    the gradient's relative estimate grows accordingly and may be untrusted.
//  * Cost (2 shared cores under load, 10 degrees of one family, pentagon):
//    long double at 4e-18: ~20k kernel evaluations (10–18 ms) at a generic
//    point, 40k–110k (20–65 ms) at z = 1e-6·diam or 1e-6·diam from an edge,
//    up to ~370k (200 ms) for c_s^i near an edge; binary128 at 1e-24 ~8 µs
//    per evaluation. The highest degree dominates: (ρ² + h²)^(-i/2) has
//    poles of order i at |ρ| = h, resolved only by short intervals.
//  * Not covered by the estimate: the conditioning of the geometry in Real.
//    Coordinates of the foot point and of the edges relative to it carry
//    rounding ~ε·diam, so near a plane that is not axis-aligned (z ≪ diam)
//    or near an edge (distance δ ≪ diam) the result can be off by
//    ~ε·diam/z or ε·diam/δ relative. With binary128 that is ≤ 1e-27 at
//    1e-6·diam; in long double ≤ 1e-13.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <list>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "extended_precision.hpp"
#include "kernel_definitions.hpp"

namespace skelconv::verify {

/// The reference field of one kernel degree at one point.
template <class Real>
struct PolygonReference {
  Real value;                   ///< f(P)
  std::array<Real, 3> gradient; ///< ∇f(P)
  Real value_error;             ///< estimated relative error of value
  Real gradient_error;          ///< estimated |error of ∇f| / |∇f|
  bool trusted;                 ///< both estimates ≤ the tolerance asked for
};

namespace polygon_detail {

template <class T>
Vec3<T> cross(const Vec3<T>& u, const Vec3<T>& v) {
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

template <class T>
Vec3<T> scaled(const T& alpha, const Vec3<T>& v) {
  return {alpha * v[0], alpha * v[1], alpha * v[2]};
}

/// sinh and cosh of x from one expm1: accurate to a few ε for every x
/// (e − 1/e alone loses relative accuracy of sinh near 0).
template <class Real>
std::pair<Real, Real> sinh_cosh(const Real& x) {
  using std::abs;
  using std::expm1;
  const Real m = expm1(abs(x));  // e^|x| − 1
  const Real e = m + 1;
  const Real s = m * (m + 2) / (2 * e);  // (e − 1/e)/2
  const Real c = (e + 1 / e) / 2;
  return {x < 0 ? -s : s, c};
}

/// A Gauss–Kronrod rule on [−1, 1] as full node lists; the Gauss nodes come
/// first (`gauss_count` of them), so a pass over the nodes can stop adding
/// to the Gauss sum after them. Boost holds the tables for 64- and 113-bit
/// types.
template <class Real>
struct KronrodRule {
  std::vector<Real> node, kronrod_weight, gauss_weight;
  std::size_t gauss_count = 0;
};

template <class Real, unsigned points>
KronrodRule<Real> make_kronrod_rule() {
  constexpr unsigned gauss_order = (points - 1) / 2;
  using GK = boost::math::quadrature::gauss_kronrod<Real, points>;
  using G = boost::math::quadrature::gauss<Real, gauss_order>;
  const auto& x = GK::abscissa();
  const auto& wk = GK::weights();
  const auto& wg = G::weights();
  // Boost stores x ≥ 0; index i is a Gauss node iff i ≡ (gauss_order odd ? 0 : 1) mod 2.
  const unsigned gauss_parity = gauss_order & 1 ? 0 : 1;
  KronrodRule<Real> out;
  for (int pass = 0; pass < 2; ++pass) {  // Gauss nodes, then Kronrod-only nodes
    for (unsigned i = 0; i < x.size(); ++i) {
      const bool is_gauss = i % 2 == gauss_parity;
      if (is_gauss != (pass == 0)) continue;
      const Real g = is_gauss ? Real(wg[i / 2]) : Real(0);
      out.node.push_back(x[i]);
      out.kronrod_weight.push_back(wk[i]);
      out.gauss_weight.push_back(g);
      if (i != 0) {
        out.node.push_back(-x[i]);
        out.kronrod_weight.push_back(wk[i]);
        out.gauss_weight.push_back(g);
      }
    }
    if (pass == 0) out.gauss_count = out.node.size();
  }
  return out;
}

/// G20/K41 for the angular (outer) integral and for the radial (inner) one
/// of p^i and c_s^i: their integrands have poles of order up to i near the
/// interval, which a higher order resolves with fewer, longer intervals
/// (measured: 2–3.5× fewer kernel evaluations than G10/K21 × G15/K31 at
/// generic and near-plane points). G10/K21 for the radial integral of k_R^i:
/// a polynomial of degree ≤ i + 1 in ρ, exact for G10 up to i = 18.
template <class Real>
const KronrodRule<Real>& outer_rule() {
  static const KronrodRule<Real> rule = make_kronrod_rule<Real, 41>();
  return rule;
}
template <class Real>
const KronrodRule<Real>& inner_rule(bool polynomial) {
  static const KronrodRule<Real> high = make_kronrod_rule<Real, 41>();
  static const KronrodRule<Real> low = make_kronrod_rule<Real, 21>();
  return polynomial ? low : high;
}

/// Rounding of one rule application, in units of ε·|∫ scale|.
///  * noise_ulps: |K − G| below this is rounding noise (kernels of degree
///    ≤ 16 are products of ~18 rounded factors per node, the sums add a few
///    ε), so bisecting cannot reduce it; the interval counts as resolved.
///  * rounding_ulps: the error then claimed for K. K's truncation error is
///    far below |K − G| (the Kronrod rule is exact to degree 3n+1 against the
///    Gauss rule's 2n−1, so for an analytic integrand err_K ≈ err_G^1.5, as
///    QUADPACK assumes), which leaves its rounding: per-node errors of a few
///    ε with random signs, averaged by the positive weights. Measured against
///    binary128 (long double, 105 values, degrees 3–12, heights 1e-6…1,
///    L-shaped polygon): total errors ≤ 3.8 ε, so each of the two nested
///    levels is charged 6 ε (long double floor ≈ 1.3e-18 relative).
inline constexpr int noise_ulps = 16;
inline constexpr int rounding_ulps = 6;

/// Adaptive vector-valued Gauss–Kronrod on [a, b]. The integrand is called
/// as integrand(x, values, errors) and must ASSIGN `components` values, and,
/// when `nested`, their absolute error estimates. Component c is judged
/// relative to |∫ component scale_of[c]|, a non-negative integrand (f for f,
/// ∫|K'| for ∇f).
template <class Real>
class AdaptiveKronrod {
 public:
  void configure(const KronrodRule<Real>& rule, bool nested, std::size_t components,
                 std::vector<std::size_t> scale_of, std::size_t max_intervals) {
    rule_ = &rule;
    nested_ = nested;
    components_ = components;
    scale_of_ = std::move(scale_of);
    max_intervals_ = max_intervals;
    node_values_.assign(components_, Real(0));
    node_errors_.assign(components_, Real(0));
    totals_.assign(components_, Real(0));
    errors_.assign(components_, Real(0));
    gauss_.assign(components_, Real(0));
    storage_.assign(3 * components_ * max_intervals_, Real(0));
    ends_.assign(2 * max_intervals_, Real(0));
  }

  /// Integrates over the partition `breaks` (ascending, ≥ 2 entries) and
  /// adds the integral to `value_out` and its error estimate to `error_out`.
  /// False if the interval budget ran out before the tolerance was met.
  template <class Integrand>
  bool integrate(const Integrand& integrand, const std::vector<Real>& breaks, const Real& tolerance,
                 Real* value_out, Real* error_out) {
    using std::abs;
    count_ = 0;
    bool budget_exhausted = false;
    for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
      if (!(breaks[k + 1] > breaks[k])) continue;
      if (count_ == max_intervals_) {
        budget_exhausted = true;
        break;
      }
      evaluate(integrand, breaks[k], breaks[k + 1], count_++);
    }
    // Ends when every component meets the tolerance, or when only rounding
    // noise is left (the estimate then says so), or out of budget (false).
    while (!budget_exhausted) {
      std::fill(totals_.begin(), totals_.end(), Real(0));
      std::fill(errors_.begin(), errors_.end(), Real(0));
      for (std::size_t k = 0; k < count_; ++k) {
        const Real* value = interval_value(k);
        const Real* error = interval_error(k);
        for (std::size_t c = 0; c < components_; ++c) {
          totals_[c] += value[c];
          errors_[c] += error[c];
        }
      }
      bool converged = true;
      for (std::size_t c = 0; c < components_ && converged; ++c)
        converged = errors_[c] <= tolerance * abs(totals_[scale_of_[c]]);
      if (converged) break;
      // Bisect the interval whose reducible (above-noise) error is largest
      // relative to the scale of its component.
      std::size_t worst = count_;
      Real worst_error = 0;
      for (std::size_t k = 0; k < count_; ++k) {
        const Real* reducible = interval_reducible(k);
        for (std::size_t c = 0; c < components_; ++c) {
          if (!(reducible[c] > 0)) continue;
          const Real scale = abs(totals_[scale_of_[c]]);
          const Real e = scale > 0 ? reducible[c] / scale : std::numeric_limits<Real>::infinity();
          if (e > worst_error) {
            worst_error = e;
            worst = k;
          }
        }
      }
      if (worst == count_) break;  // only noise left: bisection cannot help
      const Real a = ends_[2 * worst], b = ends_[2 * worst + 1];
      const Real mid = (a + b) / 2;
      if (count_ == max_intervals_ || !(mid > a && mid < b)) {
        budget_exhausted = true;
        break;
      }
      evaluate(integrand, a, mid, worst);
      evaluate(integrand, mid, b, count_++);
    }
    if (budget_exhausted) {  // totals of the final partition
      std::fill(totals_.begin(), totals_.end(), Real(0));
      std::fill(errors_.begin(), errors_.end(), Real(0));
      for (std::size_t k = 0; k < count_; ++k)
        for (std::size_t c = 0; c < components_; ++c) {
          totals_[c] += interval_value(k)[c];
          errors_[c] += interval_error(k)[c];
        }
    }
    for (std::size_t c = 0; c < components_; ++c) {
      value_out[c] += totals_[c];
      error_out[c] += errors_[c];
    }
    return !budget_exhausted;
  }

  std::uint64_t evaluations() const { return evaluations_; }

  /// The partition the last integrate() ended with (ascending breakpoints).
  void partition(std::vector<Real>& breaks) const {
    breaks.clear();
    for (std::size_t k = 0; k < count_; ++k) breaks.push_back(ends_[2 * k]);
    std::sort(breaks.begin(), breaks.end());
    if (count_ > 0) breaks.push_back(*std::max_element(ends_.begin() + 1, ends_.begin() + 2 * count_));
  }

 private:
  Real* interval_value(std::size_t k) { return storage_.data() + 3 * components_ * k; }
  Real* interval_error(std::size_t k) { return interval_value(k) + components_; }
  Real* interval_reducible(std::size_t k) { return interval_value(k) + 2 * components_; }

  template <class Integrand>
  void evaluate(const Integrand& integrand, const Real& a, const Real& b, std::size_t slot) {
    using std::abs;
    const KronrodRule<Real>& rule = *rule_;
    ends_[2 * slot] = a;
    ends_[2 * slot + 1] = b;
    Real* value = interval_value(slot);
    Real* error = interval_error(slot);
    Real* reducible = interval_reducible(slot);
    std::fill(value, value + 3 * components_, Real(0));
    std::fill(gauss_.begin(), gauss_.end(), Real(0));
    const Real half = (b - a) / 2, mid = (a + b) / 2;
    for (std::size_t k = 0; k < rule.node.size(); ++k) {
      integrand(mid + half * rule.node[k], node_values_.data(), node_errors_.data());
      const Real wk = rule.kronrod_weight[k];
      for (std::size_t c = 0; c < components_; ++c) value[c] += wk * node_values_[c];
      if (k < rule.gauss_count) {
        const Real wg = rule.gauss_weight[k];
        for (std::size_t c = 0; c < components_; ++c) gauss_[c] += wg * node_values_[c];
      }
      if (nested_)  // inner error estimates, propagated with the (positive) weights
        for (std::size_t c = 0; c < components_; ++c) error[c] += wk * node_errors_[c];
    }
    evaluations_ += rule.node.size();
    for (std::size_t c = 0; c < components_; ++c) value[c] *= half;
    const Real eps = std::numeric_limits<Real>::epsilon();
    for (std::size_t c = 0; c < components_; ++c) {
      const Real truncation = abs(value[c] - half * gauss_[c]);
      // The scale component is a non-negative integrand: its |K| is its L1 norm.
      const Real scale = abs(value[scale_of_[c]]);
      const bool resolved = truncation <= noise_ulps * eps * scale;
      reducible[c] = resolved ? Real(0) : truncation;
      error[c] = half * error[c] + (resolved ? rounding_ulps * eps * scale : truncation);
    }
  }

  const KronrodRule<Real>* rule_ = nullptr;
  bool nested_ = false;
  std::size_t components_ = 0;
  std::vector<std::size_t> scale_of_;
  std::size_t max_intervals_ = 64;
  std::size_t count_ = 0;
  std::vector<Real> storage_, ends_;
  std::vector<Real> node_values_, node_errors_, totals_, errors_, gauss_;
  std::uint64_t evaluations_ = 0;
};

// ---- triangulation (CGAL, doubles: combinatorics only) ----------------------

/// Triangles (vertex indices) covering the polygon `points` (doubles), given
/// its unit normal; throws std::invalid_argument for a polygon CGAL finds
/// self-intersecting. In polygon_triangulation.cpp, the only verifier file
/// that includes CGAL (its headers cost ~12 s of compiling per file).
std::vector<std::array<std::size_t, 3>> triangulate_planar_polygon(const std::vector<Vec3<double>>& points,
                                                                   const Vec3<double>& unit_normal);

/// Triangles (vertex indices) covering the polygon; throws std::invalid_argument
/// for a polygon CGAL finds self-intersecting or that has no area.
template <class Real>
std::vector<std::array<std::size_t, 3>> triangulate_polygon(const std::vector<Vec3<Real>>& vertices) {
  const std::size_t n = vertices.size();
  if (n < 3) throw std::invalid_argument("polygon_reference: fewer than 3 vertices");
  // Newell's normal, in double (combinatorics only).
  Vec3<double> normal{0, 0, 0};
  for (std::size_t k = 0; k < n; ++k) {
    const auto& a = vertices[k];
    const auto& b = vertices[(k + 1) % n];
    normal[0] += static_cast<double>((a[1] - b[1]) * (a[2] + b[2]));
    normal[1] += static_cast<double>((a[2] - b[2]) * (a[0] + b[0]));
    normal[2] += static_cast<double>((a[0] - b[0]) * (a[1] + b[1]));
  }
  const double length = norm(normal);
  if (!(length > 0)) throw std::invalid_argument("polygon_reference: polygon has no area");
  std::vector<Vec3<double>> points(n);
  for (std::size_t k = 0; k < n; ++k)
    points[k] = {static_cast<double>(vertices[k][0]), static_cast<double>(vertices[k][1]),
                 static_cast<double>(vertices[k][2])};
  return triangulate_planar_polygon(points, scaled(1 / length, normal));
}

}  // namespace polygon_detail

/// Triangulates a polygon once, then evaluates the reference at any point.
/// Not thread-safe (scratch space); use one per thread.
template <class Real>
class PolygonReferenceIntegrator {
 public:
  /// Interval budget of each adaptive integral (inner and outer).
  static constexpr std::size_t max_intervals = 64;

  explicit PolygonReferenceIntegrator(std::vector<Vec3<Real>> vertices)
      : vertices_(std::move(vertices)), triangles_(polygon_detail::triangulate_polygon(vertices_)) {
    using std::abs;
    // The triangles must tile the polygon: Σ |area(T)| = |area(Ω)| (Newell, in Real).
    Vec3<Real> newell{0, 0, 0};
    for (std::size_t k = 0; k < vertices_.size(); ++k) {
      const auto& a = vertices_[k];
      const auto& b = vertices_[(k + 1) % vertices_.size()];
      newell = axpy(Real(1), polygon_detail::cross(a, b), newell);
    }
    const Real polygon_area = norm(newell) / 2;
    Real triangle_area = 0;
    for (const auto& t : triangles_) {
      const auto& a = vertices_[t[0]];
      triangle_area += norm(polygon_detail::cross(sub(vertices_[t[1]], a), sub(vertices_[t[2]], a))) / 2;
    }
    if (!(abs(triangle_area - polygon_area) <= 1e-12 * polygon_area))
      throw std::invalid_argument("polygon_reference: triangles do not tile the polygon (not planar or not simple?)");
  }

  const std::vector<std::array<std::size_t, 3>>& triangles() const { return triangles_; }
  /// Kernel evaluations so far (each covers every degree asked for).
  std::uint64_t node_count() const { return inner_.evaluations(); }

  /// f, ∇f and their error estimates for each degree of `degrees` (one
  /// family; s for Cauchy, R for compact), requested to relative accuracy
  /// `tolerance`. Inverse kernels with P on the polygon give +inf (degree ≥ 2;
  /// degree 1 there is reported untrusted, NaN). Compact degrees must be even.
  std::vector<PolygonReference<Real>> evaluate(const Vec3<Real>& p, KernelFamily family,
                                               const std::vector<int>& degrees, const Real& s, const Real& R,
                                               const Real& tolerance) {
    using std::abs;
    using std::sqrt;
    for (int i : degrees) {
      if (i < 1 || (family == KernelFamily::compact && i % 2 != 0))
        throw std::invalid_argument("polygon_reference: unsupported degree " + std::to_string(i));
    }
    if (degrees.empty()) return {};
    setup_problem(p, family, degrees, s, R);
    const std::size_t nc = components();
    std::vector<Real> value(nc, Real(0)), error(nc, Real(0));
    bool all_converged = true;
    bool on_polygon = false;
    for (const auto& t : triangles_) {
      const Vec3<Real>& a = vertices_[t[0]];
      const Vec3<Real>& b = vertices_[t[1]];
      const Vec3<Real>& c = vertices_[t[2]];
      const Nearest nearest = nearest_point(a, b, c, p);
      const Vec3<Real> h_vector = sub(p, nearest.point);
      const Real h = norm(h_vector);
      if (family_ == KernelFamily::compact && !(h < R_)) continue;  // T outside the support
      if (family_ == KernelFamily::inverse && h == 0) {
        on_polygon = true;
        break;
      }
      const Real diameter = std::max({norm(sub(b, a)), norm(sub(c, b)), norm(sub(a, c))});
      if (family_ != KernelFamily::compact && peak_width(h) >= diameter) {
        all_converged &= integrate_sub_triangle(a, b, c, p, tolerance, value.data(), error.data());
        continue;
      }
      const Vec3<Real>& v = nearest.point;
      switch (nearest.region) {
        case Region::corner_a: all_converged &= integrate_sub_triangle(a, b, c, p, tolerance, value.data(), error.data()); break;
        case Region::corner_b: all_converged &= integrate_sub_triangle(b, c, a, p, tolerance, value.data(), error.data()); break;
        case Region::corner_c: all_converged &= integrate_sub_triangle(c, a, b, p, tolerance, value.data(), error.data()); break;
        case Region::edge_ab:
          all_converged &= integrate_sub_triangle(v, b, c, p, tolerance, value.data(), error.data());
          all_converged &= integrate_sub_triangle(v, c, a, p, tolerance, value.data(), error.data());
          break;
        case Region::edge_bc:
          all_converged &= integrate_sub_triangle(v, c, a, p, tolerance, value.data(), error.data());
          all_converged &= integrate_sub_triangle(v, a, b, p, tolerance, value.data(), error.data());
          break;
        case Region::edge_ca:
          all_converged &= integrate_sub_triangle(v, a, b, p, tolerance, value.data(), error.data());
          all_converged &= integrate_sub_triangle(v, b, c, p, tolerance, value.data(), error.data());
          break;
        case Region::inside:
          all_converged &= integrate_sub_triangle(v, a, b, p, tolerance, value.data(), error.data());
          all_converged &= integrate_sub_triangle(v, b, c, p, tolerance, value.data(), error.data());
          all_converged &= integrate_sub_triangle(v, c, a, p, tolerance, value.data(), error.data());
          break;
      }
    }

    std::vector<PolygonReference<Real>> out;
    for (std::size_t k = 0; k < degrees.size(); ++k) {
      PolygonReference<Real> ref{};
      if (on_polygon) {
        const Real inf = std::numeric_limits<Real>::infinity();
        const bool finite_integral = degrees[k] < 2;  // p^1 converges on the plane; not handled here
        const Real v = finite_integral ? std::numeric_limits<Real>::quiet_NaN() : inf;
        ref = {v, {v, v, v}, Real(0), Real(0), !finite_integral};
        out.push_back(ref);
        continue;
      }
      const std::size_t base = 5 * k;
      ref.value = value[base];
      ref.gradient = {value[base + 1], value[base + 2], value[base + 3]};
      ref.value_error = ref.value != 0 ? error[base] / abs(ref.value) : (error[base] == 0 ? Real(0) : std::numeric_limits<Real>::infinity());
      const Real gradient_norm = norm(ref.gradient);
      const Real gradient_error_norm =
          sqrt(error[base + 1] * error[base + 1] + error[base + 2] * error[base + 2] + error[base + 3] * error[base + 3]);
      ref.gradient_error = gradient_norm != 0 ? gradient_error_norm / gradient_norm
                                              : (gradient_error_norm == 0 ? Real(0) : std::numeric_limits<Real>::infinity());
      ref.trusted = all_converged && ref.value_error <= tolerance && ref.gradient_error <= tolerance;
      out.push_back(ref);
    }
    return out;
  }

 private:
  enum class Region { corner_a, corner_b, corner_c, edge_ab, edge_bc, edge_ca, inside };
  struct Nearest {
    Vec3<Real> point;
    Region region;
  };

  /// Closest point of triangle abc to p (Ericson, Real-Time Collision
  /// Detection §5.1.5), with the Voronoi region it lies in.
  static Nearest nearest_point(const Vec3<Real>& a, const Vec3<Real>& b, const Vec3<Real>& c, const Vec3<Real>& p) {
    const Vec3<Real> ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
    const Real d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return {a, Region::corner_a};
    const Vec3<Real> bp = sub(p, b);
    const Real d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return {b, Region::corner_b};
    const Real vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return {axpy(d1 / (d1 - d3), ab, a), Region::edge_ab};
    const Vec3<Real> cp = sub(p, c);
    const Real d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return {c, Region::corner_c};
    const Real vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return {axpy(d2 / (d2 - d6), ac, a), Region::edge_ca};
    const Real va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
      return {axpy((d4 - d3) / ((d4 - d3) + (d5 - d6)), sub(c, b), b), Region::edge_bc};
    const Real denominator = va + vb + vc;
    return {axpy(vc / denominator, ac, axpy(vb / denominator, ab, a)), Region::inside};
  }

  std::size_t components() const { return 5 * degrees_.size(); }

  void setup_problem(const Vec3<Real>& p, KernelFamily family, const std::vector<int>& degrees, const Real& s,
                     const Real& R) {
    family_ = family;
    degrees_ = degrees;
    s_ = s;
    R_ = R;
    p_ = p;
    max_power_ = 0;
    for (int i : degrees) max_power_ = std::max(max_power_, i + 2);
    powers_.assign(max_power_ + 1, Real(0));
    // Component 5k is f_k, 5k+1..3 ∇f_k, 5k+4 ∫|K'_k|; ∇f is judged against ∫|K'|.
    std::vector<std::size_t> scale_of(components());
    for (std::size_t k = 0; k < degrees.size(); ++k) {
      scale_of[5 * k] = 5 * k;
      for (std::size_t c = 1; c < 5; ++c) scale_of[5 * k + c] = 5 * k + 4;
    }
    inner_.configure(polygon_detail::inner_rule<Real>(family == KernelFamily::compact), false, components(), scale_of, max_intervals);
    outer_.configure(polygon_detail::outer_rule<Real>(), true, components(), scale_of, max_intervals);
  }

  /// Width of the radial peak at distance h from P: the singularities of
  /// ρ ↦ K(√(ρ² + 2βρ + h²)) lie on |ρ| = width (β real, 0 ≤ β ≤ h).
  Real peak_width(const Real& h) const {
    const KernelDefinition<Real> kernel{family_, degrees_.front(), s_, R_};
    return kernel.peak_width(h);  // the trait's (kernels/): h, √(h² + 1/s), or +inf
  }

  /// Writes, per component, K at distance vector y (= P − Q) times `weight`.
  void evaluate_kernels(const Vec3<Real>& y, const Real& weight, Real* values) {
    using std::sqrt;
    const Real r2 = dot(y, y);
    const Real r = sqrt(r2);
    Real base;       // K_i = base^i
    Real derivative_factor;  // K'_i/r = −i · derivative_factor · base^(i + derivative_shift)
    int derivative_shift;
    switch (family_) {
      case KernelFamily::inverse:
        base = 1 / r;
        derivative_factor = 1;
        derivative_shift = 2;
        break;
      case KernelFamily::cauchy:
        base = 1 / sqrt(1 + s_ * r2);
        derivative_factor = s_;
        derivative_shift = 2;
        break;
      default: {
        const Real q = 1 - r2 / (R_ * R_);
        if (!(q > 0)) {
          std::fill(values, values + components(), Real(0));
          return;
        }
        base = sqrt(q);
        derivative_factor = 1 / (R_ * R_);
        derivative_shift = -2;
        break;
      }
    }
    powers_[0] = 1;
    for (int k = 1; k <= max_power_; ++k) powers_[k] = powers_[k - 1] * base;
    for (std::size_t k = 0; k < degrees_.size(); ++k) {
      const int i = degrees_[k];
      const Real kernel = powers_[i] * weight;
      const Real derivative_over_r = -Real(i) * derivative_factor * powers_[i + derivative_shift] * weight;
      Real* out = values + 5 * k;
      out[0] = kernel;
      out[1] = derivative_over_r * y[0];
      out[2] = derivative_over_r * y[1];
      out[3] = derivative_over_r * y[2];
      out[4] = -derivative_over_r * r;  // |K'| = −K'/r · r
    }
  }

  /// lo, the breakpoints ±first·2^k inside (lo, hi), hi: the
  /// singularities of the substituted integrands sit near 0, so intervals may
  /// grow geometrically away from it.
  static void geometric_breaks(const Real& lo, const Real& hi, const Real& first, std::vector<Real>& breaks) {
    breaks.clear();
    breaks.push_back(lo);
    for (Real x = -first; x > lo; x *= 2)
      if (x < hi) breaks.insert(breaks.begin() + 1, x);
    for (Real x = first; x < hi; x *= 2)
      if (x > lo) breaks.push_back(x);
    breaks.push_back(hi);
  }

  /// ∬ over the triangle x b c in polar coordinates about the apex x (see
  /// the header comment); adds values and error estimates. False if an
  /// adaptive integral ran out of intervals.
  bool integrate_sub_triangle(const Vec3<Real>& x, const Vec3<Real>& b, const Vec3<Real>& c, const Vec3<Real>& p,
                              const Real& tolerance, Real* value_out, Real* error_out) {
    using std::asinh;
    using std::sqrt;
    const Vec3<Real> bc = sub(c, b);
    const Real edge_length = norm(bc);
    if (!(edge_length > 0)) return true;
    const Vec3<Real> t_hat = polygon_detail::scaled(1 / edge_length, bc);
    // F − X (⊥ BC) from the corner nearer to X: for a sliver (X close to
    // B or C) the difference from the far corner would cancel to ε·|BC|/d.
    const Vec3<Real> xb = sub(b, x), xc = sub(c, x);
    const bool b_nearer = dot(xb, xb) <= dot(xc, xc);
    const Real tau_near = dot(b_nearer ? xb : xc, t_hat);
    const Real tau_b = b_nearer ? tau_near : tau_near - edge_length;
    const Real tau_c = b_nearer ? tau_near + edge_length : tau_near;
    const Vec3<Real> to_foot = axpy(-tau_near, t_hat, b_nearer ? xb : xc);
    const Real d = norm(to_foot);
    if (!(d > 0)) return true;  // x on the line BC: no area
    const Vec3<Real> n_hat = polygon_detail::scaled(1 / d, to_foot);
    const Vec3<Real> h_vector = sub(p, x);
    const Real h = norm(h_vector);
    const Real width = peak_width(h);

    // Angular breakpoints: geometric in v, plus (compact) where the support
    // circle, centre P̄, radius √(R² − z²), crosses the opposite edge.
    std::vector<Real> v_breaks;
    geometric_breaks(asinh(tau_b / d), asinh(tau_c / d), Real(2), v_breaks);
    if (family_ == KernelFamily::compact) {
      const Vec3<Real> plane_normal = polygon_detail::cross(t_hat, n_hat);
      const Real z = dot(h_vector, plane_normal);
      const Vec3<Real> in_plane = axpy(-z, plane_normal, h_vector);  // P̄ − X
      const Real offset = d - dot(in_plane, n_hat);
      const Real radicand = R_ * R_ - z * z - offset * offset;
      if (radicand > 0) {
        const Real centre = dot(in_plane, t_hat), half_chord = sqrt(radicand);
        for (const Real& tau : {centre - half_chord, centre + half_chord})
          if (tau > tau_b && tau < tau_c) v_breaks.push_back(asinh(tau / d));
        std::sort(v_breaks.begin(), v_breaks.end());
      }
    }

    std::vector<Real> u_breaks, previous_fractions;
    bool previous_stretched = false;
    const auto angular_integrand = [&](const Real& v, Real* values, Real* errors) {
      const auto [sinh_v, cosh_v] = polygon_detail::sinh_cosh(v);
      const Vec3<Real> e = polygon_detail::scaled(1 / cosh_v, axpy(sinh_v, t_hat, n_hat));
      Real rho_end = d * cosh_v;
      if (family_ == KernelFamily::compact) {
        const Real beta = -dot(h_vector, e);
        const Real gap = R_ * R_ - h * h;  // > 0: apex inside the support
        rho_end = std::min(rho_end, gap / (beta + sqrt(beta * beta + gap)));
      }
      const bool stretched = width < rho_end;
      const Real u_end = stretched ? asinh(rho_end / width) : rho_end;
      // Start from the partition the previous ray ended with (rescaled to
      // this ray's length): neighbouring rays need nearly the same one, and
      // starting coarse wastes the parents of every bisection.
      if (!previous_fractions.empty() && stretched == previous_stretched) {
        u_breaks.clear();
        for (const Real& fraction : previous_fractions) u_breaks.push_back(fraction * u_end);
        u_breaks.front() = 0;
        u_breaks.back() = u_end;
      } else {
        geometric_breaks(Real(0), u_end, Real(1), u_breaks);
      }
      const auto radial_integrand = [&](const Real& u, Real* inner_values, Real*) {
        Real rho = u, jacobian = 1;
        if (stretched) {
          const auto [sinh_u, cosh_u] = polygon_detail::sinh_cosh(u);
          rho = width * sinh_u;
          jacobian = width * cosh_u;
        }
        evaluate_kernels(axpy(-rho, e, h_vector), rho * jacobian, inner_values);
      };
      std::fill(values, values + components(), Real(0));
      std::fill(errors, errors + components(), Real(0));
      inner_converged_ &= inner_.integrate(radial_integrand, u_breaks, tolerance / 4, values, errors);
      inner_.partition(previous_fractions);
      for (Real& fraction : previous_fractions) fraction /= u_end;
      previous_stretched = stretched;
      const Real angular_jacobian = 1 / cosh_v;  // dφ/dv
      for (std::size_t c = 0; c < components(); ++c) {
        values[c] *= angular_jacobian;
        errors[c] *= angular_jacobian;
      }
    };
    inner_converged_ = true;
    const bool outer_converged = outer_.integrate(angular_integrand, v_breaks, tolerance / 2, value_out, error_out);
    return outer_converged && inner_converged_;
  }

  std::vector<Vec3<Real>> vertices_;
  std::vector<std::array<std::size_t, 3>> triangles_;
  KernelFamily family_ = KernelFamily::inverse;
  std::vector<int> degrees_;
  Real s_ = 1, R_ = 1;
  Vec3<Real> p_{};
  int max_power_ = 0;
  std::vector<Real> powers_;
  polygon_detail::AdaptiveKronrod<Real> inner_, outer_;
  bool inner_converged_ = true;
};

/// One-shot form: triangulates `vertices` (boundary order, either
/// orientation) and evaluates every degree of `degrees` at p.
template <class Real>
std::vector<PolygonReference<Real>> polygon_reference(const std::vector<std::array<Real, 3>>& vertices,
                                                      const std::array<Real, 3>& p, KernelFamily family,
                                                      const std::vector<int>& degrees, Real s, Real R,
                                                      Real tolerance) {
  PolygonReferenceIntegrator<Real> integrator(vertices);
  return integrator.evaluate(p, family, degrees, s, R, tolerance);
}

}  // namespace skelconv::verify
