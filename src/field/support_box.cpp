// Implementation of skelconv/field/support_box.hpp.
#include "skelconv/field/support_box.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <type_traits>

namespace skelconv {
namespace {

/// The bounding box of `points` grown by ρ and support_margin.
SupportBox grown_bounding_box(std::span<const Vec3> points, double rho) {
  SupportBox box{points[0], points[0]};
  for (const Vec3& p : points) {
    box.lo = box.lo.cwiseMin(p);
    box.hi = box.hi.cwiseMax(p);
  }
  const double magnitude = std::max(box.lo.cwiseAbs().maxCoeff(), box.hi.cwiseAbs().maxCoeff());
  const double grow = rho + support_margin(rho, magnitude);
  box.lo -= Vec3::Constant(grow);
  box.hi += Vec3::Constant(grow);
  return box;
}

}  // namespace

std::optional<SupportBox> support_box(const Primitive& primitive) {
  return std::visit(
      [](const auto& p) -> std::optional<SupportBox> {
        using P = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<P, Segment>) {
          if (p.kernel().family != KernelFamily::compact) return std::nullopt;
          const Vec3 ends[] = {p.a(), p.b()};
          return grown_bounding_box(ends, p.kernel().R);
        } else if constexpr (std::is_same_v<P, Polygon>) {
          if (p.kernel().family != KernelFamily::compact) return std::nullopt;
          return grown_bounding_box(p.vertices(), p.kernel().R);
        } else if constexpr (std::is_same_v<P, PointPrimitive>) {
          if (!std::isfinite(p.support_radius())) return std::nullopt;
          const Vec3 centre[] = {p.center()};
          return grown_bounding_box(centre, p.support_radius());
        } else if constexpr (std::is_same_v<P, ScalisSegment>) {
          if (p.kernel().family != KernelFamily::compact) return std::nullopt;
          const Vec3 ends[] = {p.a(), p.b()};
          return grown_bounding_box(ends, p.kernel().sigma * std::max(p.tau0(), p.tau1()));
        } else {
          static_assert(std::is_same_v<P, ScalisTriangle>, "a new primitive type needs its support box");
          if (p.kernel().family != KernelFamily::compact) return std::nullopt;
          const double tau = std::max({p.radii()[0], p.radii()[1], p.radii()[2]});
          return grown_bounding_box(p.vertices(), p.kernel().sigma * tau);
        }
      },
      primitive);
}

}  // namespace skelconv
