// skelconv/reconstruct/medial_slope.hpp — the radii of a medial mesh kept
// as a medial axis's are: no ball inside its neighbour's
// (docs/reconstruction_medial.md, "The fit").
//
// Along a medial axis the radius changes more slowly than the centre moves
// (|∇r| < 1: a ball inside its neighbour's touches the surface nowhere the
// neighbour does not). The fit moves centres and radii to lower a distance
// and knows nothing of this: on a primitive much shorter than its radius the
// field falls as the radius grows, so a radius can grow to several times its
// medial ball and its neighbour shrink, and a short edge becomes a cone far
// steeper than it is long. A SCALIS segment's surface falls short of such a
// cone near its thin end, and the part beyond (a toe, an arm) comes back
// detached. The fitted radii are therefore kept within `slope` × the
// centres' distance of each other along every edge of the mesh (tube edges
// and triangle sides).
//
// Given each centre's clearance (its distance to the input's surface), a
// pair out of the bound is mended from both ends where the input allows:
// the smaller ball first grows, as far as the bound asks but not past its
// clearance, then the larger shrinks by what is left. Shrinking alone sinks
// a broad sheet whose radius falls steeply to its rim, where the smaller
// balls are well inside the input; growing first cost as much elsewhere,
// so the fit shrinks only by default (MedialOptions::grow_within_input).
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "skelconv/reconstruct/medial_mesh.hpp"

namespace skelconv::reconstruct {

/// The distance from a point inside the input to the input's surface: the
/// radius of the largest ball about it inside the input.
using Clearance = std::function<double(const Vec3&)>;

/// Keeps |r_u − r_v| ≤ slope × |c_u − c_v| along every tube edge and
/// triangle side of `mesh`, the centres unmoved, in two passes:
///  1. with `clearance`, each radius below its centre's clearance c_v grows
///     to the largest of its own radius and min(c_v, r_u − slope × |c_u −
///     c_v|) over its neighbours u, their radii themselves grown this way
///     (never past c_v; a radius at or above c_v stays);
///  2. each radius becomes the smallest of r_v + slope × (the length of a
///     path of edges from it to v) over the spheres v, its own radius
///     included (the largest radii within the bound below those of pass 1;
///     the smallest radius stays).
/// Same mesh, same radii; radii already within the bound stay. With
/// `bounded_by`, it gets for each sphere the neighbour whose radius plus
/// slope × their distance its radius became in pass 2 (the edge it is at the
/// bound along), or the sphere itself where pass 2 left its radius: the
/// edges a step pushed past the bound (the fit's active set, medial_step.hpp).
void limit_radius_slope(MedialMesh& mesh, double slope, const Clearance& clearance = {},
                        std::vector<std::size_t>* bounded_by = nullptr);

}  // namespace skelconv::reconstruct
