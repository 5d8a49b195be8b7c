// skelconv/reconstruct/pavlidis.hpp — polyline simplification by the split
// phase of Pavlidis's algorithm (Ferley 1996 §3.1.2, fig. 3.1).
//
// Recursive split with fixed end points: on a run [i, j] of the polyline,
// find the vertex farthest from the chord P_i P_j; if its distance exceeds
// the tolerance keep it and recurse on both halves, else keep only P_i, P_j.
// The distance is to the chord as a *segment* (to the nearer end past either
// end), so a closed branch (P_0 = P_n) is split too. Ferley computes it in 4-D,
// (x, y, z, r), so that a change of radius is kept like a bend; with
// Dimension::space the radius is ignored (for comparison).
#pragma once

#include <vector>

#include "skelconv/reconstruct/branch_graph.hpp"

namespace skelconv::reconstruct {

enum class PavlidisDimension { space_and_radius, space };

/// The kept vertices of `points` (first and last always kept), in order.
/// `tolerance` ≥ 0 is absolute: Ferley's ε times the skeleton's size (the
/// largest extent of its bounding box).
std::vector<Vec4> pavlidis_split(const std::vector<Vec4>& points, double tolerance,
                                 PavlidisDimension dimension = PavlidisDimension::space_and_radius);

}  // namespace skelconv::reconstruct
