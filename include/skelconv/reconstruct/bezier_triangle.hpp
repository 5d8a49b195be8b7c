// skelconv/reconstruct/bezier_triangle.hpp — junctions of three branches by
// cubic Bézier triangles in 4-D (x, y, z, r) (Ferley 1996 §2.4 and §3.2).
//
// A cubic Bézier triangle has 10 control points (Ferley fig. 2.24): three
// primary ones P0, P1, P2 (the corners), six secondary ones (two per edge,
// P3 P4 on P0P1, P5 P6 on P1P2, P7 P8 on P2P0) and one central P9:
//   P(r, s, t) = r³P0 + s³P1 + t³P2 + 3r²s P3 + 3rs² P4 + 3s²t P5 + 3st² P6
//              + 3rt² P7 + 3r²t P8 + 6rst P9,       r + s + t = 1, r, s, t ≥ 0.
//
// Placement at a junction J of three branches (Ferley §3.2.1): P9 = J; each
// branch is walked from J along its smoothed points until the 3-D distance
// to J reaches k × J's radius (or, on a branch to another junction, the
// part of its length shared out to J in proportion to the two junction
// radii; on a branch to a free end, its last point but one), and that point
// is the corner; the branch then starts there. The two secondary points of
// a corner are both at 1/3 of the way from the corner to J, so that every
// edge of the triangle leaves the corner along the branch's chord to J
// (Ferley's §2.4.2 choice, tangent to the branches). Ferley's §2.4.3
// trouble with it, the curvature radius vanishing at the corners, was a
// trouble of *offsetting* the patch by its normals; a convolution surface
// needs no normal, so the composition of §2.4.4 is not needed here.
//
// How the patch becomes primitives: it is tessellated into `n`² flat
// triangles of the domain, each a skelconv "scalis_triangle" at the
// constant radius of its three vertices' mean (the closed form; varying
// radii would cost the certified quadrature, ~0.1 ms a value, too slow to
// mesh). docs/reconstruction.md measures it against plain branches.
#pragma once

#include <array>
#include <vector>

#include "skelconv/reconstruct/branch_graph.hpp"

namespace skelconv::reconstruct {

/// Control points in Ferley's numbering, P0…P9.
using BezierNet = std::array<Vec4, 10>;

/// P(r, s, t); (r, s, t) need not be normalised by the caller beyond
/// r + s + t = 1.
Vec4 bezier_triangle_point(const BezierNet& net, double r, double s, double t);

/// The net of a junction at `centre` with corners c0, c1, c2 (the
/// placement above): P9 = centre, secondaries at 1/3 from each corner to
/// the centre.
BezierNet junction_net(const Vec4& centre, const Vec4& c0, const Vec4& c1, const Vec4& c2);

/// A flat facet of a tessellated patch: three (x, y, z, r) vertices.
using Facet = std::array<Vec4, 3>;

/// The patch as `n`² facets of the uniform subdivision of the domain
/// (n ≥ 1), in a fixed order.
std::vector<Facet> tessellate(const BezierNet& net, int n);

/// Places a triangle at every junction where exactly three branch ends meet
/// (not at a loop) and returns the facets of all patches; `k` is Ferley's k
/// (> 0). With `cut_branches` (Ferley's layout) the branches then start at
/// the corners; without, they still run to the junction and the patch is a
/// fillet between them. Why the default is the fillet: a patch about 2k
/// radii across, normalised against an infinite plane, gives only ~0.8 ×
/// iso at its centre, so cut branches leave the junction hollow
/// (docs/reconstruction.md measures both).
std::vector<Facet> place_junction_triangles(std::vector<Branch>& branches, double k, int n, bool cut_branches);

}  // namespace skelconv::reconstruct
