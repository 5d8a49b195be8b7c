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

}  // namespace skelconv
