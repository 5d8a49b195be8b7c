// skelconv/reconstruct/medial_parts.hpp — the closed parts of the input
// surface, and a medial mesh grouped by them. The skeleton of an input of
// several parts sums each part's primitives and joins the parts' sums by a
// union (max), so that two parts close together never blend into one
// (docs/reconstruction_medial.md, "Separate parts").
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "skelconv/mesh/triangle_mesh.hpp"
#include "skelconv/reconstruct/medial_graph.hpp"
#include "skelconv/reconstruct/medial_mesh.hpp"

namespace skelconv::reconstruct {

/// For each triangle of `surface`, the closed part it belongs to (triangles
/// joined through shared vertices: two parts that touch at a vertex are
/// one), numbered from 0 in the order of the parts' first triangles.
std::vector<std::int32_t> triangle_parts(const TriangleMesh& surface);

/// The triangles of `surface` whose part (`parts`, per triangle) is `part`,
/// with only the vertices they use, in their first use's order.
TriangleMesh surface_part(const TriangleMesh& surface, const std::vector<std::int32_t>& parts, std::int32_t part);

/// How many parts `mesh.parts` names: 1 + its largest, 1 when it is empty.
std::size_t part_count(const MedialMesh& mesh);

/// The part of a medial edge or triangle made of `spheres`: the part most
/// of them are in, the first sphere's on a tie. (An element across two
/// parts would join one part's sum and reach into the other; medial_stage
/// counts them in its progress line where it keeps the single
/// simplification: none on the two close balls of
/// tests/data/reconstruct/spheres_close.ply; a part simplified alone makes
/// none.) 0 when `mesh.parts` is empty.
std::int32_t element_part(const MedialMesh& mesh, std::span<const std::int32_t> spheres);

/// `mesh` with only the edges, triangles and isolated spheres of part
/// `part` (element_part), every sphere kept so that indices still hold,
/// and `parts` empty: the mesh one sum of fields describes.
MedialMesh medial_mesh_part(const MedialMesh& mesh, std::int32_t part);

/// The primitive budget shared out over parts of sizes `weights` (their
/// areas): each part gets at least `minimum` (or an equal share of
/// `budget` where the parts are too many for that), the rest goes in
/// proportion to the weights (largest remainders first, the first part on
/// a tie). The shares add up to at most `budget`. One simplification of
/// the whole medial graph would spend its budget where the absolute error
/// is largest, the large parts, and leave a small part one or two spheres
/// that bulge past the gap into a neighbour (docs/reconstruction_medial.md,
/// "Separate parts").
std::vector<std::size_t> part_budgets(std::span<const double> weights, std::size_t budget, std::size_t minimum);

/// Per vertex of `graph`, its part: the part of most of its four contact
/// samples (`graph.sample_parts`), the first sample's on a tie; all 0 when
/// `sample_parts` is empty. A ball inside one part touches only that
/// part's surface unless the parts touch.
std::vector<std::int32_t> vertex_parts(const MedialGraph& graph);

/// The vertices of `graph` whose part (`parts`, per vertex) is `part`, the
/// edges and faces among them only, every sample kept (the vertices'
/// contact samples index them).
MedialGraph medial_graph_part(const MedialGraph& graph, const std::vector<std::int32_t>& parts, std::int32_t part);

/// The medial meshes of the parts, in order, as one mesh: spheres, edges,
/// triangles and isolated spheres appended, and `parts` naming each
/// sphere's mesh (its index in `meshes`).
MedialMesh joined_part_meshes(const std::vector<MedialMesh>& meshes);

}  // namespace skelconv::reconstruct
