// skelconv/primitives/polygon_field.hpp — the convolution field of a planar polygon
// (docs/mathematics.md §3, Hubert 2012 §5–8), by the contour formula: a sum over the edges,
// no triangulation.
//
//     f(P) = ∬_Ω K(|P − Q|) dQ
//
// This is the contract between the runtime (skelconv/primitives/polygon.hpp validates
// the polygon once) and the generated per-edge kernels
// (generated/polygon_*.hpp, written by codegen/polygon_families.cpp, whose
// header derives the formulas). The caller guarantees: at least 3 vertices
// in boundary order, counter-clockwise about the unit normal `normal`,
// coplanar, simple, non-zero area; a kernel degree the table supports
// (polygon_supported_degrees).
//
// What this driver adds to the edge terms, and why:
//  * Θ = Σ_m θ_m is exactly 0 (P̄ outside) or 2π (inside) unless P̄ is on
//    the boundary. It multiplies ζ^(2−i), which is huge near the plane, so
//    the rounding of the sum must not enter: Θ is snapped to the nearest
//    multiple of 2π when within 1e-6 of it (P̄ on the boundary keeps the
//    computed sum: π on an edge, the interior angle at a vertex).
//  * An edge with h = 0 (P̄ on its line) contributes nothing to f (its fan
//    triangle is flat); its θ would be ±π by the sign of a zero, so it is
//    left out of Θ as well.
//  * Inverse kernels with P in the closed polygon (z = 0, P̄ inside or on
//    the boundary): the integral diverges, f = +∞ and ∇f = (+∞, +∞, +∞), as
//    for a point on an inverse segment.
//  * Compact kernels: |z| ≥ R gives f = 0, ∇f = 0; an edge is clipped to
//    the support disc of radius √(R² − z²) around P̄ (skelconv/detail/clip.hpp).
//  * Inverse and Cauchy kernels far from the polygon (distance ≥ 2
//    diameters), or a Cauchy kernel as wide (1/√s ≥ 2 diameters): the fans
//    cancel, and skelconv/detail/polygon_far_field.hpp integrates the definition
//    directly, exact to rounding there.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "generated/polygon_table.hpp"
#include "skelconv/detail/clip.hpp"
#include "skelconv/detail/polygon_far_field.hpp"
#include "skelconv/primitives/polygon_edge_input.hpp"
#include "skelconv/detail/integer_power.hpp"
#include "skelconv/detail/plane_height.hpp"
#include "skelconv/kernels/read_trait.hpp"
#include "skelconv/primitives/segment_input.hpp"  // KernelFamily

namespace skelconv {

/// A validated polygon and its kernel, on scalar type T.
template <class T>
struct PolygonInput {
  std::span<const std::array<T, 3>> vertices;  ///< boundary order, CCW about normal
  std::array<T, 3> normal{};                   ///< unit normal of the plane
  KernelFamily family = KernelFamily::inverse;
  int degree = 3;  ///< i of docs/mathematics.md §1
  T s = T(1);      ///< Cauchy sharpness (cauchy only)
  T R = T(1);      ///< support radius (compact only)
  /// The generated kernel of (family, degree), for a caller that evaluates
  /// one polygon at many points: looked up once (polygon_edge_kernel)
  /// rather than at every point. Null: polygon_evaluate looks it up.
  const generated::PolygonEdgeKernel<T>* edge_kernel = nullptr;
};

/// The generated edge kernel of (family, degree); throws
/// std::invalid_argument when the table has none.
template <class T>
const generated::PolygonEdgeKernel<T>& polygon_edge_kernel(KernelFamily family, int degree) {
  const auto* kernel = generated::find_polygon_edge_kernel<T>(family, degree);
  if (kernel == nullptr)
    throw std::invalid_argument("polygon: no generated kernel for " + std::string(family_name(family)) + " degree " +
                                std::to_string(degree));
  return *kernel;
}

/// The degrees the generated table offers for polygons, ascending
/// (the generator's defaults: inverse 3…12, cauchy 3…12, compact 4, 6, …, 12).
inline std::vector<int> polygon_supported_degrees(KernelFamily family) {
  std::vector<int> degrees;
  for (const auto& k : generated::polygon_edge_kernels<double>())
    if (k.family == family) degrees.push_back(k.degree);
  return degrees;
}

/// What the contour sums need of the polygon's kernel, from its trait
/// (kernel_list.hpp).
template <class T>
struct PolygonKernelForm {
  bool singular = false;        ///< K(0) = +inf (inverse): exact height near the plane, +inf on it
  bool finite_support = false;  ///< K = 0 beyond R (compact): the support ball's disc on the plane
  T alpha = T(1), beta = T(0);  ///< otherwise K = (α r² + β)^(−i/2) (the trait's quadratic_form)
};

/// The form of poly.family (the default form for a value that names no
/// family: the generated table has no kernel for it either).
template <class T>
PolygonKernelForm<T> polygon_kernel_form(const PolygonInput<T>& poly) {
  const auto form_of = [&](auto trait) {
    using K = typename decltype(trait)::type;
    PolygonKernelForm<T> form;
    form.singular = K::singular_at_zero;
    form.finite_support = K::finite_support;
    if constexpr (requires { K::quadratic_form(poly.s); }) {
      const std::array<T, 2> q = K::quadratic_form(poly.s);
      form.alpha = q[0];
      form.beta = q[1];
    }
    return form;
  };
  return kernels::read_trait<PolygonKernelForm<T>>(poly.family, form_of, PolygonKernelForm<T>{});
}

namespace detail {

/// Θ = Σ θ_m snapped to a multiple of 2π when it is one up to rounding.
template <class T>
T snap_winding_angle(const T& theta_sum) {
  using std::abs;
  using std::round;
  const T two_pi = 2 * std::numbers::pi_v<T>;
  const T turns = round(theta_sum / two_pi);
  return abs(theta_sum - turns * two_pi) <= T(1e-6) ? turns * two_pi : theta_sum;
}

/// f and/or ∇f (grad != nullptr) of the polygon at p; with edge_fields,
/// f by the contour sum (never the far field) and each edge's part of it.
template <class T>
T polygon_evaluate(const PolygonInput<T>& poly, const std::array<T, 3>& p, bool want_f, std::array<T, 3>* grad,
                   std::vector<T>* edge_fields = nullptr) {
  using std::abs;
  using std::sqrt;
  const generated::PolygonEdgeKernel<T>& kernel =
      poly.edge_kernel != nullptr ? *poly.edge_kernel : polygon_edge_kernel<T>(poly.family, poly.degree);
  const PolygonKernelForm<T> form = polygon_kernel_form(poly);
  const auto& n = poly.normal;
  const auto& v = poly.vertices;
  const std::size_t count = v.size();
  // The height above the plane; near it, for the inverse kernels (singular
  // there), from the exact vertices and P (skelconv/detail/plane_height.hpp).
  T z = plain_plane_height(p, v[0], n);
  if (form.singular && needs_exact_plane_height(z, p, v[0])) z = exact_plane_height(v, p);
  std::array<T, 3> foot, foot_lo;
  plane_foot(p, z, n, foot, foot_lo);
  const bool compact = form.finite_support;
  if (grad) *grad = {T(0), T(0), T(0)};
  if (!compact && edge_fields == nullptr) {
    std::array<T, 3> centre = {T(0), T(0), T(0)};
    for (const auto& q : v)
      for (int k = 0; k < 3; ++k) centre[k] += q[k] / T(count);
    T radius2 = 0, distance2 = 0;
    for (const auto& q : v)
      radius2 = std::max(radius2, (q[0] - centre[0]) * (q[0] - centre[0]) + (q[1] - centre[1]) * (q[1] - centre[1]) +
                                      (q[2] - centre[2]) * (q[2] - centre[2]));
    for (int k = 0; k < 3; ++k) distance2 += (p[k] - centre[k]) * (p[k] - centre[k]);
    // The kernel (α r² + β)^(−i/2) is singular at complex distance
    // √(r² + β/α): a wide Cauchy kernel (small s) is as smooth over the
    // polygon as a far point, and the fans cancel there just the same.
    const T alpha = form.alpha, beta = form.beta;
    const T ratio = T(polygon_far_field_ratio);
    if (distance2 + beta / alpha >= ratio * ratio * radius2)
      return polygon_far_field<T>(v, n, poly.degree, alpha, beta, p, grad);
  }
  if (compact && !(abs(z) < poly.R)) return T(0);  // the support ball misses the plane
  const T disc_radius = compact ? sqrt((poly.R - abs(z)) * (poly.R + abs(z))) : T(0);

  auto edge_function = want_f ? (grad ? kernel.f_and_grad : kernel.f) : kernel.grad;
  T theta_sum = 0, theta_in_sum = 0, S_f = 0, S_g = 0;
  bool on_boundary = false;
  std::vector<PolygonEdgeTerms<T>> all_terms;
  PolygonEdgeInput<T> in;
  in.p = foot;
  in.p_lo = foot_lo;
  in.point = p;
  in.normal = n;
  in.z = z;
  in.s = poly.s;
  in.R = poly.R;
  for (std::size_t m = 0; m < count; ++m) {
    in.a = v[m];
    in.b = v[(m + 1) % count];
    if (compact) {
      const auto clip = clip_to_ball(in.a, in.b, foot, disc_radius);
      // An edge that misses the disc still has its θ: [t0, t1] = [0, 0].
      in.t0 = clip ? clip->t0 : T(0);
      in.t1 = clip ? clip->t1 : T(0);
    }
    PolygonEdgeTerms<T> terms;
    edge_function(in, terms);
    if (edge_fields) all_terms.push_back(terms);
    if (terms.h == T(0)) {
      // P̄ on the edge's line: no fan triangle. On the closed edge itself?
      const T dot = (in.a[0] - foot[0]) * (in.b[0] - foot[0]) + (in.a[1] - foot[1]) * (in.b[1] - foot[1]) +
                    (in.a[2] - foot[2]) * (in.b[2] - foot[2]);
      on_boundary = on_boundary || dot <= T(0);
    } else {
      theta_sum += terms.theta;
      theta_in_sum += terms.theta_in;
      S_f += terms.S_f;
      S_g += terms.S_g;
    }
    if (grad) {
      // In-plane part: −(E × n) ∫ K over the edge (divergence theorem).
      const T e[3] = {in.b[0] - in.a[0], in.b[1] - in.a[1], in.b[2] - in.a[2]};
      (*grad)[0] -= (e[1] * n[2] - e[2] * n[1]) * terms.J_g;
      (*grad)[1] -= (e[2] * n[0] - e[0] * n[2]) * terms.J_g;
      (*grad)[2] -= (e[0] * n[1] - e[1] * n[0]) * terms.J_g;
    }
  }
  const T Theta = snap_winding_angle(theta_sum);
  const int i = poly.degree;
  T f = 0, dfdz = 0;
  if (compact) {
    // C = (R²/(2(j+1))) (w^(j+1) Θ − Σ G^(j+1)), ∂C/∂z = −z (w^j Θ − Σ G^(j)),
    // the θ_in parts of the G gathered with Θ first: the angle outside the
    // support disc, 0 when the disc holds the polygon.
    const int j = i / 2;
    const T R2 = poly.R * poly.R;
    const T w = (poly.R - abs(z)) * (poly.R + abs(z)) / R2;
    const T w_j = integer_power(w, j);
    const T outer_angle = Theta - theta_in_sum;
    f = R2 / T(2 * (j + 1)) * (w_j * w * outer_angle - S_f);
    dfdz = -z * (w_j * outer_angle - S_g);
    if (edge_fields)
      for (const auto& t : all_terms)
        edge_fields->push_back(t.h == T(0) ? T(0)
                                           : R2 / T(2 * (j + 1)) * (w_j * w * (t.theta - t.theta_in) - t.S_f));
  } else {
    if (form.singular && z == T(0) && (Theta != T(0) || on_boundary)) {
      const T inf = std::numeric_limits<T>::infinity();
      if (grad) *grad = {inf, inf, inf};
      return inf;
    }
    // C = (ζ^(2−i) Θ − Σ H_{i−2}) / (α(i − 2)), ∂C/∂z = −z (ζ^(−i) Θ − Σ H_i).
    const T alpha = form.alpha;
    const T zeta2 = alpha * z * z + form.beta;
    const T zeta = sqrt(zeta2);
    const T winding_f = Theta == T(0) ? T(0) : integer_power(zeta, 2 - i) * Theta;
    const T winding_g = Theta == T(0) ? T(0) : integer_power(zeta, -i) * Theta;
    f = (winding_f - S_f) / (alpha * T(i - 2));
    dfdz = -z * (winding_g - S_g);
    if (edge_fields)
      for (const auto& t : all_terms)
        edge_fields->push_back(
            t.h == T(0) ? T(0) : (integer_power(zeta, 2 - i) * t.theta - t.S_f) / (alpha * T(i - 2)));
  }
  if (grad)
    for (int k = 0; k < 3; ++k) (*grad)[k] += dfdz * n[k];
  return f;
}

}  // namespace detail

/// f(P). Inverse kernels with P in the closed polygon (z = 0, P̄ in Ω
/// or on its boundary) give +inf (the integral diverges there).
template <class T>
T polygon_f(const PolygonInput<T>& poly, const std::array<T, 3>& p) {
  return detail::polygon_evaluate<T>(poly, p, true, nullptr);
}

/// ∇f(P); (+inf, +inf, +inf) where f is +inf.
template <class T>
std::array<T, 3> polygon_grad(const PolygonInput<T>& poly, const std::array<T, 3>& p) {
  std::array<T, 3> grad;
  detail::polygon_evaluate<T>(poly, p, false, &grad);
  return grad;
}

/// Each edge's part of f(P), in the order of the vertices (edge m from
/// vertex m to m + 1): the field of the signed fan triangle (P̄, Q_m, Q_{m+1}).
/// For a triangle these are Sherstyuk's "three step functions" (Hubert 2012
/// §7, fig. 8). They add up to f(P) by the contour sum, which is what
/// polygon_f returns except far from the polygon (polygon_far_field.hpp)
/// and up to the rounding of Θ. Not for an inverse kernel with P in the
/// closed polygon (the parts are infinite there): throws std::domain_error.
template <class T>
std::vector<T> polygon_edge_fields(const PolygonInput<T>& poly, const std::array<T, 3>& p) {
  std::vector<T> parts;
  const T f = detail::polygon_evaluate<T>(poly, p, true, nullptr, &parts);
  if (parts.size() != poly.vertices.size()) {
    if (f == std::numeric_limits<T>::infinity())
      throw std::domain_error("polygon_edge_fields: P lies in the polygon, where the inverse kernel diverges");
    parts.assign(poly.vertices.size(), T(0));  // compact: the support misses the plane
  }
  return parts;
}

/// f(P) and ∇f(P) together.
template <class T>
T polygon_f_and_grad(const PolygonInput<T>& poly, const std::array<T, 3>& p, std::array<T, 3>& grad) {
  return detail::polygon_evaluate<T>(poly, p, true, &grad);
}

}  // namespace skelconv
