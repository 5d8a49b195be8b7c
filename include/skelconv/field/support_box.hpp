// skelconv/field/support_box.hpp — an axis-aligned box holding a
// compact-support primitive's support, for the bounding-volume index
// (support_grid.hpp).
//
// The contract the index relies on for exactness: at every point OUTSIDE the
// box, the primitive's value_and_gradient() returns exactly 0 and (0, 0, 0),
// so skipping it changes no bit of a sum (docs/field.md, "Exactness").
// The box is the bounding box of the primitive's skeleton geometry grown by
// its support radius ρ plus a margin (support_margin below), so every point
// outside it is farther than ρ (1 + 1e-6) from the skeleton: far beyond the
// rounding of the primitives' own support tests.
//
// The box is also cut by a ball about the geometry's centroid (radius: the
// farthest vertex plus ρ and the same margin), under the same contract: a
// box's corners lie up to √3 ρ from the skeleton, and a point there costs a
// whole evaluation (the frame, the support test) only to return 0; the ball
// answers for it with one squared distance.
#pragma once

#include <limits>

#include <optional>

#include "skelconv/geometry.hpp"
#include "skelconv/primitives/primitive.hpp"

namespace skelconv {

struct SupportBox {
  Vec3 lo, hi;
  /// The ball |P − centre|² ≤ radius2 (the default: every point).
  Vec3 centre = Vec3::Zero();
  double radius2 = std::numeric_limits<double>::infinity();
  bool contains(const Vec3& p) const {
    return p.x() >= lo.x() && p.x() <= hi.x() && p.y() >= lo.y() && p.y() <= hi.y() && p.z() >= lo.z() &&
           p.z() <= hi.z() && (p - centre).squaredNorm() <= radius2;
  }
};

/// The margin added to a support radius ρ, for geometry of largest
/// coordinate magnitude `magnitude`: ρ · 1e-6 (a millionth of the support:
/// a relative error no double support test comes near) plus 1e-13 ·
/// magnitude (the rounding of the box corners themselves, ~1e-16 ·
/// magnitude, with three orders to spare).
inline double support_margin(double rho, double magnitude) { return rho * 1e-6 + magnitude * 1e-13; }

/// The support box of a finite-support primitive: every finite-support
/// family (compact, soft, wyvill, ferley: the trait's support radius ρ) on
/// segments, polygons and points, finite-support SCALIS segments and
/// triangles (ρ = σ · max τ: |P − Q| < σ τ(Q) ≤ σ max τ on the support).
/// std::nullopt for infinite support (inverse, Cauchy, Gaussian).
std::optional<SupportBox> support_box(const Primitive& primitive);

}  // namespace skelconv
