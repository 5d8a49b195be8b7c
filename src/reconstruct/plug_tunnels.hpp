// src/reconstruct/plug_tunnels.hpp — tunnels through air the reconstruction
// has and the input does not, found where taking a small box of the meshed
// surface's triangles out lowers its genus, plugged by an isolated sphere
// each (docs/reconstruction_medial.md, "Tunnels through air").
// Internal: the medial stage (medial_stage.cpp) is its one user.
#pragma once

#include <cstdint>
#include <vector>

#include "skelconv/mesh/triangle_mesh.hpp"
#include "skelconv/reconstruct/medial_mesh.hpp"

namespace skelconv::detail {

/// Places where a tunnel of `meshed` (a closed surface f = iso, as the grid
/// mesher writes it) may run through a pipe of air the input (`input`,
/// closed) does not have: a crease of the input that the reconstruction
/// sealed at its mouth along a stretch while both its ends stay open
/// (homer's mouth: a slit between the lips narrower than the measure's
/// facet, a pipe of air through the head).
///
/// The surface is cut into cubes of side `cell`; each block of 2 × 2 × 2
/// cubes is a candidate box. A connected piece (through shared edges) of
/// the triangles whose centroids lie in the box is a *cut* where taking it
/// out lowers the surface's genus (genus_drop_doubled): a band round a
/// handle, not a disc, nor a band round a tube that taking it out cuts in
/// two (a finger: one component more, the genus kept). A band small enough
/// for the box rings a narrow pipe of air or a thin bar of solid; only the
/// first is plugged by adding material, which the caller sees when it
/// meshes again. A cut is the input's own tunnel, and left alone, where the
/// input's triangles that meet the box, grown by `cell` on every side, are
/// a cut of the input too (a bore narrower than the box).
///
/// Returns, per cut, the ball of an isolated sphere (a compact point, f =
/// iso at its radius ρ), the smallest ball that holds the cut's vertices:
/// holding a loop round the pipe, it fills the pipe's cross-section there
/// and so cuts the pipe into two creases, each open at one end; the
/// smallest such ball buries the least of a slit the pipe runs along (a
/// ball about the vertices' mean, out to the farthest, is up to twice as
/// large where the band is lopsided, as a V-shaped slit's is). Sorted by ρ, the
/// smallest first (the least material added; ties by position). The caller
/// meshes again to see that the genus dropped.
std::vector<reconstruct::Vec4> air_tunnel_plugs(const TriangleMesh& meshed, const TriangleMesh& input, double cell);

/// The smallest ball (centre, radius) that holds every point of `points`
/// (CGAL's `Min_sphere_of_spheres_d`; a zero ball where empty).
reconstruct::Vec4 smallest_ball(const std::vector<Vec3>& points);

/// How much taking the triangles `removed` (indices into `mesh.triangles`,
/// distinct) out of the closed surface `mesh` lowers its genus, doubled
/// (2 Σ g of the mesh less 2 Σ g of what is left, each component of what
/// is left counted as a surface with boundary: 2 − χ − b, b its boundary
/// loops). 2 for a band round a handle, 0 for a disc or a band round a tube
/// that the removal cuts in two.
long long genus_drop_doubled(const TriangleMesh& mesh, const std::vector<std::int32_t>& removed);

}  // namespace skelconv::detail
