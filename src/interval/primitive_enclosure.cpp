// Enclosures of single primitives over a box (skelconv/interval/enclosure.hpp).
// Compiled with -frounding-math in the OBJECT library skelconv_interval.
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <type_traits>

#include "skelconv/interval/enclosure.hpp"
#include "skelconv/interval/kernel_range.hpp"
#include "skelconv/kernels/kernel_list.hpp"
#include "../detail/infinity.hpp"

namespace skelconv::interval {
namespace {

IntervalPoint lerp(const IntervalPoint& a, const IntervalPoint& b, const Interval& t) {
  return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
}
IntervalPoint midpoint(const IntervalPoint& a, const IntervalPoint& b) {
  return {(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0, (a[2] + b[2]) / 2.0};
}

/// [min, max] of the distance from the box to a convex piece given by its
/// vertices (interval points): min from the box to the vertices' bounding
/// box, max over box corners and vertices (a convex function of P and Q
/// reaches its maximum at extreme points).
template <std::size_t N>
Interval distance_range(const Box& box, const std::array<IntervalPoint, N>& vertices) {
  IntervalPoint bounds = vertices[0];
  for (std::size_t k = 1; k < N; ++k)
    for (int i = 0; i < 3; ++i) bounds[i] = hull(bounds[i], vertices[k][i]);
  const double min_sq = squared_distance(to_interval_point(box), bounds).lower();
  double max_sq = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 c((corner & 1) ? box.hi.x() : box.lo.x(), (corner & 2) ? box.hi.y() : box.lo.y(),
                 (corner & 4) ? box.hi.z() : box.lo.z());
    for (const IntervalPoint& v : vertices) max_sq = std::max(max_sq, squared_distance(to_interval_point(c), v).upper());
  }
  return interval_sqrt(Interval(min_sq, max_sq));
}

/// K(d/(σ τ)) / τ^power over d ∈ r, τ ∈ tau (τ ≥ 0), for the SCALIS pieces
/// (power 1 on segments, 2 on triangles; i the kernel's degree).
///
/// Where τ reaches 0 (a tip of radius 0), 1/τ is unbounded but the kernel
/// vanishes faster: with y = d/(στ), K/τ^p = (σ/d)^p y^p K(y), and every
/// SCALIS kernel has K(y) ≤ y^(−i) (inverse: equal; Cauchy:
/// (1 + y²)^(−i/2) ≤ y^(−i); compact: ≤ 1 ≤ y^(−i) for y < 1, else 0), so
/// y^p K(y) ≤ y^(p−i), non-increasing for i ≥ p: at most y_min^(p−i).
template <class Kernel>
Interval scaled_kernel(const Kernel& kernel, const Interval& r, const Interval& tau, double sigma, int power,
                       int degree) {
  const double y_low = (Interval(r.lower()) / (Interval(sigma) * tau.upper())).lower();
  const double y_high = tau.lower() > 0.0 ? (Interval(r.upper()) / (Interval(sigma) * tau.lower())).upper() : infinity;
  const Interval k = kernel_range(kernel, Interval(std::max(0.0, y_low), y_high));
  if (tau.lower() <= 0.0) {
    if (k.upper() == 0.0) return Interval(0.0);
    if (!(r.lower() > 0.0 && y_low > 0.0) || degree < power) return Interval(0.0, infinity);
    const Interval scale = boost::numeric::pow(Interval(sigma) / r.lower(), power);
    const Interval tail = boost::numeric::pow(1.0 / Interval(y_low), degree - power);
    return Interval(0.0, (scale * tail).upper());
  }
  const Interval inverse_tau = 1.0 / tau;
  return k * (power == 1 ? inverse_tau : inverse_tau * inverse_tau);
}

std::size_t segment_pieces(double length, const Box& box, const EnclosureOptions& options) {
  const double diagonal = box.diagonal();
  if (!(diagonal > 0.0)) return options.max_segment_pieces;
  const double wanted = std::ceil(options.pieces_per_box * length / diagonal);
  return std::size_t(std::clamp(wanted, 1.0, double(options.max_segment_pieces)));
}

/// Σ over the pieces [t_j, t_j+1] of a segment A→B of term(piece ends, t).
template <class Term>
Interval sum_over_segment(const Vec3& a, const Vec3& b, const Box& box, const EnclosureOptions& options, Term term) {
  const IntervalPoint pa = to_interval_point(a), pb = to_interval_point(b);
  const std::size_t pieces = segment_pieces((b - a).norm(), box, options);
  Interval total(0.0);
  for (std::size_t j = 0; j < pieces; ++j) {
    const Interval t0 = Interval(double(j)) / double(pieces), t1 = Interval(double(j + 1)) / double(pieces);
    const std::array<IntervalPoint, 2> ends{lerp(pa, pb, t0), lerp(pa, pb, t1)};
    total += term(distance_range(box, ends), hull(t0, t1), t1 - t0);
    if (total.upper() == infinity && total.lower() == -infinity) break;
  }
  return total;
}

/// A triangle with an interval attribute (the SCALIS radius) at its vertices.
struct Corner {
  IntervalPoint p;
  Interval tau;
};

int triangle_levels(const std::array<Vec3, 3>& v, const Box& box, const EnclosureOptions& options) {
  const double diameter = std::max({(v[1] - v[0]).norm(), (v[2] - v[1]).norm(), (v[0] - v[2]).norm()});
  int levels = 0;
  for (double size = diameter; size > box.diagonal() && levels < options.max_triangle_levels; size /= 2) ++levels;
  return levels;
}

/// Calls leaf(distance range, τ range) on each of the 4^levels pieces.
void for_each_piece(const Box& box, const std::array<Corner, 3>& t, int levels,
                    const std::function<void(const Interval&, const Interval&)>& leaf) {
  if (levels == 0) {
    const std::array<IntervalPoint, 3> points{t[0].p, t[1].p, t[2].p};
    leaf(distance_range(box, points), hull(hull(t[0].tau, t[1].tau), t[2].tau));
    return;
  }
  const auto mid = [&](int i, int j) { return Corner{midpoint(t[i].p, t[j].p), (t[i].tau + t[j].tau) / 2.0}; };
  const Corner m01 = mid(0, 1), m12 = mid(1, 2), m20 = mid(2, 0);
  for (const auto& piece : {std::array<Corner, 3>{t[0], m01, m20}, std::array<Corner, 3>{m01, t[1], m12},
                            std::array<Corner, 3>{m20, m12, t[2]}, std::array<Corner, 3>{m01, m12, m20}}) {
    for_each_piece(box, piece, levels - 1, leaf);
  }
}

/// The area |(B − A) × (C − A)|/2 of a triangle, enclosed, and the sign of
/// its orientation along `normal` (+1, −1, or 0 when not certain).
std::pair<Interval, int> triangle_area(const std::array<Vec3, 3>& v, const Vec3& normal) {
  const IntervalPoint a = to_interval_point(v[0]), b = to_interval_point(v[1]), c = to_interval_point(v[2]);
  const IntervalPoint u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const IntervalPoint cross{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
  const Interval area = interval_sqrt(interval_square(cross[0]) + interval_square(cross[1]) +
                                      interval_square(cross[2])) / 2.0;
  const Interval along = cross[0] * normal.x() + cross[1] * normal.y() + cross[2] * normal.z();
  return {area, along.lower() > 0.0 ? 1 : along.upper() < 0.0 ? -1 : 0};
}

/// ∫_T g over a triangle whose pieces contribute piece_area · term(r, τ).
template <class Term>
Interval triangle_integral(const std::array<Vec3, 3>& v, const std::array<double, 3>& tau, const Interval& area,
                           const Box& box, const EnclosureOptions& options, Term term) {
  const int levels = triangle_levels(v, box, options);
  const Interval piece_area = area / std::pow(4.0, levels);  // exact division by a power of 2
  Interval total(0.0);
  const std::array<Corner, 3> corners{Corner{to_interval_point(v[0]), Interval(tau[0])},
                                      Corner{to_interval_point(v[1]), Interval(tau[1])},
                                      Corner{to_interval_point(v[2]), Interval(tau[2])}};
  for_each_piece(box, corners, levels, [&](const Interval& r, const Interval& t) {
    total += safe_product(piece_area, term(r, t));
  });
  return total;
}

Interval enclose_point(const PointPrimitive& point, const Box& box) {
  const Interval r = interval_sqrt(squared_distance(box, point.center()));
  const Interval k = std::visit([&](const auto& kernel) { return kernel_range(kernel, r); }, point.radial_kernel());
  return safe_product(Interval(point.weight()), k);
}

Interval enclose_segment(const Segment& segment, const Box& box, const EnclosureOptions& options) {
  const kernels::RadialKernel kernel = kernels::make_radial_kernel(segment.kernel());
  const IntervalPoint a = to_interval_point(segment.a()), b = to_interval_point(segment.b());
  const Interval length = interval_sqrt(squared_distance(a, b));
  const std::span<const double> w = segment.weight();
  return sum_over_segment(segment.a(), segment.b(), box, options, [&](const Interval& r, const Interval& t, const Interval& dt) {
    Interval weight(w.back());  // Horner on the piece's t interval
    for (std::size_t k = w.size() - 1; k-- > 0;) weight = weight * t + w[k];
    const Interval k_range = std::visit([&](const auto& kk) { return kernel_range(kk, r); }, kernel);
    return safe_product(length * dt * weight, k_range);
  });
}

/// The radial trait equal to a SCALIS kernel of scale 1 (K(y) with y = d/σ).
kernels::RadialKernel scalis_trait(const ScalisKernel& kernel) {
  KernelSpec spec{kernel.family, kernel.degree, 1.0, 1.0};
  return kernels::make_radial_kernel(spec);
}

Interval enclose_scalis_segment(const ScalisSegment& s, const Box& box, const EnclosureOptions& options) {
  const kernels::RadialKernel kernel = scalis_trait(s.kernel());
  const Interval length = interval_sqrt(squared_distance(to_interval_point(s.a()), to_interval_point(s.b())));
  const double sigma = s.kernel().sigma;
  const Interval F = sum_over_segment(s.a(), s.b(), box, options, [&](const Interval& r, const Interval& t, const Interval& dt) {
    const Interval tau = s.tau0() + t * (Interval(s.tau1()) - s.tau0());
    const Interval tau_pos(std::max(0.0, tau.lower()), std::max(0.0, tau.upper()));
    return safe_product(length * dt, std::visit([&](const auto& kk) { return scaled_kernel(kk, r, tau_pos, sigma, 1, s.kernel().degree); }, kernel));
  });
  const double h = ScalisSegment::normalisation(s.kernel().family, s.kernel().degree, sigma);
  return safe_product(Interval(s.iso()) / h, F);
}

Interval enclose_scalis_triangle(const ScalisTriangle& s, const Box& box, const EnclosureOptions& options) {
  const kernels::RadialKernel kernel = scalis_trait(s.kernel());
  const double sigma = s.kernel().sigma;
  const Interval area = triangle_area(s.vertices(), Vec3::UnitZ()).first;
  const Interval F = triangle_integral(s.vertices(), s.radii(), area, box, options, [&](const Interval& r, const Interval& tau) {
    const Interval tau_pos(std::max(0.0, tau.lower()), std::max(0.0, tau.upper()));
    return std::visit([&](const auto& kk) { return scaled_kernel(kk, r, tau_pos, sigma, 2, s.kernel().degree); }, kernel);
  });
  const double h = ScalisTriangle::normalisation(s.kernel().family, s.kernel().degree, sigma);
  return safe_product(Interval(s.iso()) / h, F);
}

Interval enclose_polygon(const Polygon& polygon, const Box& box, const EnclosureOptions& options) {
  const kernels::RadialKernel kernel = kernels::make_radial_kernel(polygon.kernel());
  const std::vector<Vec3>& v = polygon.vertices();
  Interval total(0.0);
  for (std::size_t j = 1; j + 1 < v.size(); ++j) {  // the fan v0, v_j, v_j+1 with signed areas
    const std::array<Vec3, 3> triangle{v[0], v[j], v[j + 1]};
    const auto [area, sign] = triangle_area(triangle, polygon.normal());
    const Interval integral = triangle_integral(triangle, {1.0, 1.0, 1.0}, area, box, options,
                                                [&](const Interval& r, const Interval&) {
                                                  return std::visit([&](const auto& kk) { return kernel_range(kk, r); }, kernel);
                                                });
    total += sign > 0 ? integral : sign < 0 ? -integral : hull(-integral, integral);
  }
  return total;
}

/// g(r) = K'(r)/r at one distance r > 0, enclosed.
template <class Kernel>
Interval slope_over_distance(const Kernel& kernel, double r) {
  return kernel.derivative(Interval(r)) / Interval(r);
}

}  // namespace

std::optional<IntervalPoint> enclose_gradient(const Primitive& primitive, const Box& box) {
  const PointPrimitive* point = std::get_if<PointPrimitive>(&primitive);
  if (point == nullptr) return std::nullopt;
  const Interval r = interval_sqrt(squared_distance(box, point->center()));
  const IntervalPoint offset = to_interval_point(box);
  if (!(r.lower() > 0.0)) {
    return IntervalPoint{Interval(-infinity, infinity), Interval(-infinity, infinity), Interval(-infinity, infinity)};
  }
  const Interval g = std::visit(
      [&](const auto& kernel) {
        const double high = r.upper() == infinity ? 0.0 : slope_over_distance(kernel, r.upper()).upper();
        return Interval(slope_over_distance(kernel, r.lower()).lower(), std::min(0.0, high));
      },
      point->radial_kernel());
  IntervalPoint gradient;
  for (int i = 0; i < 3; ++i) gradient[i] = Interval(point->weight()) * g * (offset[i] - point->center()[i]);
  return gradient;
}

Interval enclose(const Primitive& primitive, const Box& box, const EnclosureOptions& options) {
  return std::visit(
      [&](const auto& p) -> Interval {
        using P = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<P, PointPrimitive>) return enclose_point(p, box);
        else if constexpr (std::is_same_v<P, Segment>) return enclose_segment(p, box, options);
        else if constexpr (std::is_same_v<P, Polygon>) return enclose_polygon(p, box, options);
        else if constexpr (std::is_same_v<P, ScalisSegment>) return enclose_scalis_segment(p, box, options);
        else return enclose_scalis_triangle(p, box, options);
      },
      primitive);
}

}  // namespace skelconv::interval
