// skelconv/reconstruct/medial_quadric.hpp — the inner Voronoi medial mesh
// simplified by edge collapses under the spherical quadric error (Q-MAT:
// Li et al., "Q-MAT: Computing Medial Axis Transform by Quadratic Error
// Minimization", ACM TOG 2015). docs/reconstruction_medial.md describes it.
//
// The start is the medial graph's 2-complex (medial_graph.hpp): its inner
// Voronoi vertices as spheres (c, r), its Voronoi edges, and its Voronoi
// faces cut into triangles (a fan from each polygon's first vertex).
//
// The error of a sphere s = (c, r) against a plane through q with unit
// normal n (pointing out of the shape) is the signed distance between the
// plane and the sphere, d(s) = n·(q − c) − r = k − ñ·s with ñ = (n, 1) and
// k = n·q: zero when the sphere touches the plane from inside. Its square is
// a quadric in s ∈ R⁴, sᵀ A s − 2 bᵀ s + k² with A = ñ ñᵀ, b = k ñ (the
// SQEM). Each Voronoi ball touches the surface at its four samples; the
// tangent planes there are the surface's, and a vertex's quadric is the sum
// over them. A collapse of the edge (u, v) gives the merged sphere the sum
// of both quadrics, minimised by the 4 × 4 system A s = b; where that is
// singular (a tube's planes all contain its axis, so the centre may slide
// along it) a small pull toward the edge's midpoint decides, and where the
// solution is not finite or its radius not positive, the better of the two
// ends and the midpoint is taken. Where the input's signed distance is
// given, a merged sphere that is not a ball of the shape (its centre
// outside, or its radius beyond its centre's depth) is refused the same
// way.
//
// Collapses go cheapest first. The link condition (Dey et al. 1999: the
// common neighbours of u and v are exactly the apexes of the triangles on
// the edge, and no triangle outside the edge is shared by the two links)
// refuses every collapse that would change the complex's topology, so its
// Euler characteristic stays, with two exceptions where the complex's
// topology is not the shape's: a loop of three edges without its triangle
// whose balls cover the triangle (at its centroid and the midpoints of its
// sides: a hole in a sheet where pruning or a sliver left a Voronoi vertex
// out; the balls are inside the shape, and a tunnel of the shape is not) is
// closed, and a closed tetrahedron inside its balls (a cavity: a solid has
// none) is flattened. Spikes (the medial axis's
// response to every sharp vertex or noisy sample: a chain of shrinking balls
// each nearly inside the next) are collapsed first: an edge's cost is its
// quadric error times its stability ratio squared, (|c_u − c_v| − |r_u −
// r_v|) / |c_u − c_v| ∈ [0, 1], which is near 0 for a ball inside its
// neighbour and 1 across a sheet (a small term in the edge's length keeps
// the spheres evenly spread where the error is zero; where asked, a term in
// the radius's change along the edge keeps a sheet's triangles narrow where
// its radius varies, QuadricOptions::radius_weight). The collapses stop when
// the primitives (triangles, edges in no triangle, spheres in no edge) fit
// the budget, or, with an error target (QuadricOptions::error_target), once
// under the budget, when every collapse left would make a sphere farther than
// the target from one of the tangent planes it stands for (the budget is a cap, the
// target a floor on the error worth a primitive).
//
// Where asked (QuadricOptions::inside_samples, with the input's depth),
// a loop the input holds a disc across is no tunnel of the shape and is
// closed even where the balls do not cover it: a loop of three edges at a
// collapse, and after the collapses each side of a tube edge that bridges
// a hole between two spheres of sheets (the loop of the edge and the
// shortest way back along the hole's rim, closed by a fan of triangles),
// then each hole through a sheet that the collapses left (the budget
// reached before a collapse on its rim): a loop of the sheets' rims (edges on one triangle)
// that bounds no triangles of the complex (over GF(2), shortest loops
// first, so that a sheet's outer rim, which bounds the sheet once its holes
// are closed, is never closed over it).
//
// Where given (QuadricOptions::reach_points), the ball nearest a sample at
// a thin protrusion's end that no ball reaches keeps its place: a collapse
// with it keeps its sphere.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "skelconv/reconstruct/medial_graph.hpp"
#include "skelconv/reconstruct/medial_mesh.hpp"

namespace skelconv::reconstruct {

/// A point of the surface that vertex `vertex` of the medial graph must go
/// on reaching (QuadricOptions::reach_points).
struct ReachPoint {
  std::int32_t vertex = 0;
  Vec3 point;
};

struct QuadricOptions {
  /// Collapse until the primitives are at most this many.
  std::size_t budget = 500;
  /// Once within the budget, go on collapsing, cheapest first, where the
  /// merged sphere stays within this distance (absolute; 0: off, stop at
  /// the budget) of every tangent plane it stands for: the planes of every
  /// sample the sphere stands for (the contact samples of every Voronoi
  /// ball merged into it, and the reach points), the sphere's distance to
  /// the plane being |n·(q − c) − r|, how far the ball's surface is from
  /// the input's along its normal at that sample. The farthest plane, not
  /// a mean: a mean over a sphere of many planes lets it stand far from a
  /// few of them (a thin part's end, a tube's turn). So after the stop
  /// every sphere merged under the budget is within the target of each of
  /// its planes (a sphere merged to reach the budget may not be), and the
  /// collapses that would make one farther are left undone. It bounds the
  /// balls of the medial mesh, not the surface the fit makes of them.
  double error_target = 0.0;
  /// The pull toward the edge's midpoint, × the trace of the summed
  /// quadric: small enough not to move a well-determined sphere (a relative
  /// change of about this), large enough to fix a tube's free direction.
  double regularisation = 1e-4;
  /// Added to every cost before the stability ratio scales it: this × the
  /// number of planes in the summed quadric × the edge's squared length.
  /// Along a tube or across a flat sheet every collapse costs no error; the
  /// shortest edges then go first, and the spheres stay evenly spread. Small:
  /// it counts like an error of 1% of the edge's length at each plane.
  double length_weight = 1e-4;
  /// Added to every cost before the stability ratio scales it: this × the
  /// number of planes in the summed quadric × (r_u − r_v)². The quadric is
  /// blind to how a sphere's radius varies along a sheet (every ball of a
  /// bisector sheet touches both its planes: no error), but a medial
  /// triangle becomes a SCALIS triangle of one radius, whose surface steps
  /// where the radius varies across it, most steeply at a sharp edge, where
  /// it falls to the floor. This keeps the triangles small where the radius
  /// varies; 0 leaves the budget to the quadric and the length term.
  double radius_weight = 0.0;
  /// A triangle whose smallest altitude is below this × its smallest
  /// radius and this × its longest side becomes that side, a tube edge: along a tube the
  /// Voronoi faces simplify to strips narrower than the tube, which SCALIS
  /// triangles (normalised for a wide sheet) make too thin.
  double thin_triangle = 0.25;
  /// The input's signed distance (positive inside), if known. A merged
  /// sphere must then be a ball of the shape: its centre inside and its
  /// radius at most the centre's depth plus `overhang` (absolute), or the
  /// collapse keeps one of its ends instead. The quadric alone does not
  /// know the inside: where few planes remain (a sheet collapsed round a
  /// bore), a sphere tangent to all of them lies anywhere, often in the
  /// bore with a radius several times the wall's. It must be 1-Lipschitz
  /// (a signed distance is): a candidate is decided from the depths at the
  /// centres of the two balls it merges where they bound it, which asks
  /// those centres again for every candidate, so a costly `depth` should
  /// remember its answers.
  std::function<double(const Vec3&)> depth;
  double overhang = 0.0;
  /// With `depth`: a loop of three edges without its triangle is also
  /// closed where the balls do not cover the triangle but the input holds
  /// it (`depth` positive at `inside_samples` + 1 points along each side
  /// and across it). Such a loop bounds a disc inside the shape, so it is
  /// no tunnel of the shape; it is a hole that pruning or a wall thinner
  /// than the samples' spacing punched into a sheet, wider than the balls
  /// on its rim. After the collapses, each side of a tube edge between two
  /// spheres of sheets is closed the same way, and then each hole through a
  /// sheet the collapses left (the header). Off (0) by
  /// default: the sum of fields covers most such holes, and
  /// medial_stage.cpp asks for it only where the reconstruction came back
  /// with a tunnel too many.
  int inside_samples = 0;
  /// A point of such a triangle counts as held where its depth is above
  /// minus this (absolute): a triangle spans its corners' centres, and
  /// across a curved wall barely thicker than the balls its chord passes
  /// the medial sheet by a little (CGAL's rotor: 2% of a ball's radius
  /// outside). A tunnel narrower than twice this is not told from it;
  /// medial_stage.cpp takes half a facet of the measuring mesh, below
  /// what the measure resolves.
  double inside_tolerance = 0.0;
  /// Points of the surface the balls fall short of at the end of a thin
  /// protrusion (the samples at a horn's tip, beyond the balls pruning
  /// left: unreached_tips.hpp), each with the ball falling shortest of it.
  /// Each adds to that vertex's quadric the plane through the point facing
  /// away from the ball's centre, `reach_weight` times: its error is how
  /// far a sphere falls short of the point along that way. The contact
  /// planes along a cone all touch every ball on its axis, the larger ones
  /// deeper in too, so without it the collapses merge a horn's end balls
  /// into a deeper one at no error and the horn comes back short (CGAL's
  /// mannequin-devil: into a sheet's corner 0.67 deeper). So the ball is
  /// also held: a collapse with it keeps its sphere (two held balls merge
  /// as any two, into a held ball, so that the budget is always reached).
  std::vector<ReachPoint> reach_points;
  double reach_weight = 1.0;
};

struct QuadricReport {
  std::size_t vertices_before = 0, triangles_before = 0;
  long long euler_before = 0, euler_after = 0;  ///< V − E + T of the complex
  std::size_t collapses = 0, refused_by_link = 0;
  std::size_t loops_closed = 0;  ///< covered loops the collapses closed (the header)
  std::size_t loops_closed_inside = 0;  ///< of those, loops inside the input, not the balls (inside_samples)
  std::size_t bridges_closed = 0;       ///< sheets closed across a tube edge after the collapses (inside_samples)
  std::size_t holes_closed = 0;         ///< holes through sheets closed after the collapses (inside_samples)
  std::size_t tips_held = 0;            ///< balls held in place for their reach points (reach_points)
  /// Why the collapses stopped, one of the three per simplification (the
  /// counts add up over the parts of a shape simplified apart): the budget
  /// reached (no error target); within the budget, every collapse left
  /// over the error target (or refused by the link condition); above the
  /// budget, no collapse left that the link condition allows.
  std::size_t stopped_at_budget = 0, stopped_at_error = 0, stopped_without_collapse = 0;
  std::size_t collapses_under_budget = 0;  ///< collapses made once within the budget (error_target)
  std::size_t over_error_target = 0;       ///< collapses left undone for their error (error_target)
};

/// The medial mesh of `graph` (its faces included) simplified as described
/// above. Same graph, same mesh. Empty for an empty graph.
MedialMesh quadric_medial_mesh(const MedialGraph& graph, const QuadricOptions& options, QuadricReport* report = nullptr);

}  // namespace skelconv::reconstruct
