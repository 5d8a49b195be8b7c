// src/reconstruct/unreached_tips.hpp — the samples at the ends of thin
// protrusions that the pruned medial graph's balls fall short of
// (docs/reconstruction_medial.md, "Tips the collapses shortened").
// Internal: the medial stage (medial_stage.cpp) gives them to the
// simplification (QuadricOptions::reach_points).
#pragma once

#include <vector>

#include "skelconv/reconstruct/medial_graph.hpp"
#include "skelconv/reconstruct/medial_quadric.hpp"

namespace skelconv::detail {

/// For each sample q of `graph`, its gap: how far the nearest ball falls
/// short of it, min over the vertices of |q − c| − r. Pruning drops the
/// thin end of a protrusion's medial axis (its balls see their samples
/// under a small angle), so a horn's tip keeps a gap of about the length
/// pruned off. A sample is an unreached tip where its gap is at least
/// `reach` (absolute) and at least `thinness` × the radius of the ball
/// falling shortest of it: the part beyond that ball is longer than it is
/// thick (a cone under 30° half-angle for `thinness` 1). Each such ball
/// gets its one farthest sample (a ReachPoint), at most one per ball, and
/// keeps it only where no other ball's is within `apart`: a protrusion
/// ends in a point, and unreached samples close together are a hole that
/// a wall thinner than the samples' spacing left in its sheet (CGAL's
/// rotor: five within 0.04 of each other, a spacing 0.035) or a rim.
/// Same graph, same points, in vertex order.
std::vector<reconstruct::ReachPoint> unreached_tips(const reconstruct::MedialGraph& graph, double reach,
                                                    double thinness, double apart);

}  // namespace skelconv::detail
