// skelconv/reconstruct/surface_fit.hpp — the ends and the radii, fitted to
// the input surface (docs/reconstruction.md, "Ends and radii").
//
// Three things make a SCALIS surface around the medial skeleton miss the
// input, and each has a step here:
//   1. Caps. Where a tube ends, the medial axis bends into the cap (an
//      oblate cap has a medial *disc*, which the level-set graph follows
//      sideways) with radii falling fast. On the medial axis dr/ds = −cos α,
//      α the angle between the ball's contact points and the axis normal; a
//      steep fall means the contacts are on the cap, not on the tube.
//      trim_caps drops those end points (|dr/ds| > `max_slope`).
//   2. Ends. The trimmed axis stops about one radius short of the tip, and
//      a SCALIS segment's surface falls short of its radius near its end.
//      extend_free_ends adds one point beyond each free end along the end
//      tangent; fit_to_surface moves it until the reconstructed surface
//      reaches the input's tip on that line (the branch extension of the
//      issue; Zanni et al. §5.1 add point primitives instead).
//   3. Radii and centres. An empty Voronoi ball of a polyhedral sampling is
//      a little smaller than the tube, a finite SCALIS segment is thinner
//      than a long one, the sum blend bulges where branches meet, a
//      B-spline cuts corners (a ring shrinks), and a curved tube's section
//      is not a circle (a ring's field is stronger inside it). Each round,
//      fit_to_surface casts `directions` rays from every point in the plane
//      normal to the branch, to the input and to the reconstructed surface.
//      In a tube section (every ray meets the input, within `tube_ratio` of
//      each other) the radius is rescaled by (mean input distance / mean
//      reconstructed distance) and the centre moved by the first harmonic
//      of their difference; elsewhere (junctions, near caps) only the
//      radius, by the ratio of the nearest crossings. A SCALIS surface is
//      homothetic in its radii, so a uniform error is corrected in one
//      step; a few steps settle the rest.
#pragma once

#include <functional>
#include <vector>

#include "skelconv/reconstruct/branch_graph.hpp"
#include "skelconv/reconstruct/surface_query.hpp"
#include "skelconv/skeleton/skeleton.hpp"

namespace skelconv::reconstruct {

/// Drops points from every free end (a node that ends exactly one branch)
/// while the radius falls faster than `max_slope` per unit length towards
/// the end, or the last step turns back (its direction against the step
/// before it, an angle over 90°: on a noisy cap the last level-set piece
/// can lie on a sheet beside the axis, behind the end, and the end tangent
/// then points back into the tube); a branch keeps at least 2 points.
std::vector<Branch> trim_caps(std::vector<Branch> branches, double max_slope);

/// Appends (prepends) to every free end a point at `factor` × its radius
/// along the end tangent, at the end's radius, and marks it in
/// Branch::extended_first / extended_last. The tangent is the chord from
/// the point about one radius back along the branch.
std::vector<Branch> extend_free_ends(std::vector<Branch> branches, double factor);

struct FitOptions {
  int iterations = 4;      ///< rounds of (radii, end extensions) updates
  int directions = 8;      ///< rays per point in the plane normal to the branch
  /// One round changes a radius by at most this factor (either way), so a
  /// point whose surface is lost (a centre outside the current surface)
  /// recovers over a few rounds instead of jumping.
  double largest_step = 2.0;
  int bisection_steps = 30;  ///< crossing of the reconstructed surface
  /// A point is a tube section when all its rays meet the input within this
  /// ratio of each other (not a junction, where rays run down other
  /// branches, nor a cap); its centre is fitted too, not only its radius.
  double tube_ratio = 1.5;
  /// One round moves a centre by at most this × its radius.
  double largest_shift = 0.5;
};

/// The reconstructed field of a set of branches (reconstruct.cpp builds the
/// skeleton file; the fit does not need to know how).
using BranchField = std::function<Skeleton(const std::vector<Branch>&)>;

struct FitReport {
  double largest_radius_change = 0.0;  ///< last round, relative
  double largest_tip_change = 0.0;     ///< last round, in length units
};

/// Fits the radii and the end extensions of `branches` (from
/// extend_free_ends) to `input`. Points whose rays all miss the input
/// (outside it) keep their radius.
std::vector<Branch> fit_to_surface(std::vector<Branch> branches, const SurfaceQuery& input, const BranchField& field,
                                   const FitOptions& options, FitReport* report = nullptr);

}  // namespace skelconv::reconstruct
