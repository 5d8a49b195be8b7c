// src/reconstruct/tube_ends.hpp — the medial mesh's tube ends extended by
// one sphere (docs/reconstruction_medial.md, "The medial mesh", step 4).
// Internal: the medial stage (medial_stage.cpp) is its one user.
#pragma once

#include <cstddef>
#include <functional>

#include <vector>

#include "skelconv/reconstruct/medial_mesh.hpp"
#include "skelconv/reconstruct/medial_quadric.hpp"

namespace skelconv::detail {

/// Each tube end (a sphere on one edge and no triangle) gets one more
/// sphere `factor` radii beyond it along the edge, at its radius: the
/// pruned medial axis stops about a radius short of a cap, and a SCALIS
/// segment's surface falls short of its radius near its end.
///
/// But a spike: a tip whose centre is less than `spike_depth` × its radius
/// deep (`depth`, the input's signed distance, negative outside) has a
/// ball reaching that far out of the input, no ball of it but the end of a
/// spike the medial axis sends towards a crease of the tessellation (Q-MAT
/// merges such balls up to its overhang), with no cap beyond. Where its
/// sphere beyond would be outside the input, it goes back along the edge
/// to the input's surface: a segment out to it would stick out of the
/// input as a spike of the reconstruction about one facet of the measuring
/// mesh thick, which the fit's points, a few facets apart, do not see (CGAL's
/// knot). It is moved, not dropped, so that the primitives are as many and
/// the medial mesh the same. The ends of tubes, whose balls are about as
/// deep as their radius, are extended as before, even where the sphere
/// beyond is just outside (a cap a radius ahead). Returns how many spheres
/// beyond were moved back (or left out, where none would be left of the
/// segment, or the tip itself is outside).
///
/// And a tapering tip: where a tube end is shallower than its radius and
/// the input goes on along the edge more than `taper_reach` times as far
/// as the sphere beyond, its depth falling gently to 0 on the way (a horn's
/// tip: the medial axis was pruned where it grew thinner than the samples'
/// spacing), the sphere beyond goes to where the input
/// ends along the edge instead, so that the segment reaches into the tip.
/// 0 turns it off.
///
/// And a bulb: a tube end whose radius exceeds its neighbour's by more
/// than `bulb_slope` × their distance (a round lobe reached through a
/// neck, whose ball the collapses kept at its centre) and whose sphere
/// beyond would be less than half its radius deep (the input ends about
/// where the tip's ball does: the ball is the cap). A segment out to a
/// sphere beyond there makes a capsule of the ball, up to a radius past
/// the input, and the fit, pulling that surface back, shrinks the tip's
/// radius with the sphere beyond's, the ball with it. It gets no sphere
/// beyond; a copy of its sphere is added as an isolated sphere (a point,
/// whose surface is that ball), so the primitives are as many.
/// `bulbs` (if set) gets how many. 0 turns it off.
std::size_t extend_tube_ends(reconstruct::MedialMesh& mesh, double factor, double spike_depth, double taper_reach,
                             double bulb_slope, const std::function<double(const Vec3&)>& depth,
                             std::size_t* bulbs = nullptr);

/// A sharp tip the simplified mesh still falls short of: for each point q
/// of `tips` (unreached_tips.hpp) whose nearest sphere (c, r) (the least
/// |q − c| − r) still falls short of it by at least `reach` and `thinness`
/// × r, a tube edge from that sphere towards q, ending `radius` short of q
/// (at most halfway) with a sphere of that radius. A cone's medial axis
/// runs on to its apex, its radius falling to 0; the samples' spacing
/// stops the medial graph about a spacing short of it (on a tip thinner
/// than the spacing, at balls barely inside the input), at a sheet's
/// corner or a tube end whose surface is round and about as wide as its
/// ball, and no fit brings a sharp tip out of that. Only a sharp tip: at
/// the new sphere's centre the input (`depth`, its signed distance) must be
/// less than half `radius` deep (a cone under 30° half-angle; a round end
/// is about `radius` deep there). The segment must run inside the input
/// (at 17 points). Elsewhere nothing is added. Returns how many edges were added (each
/// with one new sphere).
std::size_t reach_unreached_tips(reconstruct::MedialMesh& mesh, const std::vector<reconstruct::ReachPoint>& tips,
                                 double reach, double thinness, double radius,
                                 const std::function<double(const Vec3&)>& depth);

}  // namespace skelconv::detail
