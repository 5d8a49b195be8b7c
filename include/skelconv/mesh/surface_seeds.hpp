// skelconv/mesh/surface_seeds.hpp — points on every component of the
// surface f = iso, for the mesher to start from.
//
// CGAL's own initial points come from random rays through a bounding
// sphere, which miss small separate pieces. Here every skeleton point where
// f > iso shoots six axis-aligned rays (±x, ±y, ±z): each ray is walked in
// doubling steps from `spacing` until f < iso, and the crossing is then
// bisected. A component of {f > iso} that contains a skeleton point
// therefore receives up to six surface points, around it, which is what the
// Delaunay refinement needs to see the component (docs/mesh.md, "Seeding").
// Skeleton points closer than `spacing` to an already used one (same cell
// of a grid of that spacing) shoot no rays of their own, which bounds the
// cost on long or dense skeletons. A crossing closer than `separation` ×
// `spacing` to a seed of an earlier skeleton point is dropped: two seeds a
// hair apart force the Delaunay refinement to grade from that distance up to
// the facet size, thousands of needless triangles (the crossings of one
// skeleton point are all kept, so a component smaller than the spacing
// still gets its six).
#pragma once

#include <vector>

#include "skelconv/geometry.hpp"
#include "skelconv/mesh/bounding_region.hpp"
#include "skelconv/mesh/implicit_field.hpp"

namespace skelconv {

struct SurfaceSeedOptions {
  /// Grid spacing for thinning the skeleton points, and first ray step.
  double spacing = 0.0;
  /// Bisection stops when the crossing is bracketed to this fraction of
  /// `spacing` (the mesher only needs points near the surface; every final
  /// vertex is projected exactly afterwards).
  double bracket_fraction = 1e-4;
  /// Smallest distance between seeds of different skeleton points, as a
  /// fraction of `spacing`.
  double separation = 0.5;
  /// Threads casting the rays (0: every core); the seeds are the same for
  /// any count.
  unsigned threads = 0;
};

/// Surface points of `field` at `iso` inside `box`. Throws InputError
/// located at "--iso" when no skeleton point has f > iso ("no surface").
std::vector<Vec3> surface_seeds(const ImplicitField& field, double iso, const Box3& box,
                                const SurfaceSeedOptions& options);

/// Seeds for a mesher that follows a surface from any one point of it (the
/// grid method's continuation), where the rays of every skeleton point
/// would mostly land on surfaces an earlier point's rays already seeded.
/// The skeleton points where f > iso are joined into regions: each to its
/// nearest earlier such point within 4 `spacing`s when f ≥ iso at every
/// node of the grid (spacing `spacing` from box.lo, the grid method's) on
/// a path of face neighbours between their nearest nodes: the same piece
/// of the grid's inside (not for a field infinite on its skeleton, whose
/// markers f = +inf say nothing of the pieces). Only the first ray source
/// of each region (surface_seeds' thinning) casts its six rays; the
/// region's other sources are `deferred`: their rays would start inside a
/// piece already seeded. The mesher casts them (seeds_from_points) where
/// the mesh it made has no vertex near them, so that a part the region's
/// first rays did not reach (a cavity) is still seeded.
struct RegionSeeds {
  std::vector<Vec3> seeds;
  std::vector<Vec3> deferred;
};

/// As surface_seeds, the same checks and errors, with one ray source per
/// region (RegionSeeds).
RegionSeeds region_seeds(const ImplicitField& field, double iso, const Box3& box, const SurfaceSeedOptions& options);

/// The crossings of the six rays from each of `points` (f > iso at each),
/// dropping those within `separation` × `spacing` of `existing` or of a
/// crossing of an earlier point, as surface_seeds does.
std::vector<Vec3> seeds_from_points(const ImplicitField& field, double iso, const Box3& box,
                                    const std::vector<Vec3>& points, const std::vector<Vec3>& existing,
                                    const SurfaceSeedOptions& options);

}  // namespace skelconv
