// Implementation of skelconv/reconstruct/medial_derivatives.hpp.
#include "skelconv/reconstruct/medial_derivatives.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "skelconv/errors.hpp"

namespace skelconv::reconstruct {
namespace {

/// m of the compact kernel (1 − d²/σ²)^m, or InputError.
int compact_half_degree(const ScalisKernel& kernel) {
  if (kernel.family != KernelFamily::compact || kernel.degree % 2 != 0)
    throw InputError(fmt::format("the medial fit's derivatives need a compact kernel of even degree, got degree {} of "
                                 "another family or odd",
                                 kernel.degree),
                     "kernel");
  return kernel.degree / 2;
}

/// x^k for a small k ≥ 0 (std::pow is the fit's hottest call otherwise).
double power(double x, int k) {
  double result = 1.0;
  for (int i = 0; i < k; ++i) result *= x;
  return result;
}

/// ∫ ((w² − t²)/R²)^m (α + β t) dt over [t0, t1], expanded in powers of t.
double polynomial_integral(int m, double w2, double r2, double alpha, double beta, double t0, double t1) {
  double sum = 0.0, binomial = 1.0;  // C(m, j)
  for (int j = 0; j <= m; ++j) {
    // C(m, j) w^{2(m−j)} (−t²)^j, times α + β t.
    const double c = binomial * power(w2, m - j) * (j % 2 == 0 ? 1.0 : -1.0);
    const int even = 2 * j + 1, odd = 2 * j + 2;
    sum += c * (alpha * (power(t1, even) - power(t0, even)) / even + beta * (power(t1, odd) - power(t0, odd)) / odd);
    binomial = binomial * (m - j) / (j + 1);
  }
  return sum / power(r2, m);
}

/// ∫ over the edge from `from` (λ = 1) to `to` (λ = 0) of K(|P − Q|/τ) λ(Q) ds,
/// K = (1 − d²/σ²)^m clipped to its support |P − Q| < στ.
double weighted_edge_integral(const Vec3& p, const Vec3& from, const Vec3& to, double support, int m) {
  const Vec3 edge = to - from;
  const double length = edge.norm();
  const Vec3 u = edge / length;
  const double s0 = (p - from).dot(u);
  const double r2 = support * support;
  const double w2 = r2 - ((p - from) - s0 * u).squaredNorm();
  if (!(w2 > 0.0)) return 0.0;
  const double w = std::sqrt(w2);
  // t = s − s0 over the edge ∩ the support; λ = 1 − s/L = (1 − s0/L) − t/L.
  const double t0 = std::max(-s0, -w), t1 = std::min(length - s0, w);
  if (!(t1 > t0)) return 0.0;
  return polynomial_integral(m, w2, r2, 1.0 - s0 / length, -1.0 / length, t0, t1);
}

/// K(|x|/τ) for the compact kernel of half degree m and scale σ.
double compact_kernel(const Vec3& x, double tau, double sigma, int m) {
  const double q = 1.0 - x.squaredNorm() / (sigma * sigma * tau * tau);
  return q > 0.0 ? power(q, m) : 0.0;
}

}  // namespace

PrimitiveDerivatives<3> derivatives(const ScalisTriangle& triangle, const Vec3& p) {
  const int m = compact_half_degree(triangle.kernel());
  const std::array<double, 3>& radii = triangle.radii();
  if (radii[0] != radii[1] || radii[0] != radii[2])
    throw InputError("the medial fit's derivatives need a triangle of constant radius", "radius");
  const double tau = radii[0], sigma = triangle.kernel().sigma;
  const std::array<Vec3, 3>& v = triangle.vertices();
  PrimitiveDerivatives<3> d;
  d.field = triangle.value_and_gradient(p);
  const Vec3& gradient = d.field.gradient;
  const Vec3 doubled_normal = (v[1] - v[0]).cross(v[2] - v[0]);
  const double doubled_area = doubled_normal.norm();
  const Vec3 n = doubled_normal / doubled_area;
  const double height = (p - v[0]).dot(n);
  // f = iso F / h, and g = K / τ² inside F.
  const double scale = triangle.iso() / triangle.normalisation() / (tau * tau);
  for (int i = 0; i < 3; ++i) {
    const Vec3 &vi = v[std::size_t(i)], &vj = v[std::size_t((i + 1) % 3)], &vk = v[std::size_t((i + 2) % 3)];
    // In the plane: the two edges at v_i, each with its outward normal.
    Vec3 in_plane = Vec3::Zero();
    for (const Vec3* other : {&vj, &vk}) {
      const Vec3& apex = other == &vj ? vk : vj;  // the vertex off this edge
      const Vec3 u = (*other - vi).normalized();
      const Vec3 inward = (apex - vi) - (apex - vi).dot(u) * u;
      in_plane -= inward.normalized() * weighted_edge_integral(p, vi, *other, sigma * tau, m);
    }
    // Across the plane: the rotation about an axis in the plane.
    const Vec3 slope = n.cross(vk - vj) / doubled_area;  // ∇λ_i
    const double lambda = 1.0 + slope.dot(p - vi);
    d.vertex[std::size_t(i)] = scale * in_plane + (-lambda * n.dot(gradient) + height * slope.dot(gradient)) * n;
  }
  double euler = 0.0;
  for (int i = 0; i < 3; ++i) euler += (v[std::size_t(i)] - p).dot(d.vertex[std::size_t(i)]);
  d.radius[0] = -euler / tau;
  return d;
}

PrimitiveDerivatives<2> derivatives(const ScalisSegment& segment, const Vec3& p) {
  const int m = compact_half_degree(segment.kernel());
  const double sigma = segment.kernel().sigma;
  const Vec3 &a = segment.a(), &b = segment.b();
  const double tau0 = segment.tau0(), tau1 = segment.tau1();
  PrimitiveDerivatives<2> d;
  d.field = segment.value_and_gradient(p);
  const Vec3& gradient = d.field.gradient;
  // ∂f/∂τ by forward differences of the segment itself.
  constexpr double relative_step = 1e-6;  // ~1e-6 relative error, far below the fit's needs
  const double h0 = relative_step * tau0, h1 = relative_step * tau1;
  d.radius[0] = (ScalisSegment(a, b, tau0 + h0, tau1, segment.kernel(), segment.iso()).value(p) - d.field.value) / h0;
  d.radius[1] = (ScalisSegment(a, b, tau0, tau1 + h1, segment.kernel(), segment.iso()).value(p) - d.field.value) / h1;
  const double length = (b - a).norm();
  const Vec3 u = (b - a) / length;
  const Eigen::Matrix3d across = Eigen::Matrix3d::Identity() - u * u.transpose();
  const double scale = segment.iso() / segment.normalisation();
  const double slope = (tau1 - tau0) / length;
  const Vec3 from_a = p - a, from_b = p - b;
  // Across: rotations about the other end; along: lengthening.
  d.vertex[1] = across * (-gradient * u.dot(from_a) + u.dot(gradient) * from_a) / length +
                (scale * compact_kernel(from_b, tau1, sigma, m) / tau1 - slope * d.radius[1]) * u;
  d.vertex[0] = across * (gradient * u.dot(from_b) - u.dot(gradient) * from_b) / length +
                (-scale * compact_kernel(from_a, tau0, sigma, m) / tau0 - slope * d.radius[0]) * u;
  return d;
}

PrimitiveDerivatives<1> derivatives(const PointPrimitive& point, double rho, const Vec3& p) {
  PrimitiveDerivatives<1> d;
  d.field = point.value_and_gradient(p);
  d.vertex[0] = -d.field.gradient;
  d.radius[0] = -(p - point.center()).dot(d.field.gradient) / rho;
  return d;
}

}  // namespace skelconv::reconstruct
