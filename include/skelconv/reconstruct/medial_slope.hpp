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
#pragma once

#include "skelconv/reconstruct/medial_mesh.hpp"

namespace skelconv::reconstruct {

/// Lowers radii of `mesh` until |r_u − r_v| ≤ slope × |c_u − c_v| along every
/// tube edge and triangle side: each radius becomes the smallest of r_v +
/// slope × (the length of a path of edges from it to v) over the spheres v,
/// its own radius included (the largest radii within the bound below the
/// given ones; the spheres' centres and the smallest radius stay). Same
/// mesh, same radii.
void limit_radius_slope(MedialMesh& mesh, double slope);

}  // namespace skelconv::reconstruct
