// skelconv/reconstruct/skeleton_comparison.hpp — a recovered skeleton
// against the known one it was meshed from (branch count, junction
// positions, radii along branches; docs/reconstruction.md,
// "Against the known skeletons").
//
// The known skeleton is a set of SCALIS segments (a, b, r_a, r_b). Each
// recovered junction is matched to the nearest known junction (a point
// where three or more known segments meet); each recovered branch point
// (end extensions excepted: they are fitted to the surface's tip, not
// skeleton points) to the nearest point of the known skeleton, where the
// known radius is interpolated linearly along its segment. Both sides are
// SCALIS radii normalised the same way (f = iso at distance r from a long
// segment), so the fitted stage's radii are directly comparable.
#pragma once

#include <cstddef>
#include <vector>

#include "skelconv/reconstruct/branch_graph.hpp"
#include "skelconv/skeleton.hpp"

namespace skelconv::reconstruct {

/// One known SCALIS segment: end points and radii.
struct KnownSegment {
  Vec3 a, b;
  double radius_a = 0.0, radius_b = 0.0;
};

/// The SCALIS segments of `skeleton` (other primitives are ignored).
std::vector<KnownSegment> known_segments(const Skeleton& skeleton);

/// The points where three or more known segments meet: end points that
/// coincide within `tolerance` are one point.
std::vector<Vec3> known_junctions(const std::vector<KnownSegment>& known, double tolerance);

struct ErrorStatistics {
  double max = 0.0, mean = 0.0;
  std::size_t count = 0;
};

struct SkeletonComparison {
  ErrorStatistics junction;  ///< recovered junction → nearest known junction, distance
  ErrorStatistics axis;      ///< recovered branch point → nearest known skeleton point, distance
  ErrorStatistics radius;    ///< |r − known r| at that nearest point
  std::size_t known_junctions = 0;
};

/// Compares `branches` (a reconstruction stage) with `known`; end points of
/// the known segments within `tolerance` of each other are one point.
/// Recovered junctions are the branch end nodes shared by three or more
/// branch ends. With no known junction, `junction` stays empty (count 0).
SkeletonComparison compare_with_known(const std::vector<Branch>& branches, const std::vector<KnownSegment>& known,
                                      double tolerance);

}  // namespace skelconv::reconstruct
