// src/reconstruct/fill_cavities.hpp — hollows the fit opened inside a solid
// part of the input, filled by one isolated sphere each
// (docs/reconstruction_medial.md, "Cavities the guard lets through").
// Internal: the medial stage (medial_stage.cpp) is its one user.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "skelconv/mesh/mesh_topology.hpp"
#include "skelconv/mesh/triangle_mesh.hpp"
#include "skelconv/reconstruct/medial_mesh.hpp"
#include "skelconv/reconstruct/reconstruct.hpp"

namespace skelconv::detail {

/// A cavity of the reconstruction to fill: the ball of the isolated sphere
/// that holds it, and the χ of its wall (a component of the meshed surface;
/// 2 for a bubble), which the topology guard takes off the surface's as the
/// fill will.
struct Cavity {
  reconstruct::Vec4 ball;
  long long euler_characteristic = 0;
  /// Whether the wall's centre lies outside the input: a bubble of a
  /// crease's air, not a hollow in the input's solid.
  bool air = false;
};

/// A closed component of `meshed` (the surface f = iso of a medial mesh,
/// its triangles facing out of {f ≥ iso}, as the grid mesher writes them)
/// that bounds a negative volume is the wall of a cavity: a pocket where
/// f < iso inside the reconstruction. It is the fit's, not the input's,
///   * where the input is solid at the centre of the wall's bounding box
///     (`depth`, the input's signed distance, positive inside): the fit
///     shrank the primitives about it until their sum fell below iso
///     between them, and no surface point sees it; or
///   * where the input encloses no empty space at all (`input_hollow`
///     false) and the centre is outside it: a bubble of the air in a
///     crease (between a chin and a neck, in an armpit) that the
///     reconstruction closed over at the crease's mouth. No input has
///     such a bubble, so it is a component and a χ of 2 too many.
///
/// Returns, per such cavity, a ball for an isolated sphere (a compact
/// point, f = iso at its radius ρ, support σ ρ, σ = `sigma`) about that
/// centre: ρ the distance to the wall's farthest vertex plus `margin` (the
/// unprojected wall lies within a facet of f = iso), where the sphere alone
/// is ≥ iso on the whole cavity; but inside the input at most depth / σ,
/// so that its support stays inside the input and the reconstruction's
/// surface near the input's does not move, and outside it at most the
/// distance to the nearest vertex of the reconstruction's outer surface
/// (the components bounding a positive volume): the surface there is the
/// reconstruction's seal over the crease, and the sphere's own surface
/// stays within it. Such a smaller sphere covers the middle of the
/// cavity, and its field added to the wall's (near iso there) closes the
/// rest, mostly: the caller meshes again to see.
std::vector<Cavity> spurious_cavities(const TriangleMesh& meshed, const std::function<double(const Vec3&)>& depth,
                                      bool input_hollow, double margin, double sigma);

/// The topology of `meshed` as the fill will leave it, as the fit's
/// topology guard counts it: each of `cavities` (spurious_cavities of
/// `meshed`) that `counted` names, every one (`all`), the bubbles of air
/// alone (`air`) or none, taken off, one component and its wall's χ each.
MeshTopology topology_after_fill(const TriangleMesh& meshed, const std::vector<Cavity>& cavities,
                                 reconstruct::GuardFilledCavities counted);

/// Whether a closed surface encloses empty space: a component of it bounds
/// a negative volume (faces into what it bounds), as a hollow ball's inner
/// wall does.
bool encloses_empty_space(const TriangleMesh& surface);

/// Where `meshed` (a closed surface f = iso, as the grid mesher writes it)
/// has more outer shells (components bounding a positive volume) than
/// `components`, the input's count: a piece of the reconstruction apart
/// from the rest (a toe's tip whose neck the fit thinned below the measure's
/// facet). Returns, per outer shell but the one of the largest volume, the
/// smallest volume first (ties in the components' order), a ball for an
/// isolated sphere (a compact point, f = iso at its radius ρ) across the
/// gap between the shell and the nearest other outer shell: the smallest
/// ball holding the two nearest vertices, one on each. Compact kernels are
/// non-negative, so the sum of fields is ≥ iso wherever one of them is:
/// the solid then holds the ball, which touches both shells, and the two
/// are one where the mesher resolves the joint; the caller meshes again to
/// see. Empty where the outer shells are no more than `components`.
std::vector<reconstruct::Vec4> piece_bridges(const TriangleMesh& meshed, std::size_t components);

/// Room for `count` more primitives within the budget: drops the `count`
/// tube edges or triangles of `mesh` with the smallest supports (the
/// Minkowski sum of the primitive and a ball of σ × its mean radius, σ =
/// `sigma`) among those whose every sphere another primitive still uses, so
/// that no sphere is left without a primitive and the spheres' indices
/// stay. The smallest support is the least field taken away; the caller
/// meshes again to see that the topology came no farther from the
/// input's. Returns how many were dropped (fewer where no such primitive
/// is left).
std::size_t drop_smallest_primitives(reconstruct::MedialMesh& mesh, std::size_t count, double sigma);

}  // namespace skelconv::detail
