// Implementation of skelconv/field/support_box.hpp.
#include "skelconv/field/support_box.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <type_traits>

#include "skelconv/kernels/kernel_list.hpp"

namespace skelconv {
namespace {

/// The bounding box of `points` grown by ρ and support_margin, and the ball
/// about their centroid c grown as much: a point X outside it has
/// |X − c| > reach + ρ + margin, reach = max |point − c|, so it is farther
/// than ρ + margin from the points' convex hull (which lies within reach of
/// c). The roundings of the squared distances and of the reach, a few
/// 1e-16 of |X − c| and of the magnitude, are far below the margin's
/// 1e-6 ρ + 1e-13 × magnitude.
SupportBox grown_bounding_box(std::span<const Vec3> points, double rho) {
  SupportBox box{points[0], points[0]};
  Vec3 sum = Vec3::Zero();
  for (const Vec3& p : points) {
    box.lo = box.lo.cwiseMin(p);
    box.hi = box.hi.cwiseMax(p);
    sum += p;
  }
  const double magnitude = std::max(box.lo.cwiseAbs().maxCoeff(), box.hi.cwiseAbs().maxCoeff());
  const double grow = rho + support_margin(rho, magnitude);
  box.lo -= Vec3::Constant(grow);
  box.hi += Vec3::Constant(grow);
  box.centre = sum / double(points.size());
  double reach = 0.0;
  for (const Vec3& p : points) reach = std::max(reach, (p - box.centre).norm());
  const double radius = reach + grow;
  box.radius2 = radius * radius;
  return box;
}

/// ρ of a classical kernel (segments, polygons): its trait's support radius,
/// +inf for infinite support. Every finite-support family counts (compact,
/// soft, wyvill, ferley), not one by name.
double kernel_support_radius(const KernelSpec& kernel) {
  return kernels::support_radius(kernels::make_radial_kernel(kernel));
}

/// Whether a SCALIS kernel K(d/σ) (the family's K at R = 1) vanishes beyond
/// d = σ τ: the family has finite support (its trait says so).
bool scalis_finite_support(KernelFamily family) { return kernels::family_facts(family).finite_support; }

}  // namespace

std::optional<SupportBox> support_box(const Primitive& primitive) {
  return std::visit(
      [](const auto& p) -> std::optional<SupportBox> {
        using P = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<P, Segment>) {
          const double rho = kernel_support_radius(p.kernel());
          if (!std::isfinite(rho)) return std::nullopt;
          const Vec3 ends[] = {p.a(), p.b()};
          return grown_bounding_box(ends, rho);
        } else if constexpr (std::is_same_v<P, Polygon>) {
          const double rho = kernel_support_radius(p.kernel());
          if (!std::isfinite(rho)) return std::nullopt;
          return grown_bounding_box(p.vertices(), rho);
        } else if constexpr (std::is_same_v<P, PointPrimitive>) {
          if (!std::isfinite(p.support_radius())) return std::nullopt;
          const Vec3 centre[] = {p.center()};
          return grown_bounding_box(centre, p.support_radius());
        } else if constexpr (std::is_same_v<P, ScalisSegment>) {
          if (!scalis_finite_support(p.kernel().family)) return std::nullopt;
          const Vec3 ends[] = {p.a(), p.b()};
          return grown_bounding_box(ends, p.kernel().sigma * std::max(p.tau0(), p.tau1()));
        } else {
          static_assert(std::is_same_v<P, ScalisTriangle>, "a new primitive type needs its support box");
          if (!scalis_finite_support(p.kernel().family)) return std::nullopt;
          const double tau = std::max({p.radii()[0], p.radii()[1], p.radii()[2]});
          return grown_bounding_box(p.vertices(), p.kernel().sigma * tau);
        }
      },
      primitive);
}

}  // namespace skelconv
