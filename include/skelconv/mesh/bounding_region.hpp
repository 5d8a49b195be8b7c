// skelconv/mesh/bounding_region.hpp — an axis-aligned box that contains the
// whole surface f = iso, found from the field alone (any skeleton scale).
//
// Every kernel decays away from its skeleton, so f < iso on the faces of a
// box large enough around the skeleton. The box is the skeleton's bounding
// box widened by a margin m: m starts at a quarter of the skeleton's
// diagonal (1 for a single point), is halved while f < iso at every sample
// of the six faces and doubled while not, and the smallest passing margin is
// then doubled once more, so that the faces stay about one surface thickness
// away from the surface (a bump of the surface narrower than the sample
// spacing would otherwise slip between samples). The faces are also sampled
// at their points nearest the skeleton points, where a small component far
// from the others bulges through them. docs/mesh.md discusses it.
#pragma once

#include "skelconv/geometry.hpp"
#include "skelconv/mesh/implicit_field.hpp"

namespace skelconv {

struct Box3 {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Zero();
  double diagonal() const { return (hi - lo).norm(); }
  bool contains(const Vec3& p) const {
    return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
  }
};

/// The bounding box of `points` (non-empty).
Box3 bounding_box(const std::vector<Vec3>& points);

struct BoundingRegionOptions {
  /// Samples per face side (n × n per face): the faces are checked at
  /// 6 n² points.
  int face_samples = 17;
  /// The margin is halved or doubled at most this many times (2^±200 spans
  /// every scale a double can hold around a skeleton).
  int max_rescalings = 200;
};

/// A box containing the surface f = iso of `field` (iso > field.far_field,
/// field.skeleton_points non-empty). Throws InputError located at "--iso"
/// if f ≥ iso on the faces of every box tried (the surface does not close).
Box3 bounding_region(const ImplicitField& field, double iso, const BoundingRegionOptions& options = {});

}  // namespace skelconv
