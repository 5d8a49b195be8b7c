// skelconv/reconstruct/pruning.hpp — removing the skeleton branches that
// sampling noise creates (Ferley 1996 §1.2.3, fig. 1.17).
//
// Ferley's criterion: a skeleton vertex v, centre of a ball of radius ρ
// touching the shape at samples p⁻, p⁺, is removed when the angle θ under
// which v "sees" the shape, θ = angle(v p⁻, v p⁺) = 2 asin(|p⁻p⁺| / (2ρ)),
// is below a threshold. In the 2-D figure p⁻, p⁺ are the two samples of the
// Delaunay edge dual to the terminal Voronoi edge [v v']. Ferley extends it
// to 3-D with "the Delaunay tetrahedra associated with the skeleton
// vertices"; we take p⁻, p⁺ = the two vertices of v's Delaunay tetrahedron
// farthest apart (its longest edge), the largest angle the ball's contact
// points subtend at v: a vertex goes only when even that angle is small.
//
// Why every vertex and not only the ends: in 2-D the inner Voronoi graph is
// a tree-like set of curves and removing ends repeatedly strips the noise
// branches. In 3-D it is the edge graph of a medial *surface*, full of short
// cycles, with few vertices of degree 1, so end-stripping stops almost at
// once; the vertices that sampling creates near the surface (balls through
// four close samples, θ small) are then removed wherever they are. Near the
// axis of a tube of radius R, θ is close to 180°. Connected pieces left with
// fewer than `minimum_piece` × the vertices of the largest piece in the same
// closed part of the surface are removed too (islands of noise; a separate
// part, one bone of a foot, is measured against its own largest piece). Reported: vertices removed by the angle, pieces
// (branches) removed.
#pragma once

#include <cstddef>

#include "skelconv/reconstruct/medial_graph.hpp"

namespace skelconv::reconstruct {

/// θ = 2 asin(|p⁻p⁺| / (2ρ)) in radians; the ratio is clamped to 1 (θ = π
/// when the samples are a diameter apart or, by rounding, farther).
double pruning_angle(const Vec3& p_minus, const Vec3& p_plus, double rho);

struct PruningReport {
  std::size_t vertices_removed = 0;
  /// Connected pieces of the removed vertices: the branches that went.
  std::size_t branches_removed = 0;
  std::size_t small_pieces_removed = 0;
  /// Small pieces kept as lobes (LobeOptions).
  std::size_t lobes_kept = 0;
  /// Small pieces kept as thin protrusions (TipOptions).
  std::size_t tips_kept = 0;
  /// Of them, those joined again to the large pieces along the graph
  /// (TipOptions::connect), and the pruned vertices kept to join them;
  /// those the graph does not reach, bridged by an edge between overlapping
  /// balls.
  std::size_t tips_connected = 0;
  std::size_t connecting_vertices = 0;
  std::size_t tips_bridged = 0;
};

/// When a small piece is a lobe of the shape and not noise. A ball on a
/// body (CGAL's elk) has a point for medial axis: its Voronoi vertices are
/// a cloud round the centre that the angle cuts into small pieces, none of
/// them 5% of the body's sheet, and the islands rule would drop the whole
/// ball. A small piece is kept when its deepest ball (radius r) is deep,
/// r ≥ `radius` × the largest radius of the large pieces, and not inside
/// them: it reaches at least `outside` × r beyond every ball of the large
/// pieces (r − max over their balls of (ρ − |centre distance|)). Noise
/// pieces are shallow (balls near the surface) or lie inside the balls of
/// the sheet they broke off. 0 for `radius`: no piece is kept.
struct LobeOptions {
  double radius = 0.0;
  double outside = 0.5;
};

/// When a small piece is a thin protrusion of the shape and not noise. A
/// teat, a horn's tip, an ear: where it meets the body the surface is
/// concave, the balls there see their contacts under small angles, and the
/// angle cuts the protrusion's piece off the body's sheet; the islands rule
/// would then drop it, and the medial mesh stop at the body (CGAL's cow:
/// the udder's four teats, 51 to 60 vertices each, gone). A small piece is
/// kept when one of its balls (radius r) reaches beyond every ball of the
/// large pieces and of the lobes (r − max over their balls of (ρ − |centre
/// distance|), as LobeOptions) by at least `reach` (length units) and at
/// least `thinness` × r. Noise pieces are balls near the surface whose
/// centres sit about on the large balls' boundary: they reach about their
/// own radius (0.8–1.4 r on the real shapes), and an isolated ball deeper
/// than that would be a lobe; a protrusion longer than it is thick reaches
/// several radii (the cow's teats 4 r). 0 for `reach`: no piece is kept.
///
/// With `connect`, each piece kept is joined again to the large pieces (or
/// the lobes) along the shortest way through the graph's vertices the
/// pruning removed (the sum of the Voronoi edges' lengths): the piece the
/// angle cut off keeps its medial path to the body, and the medial mesh
/// makes one tube of it. Kept apart, the two tube ends facing each other
/// across the cut meet only where their end spheres overlap, a neck
/// thinner than the part; on a part thinner than the measuring mesh's
/// facet the mesher cannot resolve it (CGAL's camel: the tail, 0.4% of the
/// diagonal thick, came back in two pieces, one with the body, at diagonal
/// / 120, one piece at diagonal / 240). Where the graph does not reach the
/// piece (a tube thinner than its samples' spacing along it breaks the
/// inner Voronoi graph: the camel's tail), an edge bridges its ball and a
/// large piece's ball that overlap; a piece overlapping none stays apart.
struct TipOptions {
  double reach = 0.0;
  double thinness = 2.0;
  bool connect = false;
};

/// θ of vertex `v` of `graph` (p± = the longest edge of its tetrahedron).
double vertex_angle(const MedialGraph& graph, std::size_t v);

/// |p⁻p⁺| of vertex `v`: the longest edge of its tetrahedron, the span of
/// the ball's contact samples.
double contact_span(const MedialGraph& graph, std::size_t v);

/// Removes the vertices with θ < `threshold` (radians) or a contact span
/// below `minimum_span` (length units; 0: no such test), then the pieces
/// smaller than `minimum_piece` (in [0, 1]) × the largest in their part of
/// the surface (MedialGraph::sample_parts; a vertex's part is the one most
/// of its four samples lie on) but those that `lobes` or `tips` keeps;
/// renumbers.
///
/// Why a span as well as the angle: θ is scale-free, so noise larger than
/// the sample spacing (a folded surface) makes whole small-scale medial
/// structures whose balls, tiny as they are, see their contacts under
/// large angles (the tree with noise: 70 000 vertices kept at 90°, median
/// radius 0.008 for leaves of radius 0.14). A ball whose contacts span less
/// than about twice the noise amplitude cannot be told from noise (Chazal
/// & Lieutier's λ-medial axis keeps the balls whose contacts span ≥ λ).
PruningReport prune_medial_graph(MedialGraph& graph, double threshold, double minimum_piece = 0.05,
                                 double minimum_span = 0.0, const LobeOptions& lobes = {},
                                 const TipOptions& tips = {});

}  // namespace skelconv::reconstruct
