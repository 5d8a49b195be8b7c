// skelconv/reconstruct/branch_graph.hpp — from the inner Voronoi graph to a
// curve skeleton, and that curve skeleton as branches (Ferley 1996 §3.1.1).
//
// The inner Voronoi graph of a sampled tube is not a curve: it is a tangle
// of short edges around the axis (a Voronoi edge per interior Delaunay
// facet). Ferley works on a "squelette filiforme"; we reduce the tangle to
// one with a level-set graph (Lazarus & Verroust 1999): graph distances d
// (Dijkstra, edge length = distance between the ball centres) from a root
// taken at an extremity (the vertex farthest from vertex 0), sliced into
// bins of width `bin_width`; every connected piece of a bin becomes a node
// at the mean centre and mean radius of its largest balls (ρ ≥
// `core_fraction` × the piece's largest ρ: the balls near the axis, not the
// small ones near the surface), and two nodes are joined when a Voronoi edge
// joins their pieces. A tube becomes a chain, a split a junction, a handle a
// cycle.
//
// Branches: nodes are ends (degree 1), regular (2) or junctions (≥ 3); a
// branch is the polyline of (x, y, z, r) from an end or junction to the next
// one. A cycle without junction is one closed branch (first point = last).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "skelconv/reconstruct/medial_graph.hpp"
#include "skelconv/reconstruct/weighted_point.hpp"

namespace skelconv::reconstruct {

/// (x, y, z, r): a skeleton point and its radius.
using Vec4 = Eigen::Vector4d;

struct CurveSkeleton {
  std::vector<Vec4> nodes;
  std::vector<std::pair<std::int32_t, std::int32_t>> edges;
};

struct LevelSetOptions {
  double bin_width = 0.0;       ///< > 0, in length units
  double core_fraction = 0.8;   ///< in (0, 1]
};

CurveSkeleton level_set_skeleton(const MedialGraph& graph, const LevelSetOptions& options);

struct Branch {
  std::vector<Vec4> points;
  std::int32_t first_node = -1, last_node = -1;  ///< node indices of the ends
  std::vector<std::int32_t> interior_nodes;       ///< the regular nodes between
  /// The first / last point is an end extension beyond the skeleton's free
  /// end (surface_fit.hpp), not a skeleton node.
  bool extended_first = false, extended_last = false;
};

struct BranchGraph {
  std::vector<Branch> branches;
  std::size_t ends = 0;       ///< nodes of degree 1
  std::size_t junctions = 0;  ///< nodes of degree ≥ 3
};

/// Splits `skeleton` into branches at every node of degree ≠ 2.
BranchGraph extract_branches(const CurveSkeleton& skeleton);

/// Cleans the junctions, until nothing changes: contracts every branch
/// between two junctions (or loop at one) shorter than `spur_factor` × the
/// larger end radius (a "bubble" of a coarsely sampled junction: its two
/// junctions become one, at their midpoint, with the larger radius), and
/// removes every terminal branch (an end to a junction) that is a spur:
/// shorter than `spur_factor` × the junction's radius (it stays about inside
/// the junction's ball), or whose balls reach less than `protrusion_factor`
/// × the junction's radius beyond the balls of the rest of the skeleton
/// (0: not tested). The second rule catches what sampling noise grows: a
/// bump of the surface pulls a piece of medial sheet from the axis towards
/// it, a spur as long as the tube is thick whose balls stay inside the
/// tube (measured on the noisy ring: 0.03-0.48 junction radii beyond; the
/// real branches of the test shapes reach 1.8-6). First, each round, it
/// removes the extra path of two paths that run in one tube: one of two
/// branches joining the same two junctions, and one half of a branch split
/// into a loop at its junction (docs/reconstruction.md). Returns how many
/// went.
std::size_t remove_spurs(CurveSkeleton& skeleton, double spur_factor, double protrusion_factor = 0.0);

/// Which terminal branch is a spur. Without `surface`, the rules of
/// remove_spurs above: shorter than `length_factor` × its junction's radius
/// R, or reaching less than `protrusion_factor` × R beyond the rest's
/// balls. With `surface` (the input as area-weighted points), by the area
/// it explains instead (explained_area): a spur explains less than
/// `explained_factor` × π R² of the input's area, a limb more, however
/// short it is. `length_factor` still sets which branches between two
/// junctions are contracted.
struct SpurRule {
  double length_factor = 1.5;
  double protrusion_factor = 0.0;
  const std::vector<WeightedPoint>* surface = nullptr;
  /// A limb explains at least the area of a hemisphere of radius R/2
  /// (π R²/2), the cap of the thinnest limb still worth a branch; the spurs
  /// noise grows explain only the few samples of a bump.
  double explained_factor = 0.5;
  /// A sample counts for a branch only when the rest of the skeleton misses
  /// it by more than this × the rest's radius there, beyond what the branch
  /// does (the medial balls fall short of the surface by ~8% of the radius,
  /// and noise moves it: neither is something a branch explains).
  double explained_tolerance = 0.25;
};

/// remove_spurs with `rule` (the three-argument form is rule {spur_factor,
/// protrusion_factor}).
std::size_t remove_spurs(CurveSkeleton& skeleton, const SpurRule& rule);

/// The area of `surface` that branch `which` of `branches` explains beyond
/// the rest: the total weight of the points whose nearest tube is the
/// branch's and whose distance to the rest's tubes exceeds their distance
/// to the branch's tubes by more than `tolerance` × the rest's radius at
/// its nearest point. The distance to a branch's tubes is the smallest, over
/// its polyline's segments, of |p − q| − r_q (q the point of the segment
/// nearest p, r_q the radius interpolated there): the signed distance to
/// the surface of its balls, about.
double explained_area(const std::vector<Branch>& branches, std::size_t which, const std::vector<WeightedPoint>& surface,
                      double tolerance);

struct JunctionOptions {
  /// The axis of a branch leaving a junction of radius R is the chord of
  /// its points from R to `reach` × R (arc length) away.
  double reach = 3.0;
  /// A move larger than this × R is not trusted (the junction stays).
  double largest_move = 2.0;
  /// The axes must not be about parallel: the smallest eigenvalue of
  /// Σ (I − d dᵀ) at least this × their number (0 for parallel axes,
  /// 1 for three orthogonal ones; a plane Y of 120° gives 0.5 × 3 in the
  /// plane and 1 × 3 across it).
  double min_spread = 0.05;
};

/// Moves every junction (degree ≥ 3) to the point nearest, in least
/// squares, to the axes of the branches leaving it (each the chord from one
/// to `reach` junction radii along the branch). A level-set graph puts a
/// junction where its level set splits, about a radius past the true
/// branching point, and branches then cut the corner there (the tree's
/// largest distances were at those corners). Interior nodes left behind
/// the moved junction, or within half its radius ahead of it, go. Returns
/// how many junctions moved.
std::size_t relocate_junctions(CurveSkeleton& skeleton, const JunctionOptions& options = {});

/// 3-D length of a polyline (r ignored).
double polyline_length(const std::vector<Vec4>& points);

}  // namespace skelconv::reconstruct
