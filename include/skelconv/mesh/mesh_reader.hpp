// skelconv/mesh/mesh_reader.hpp — reading a triangle mesh (PLY, OBJ, OFF or STL) as a
// user would give it; the reading half of triangle_mesh.hpp's write_mesh.
//
//   * PLY: "ascii 1.0", "binary_little_endian 1.0" or "binary_big_endian
//     1.0"; the vertex element's x, y, z of any scalar type (char … double,
//     also int8 … float64; in ASCII an integer type's words must be whole
//     numbers within its range); faces from the list property "vertex_indices" (or
//     "vertex_index"), polygons triangulated (below); every other element and
//     property is read past and ignored (normals are not read: the consumer
//     recomputes what it needs);
//   * OBJ: "v x y z" (optionally w, or a colour r g b) and "f i j k …"
//     lines (i, i/t, i//n, i/t/n; negative indices count from the end),
//     polygons triangulated (below); "#" comments and the statements that do not
//     change the shape (vn, vt, vp, g, o, s, usemtl, mtllib and the other
//     display attributes) skipped; points, lines, free-form geometry and
//     unknown statements refused at their line;
//   * OFF: "OFF" or "COFF", the counts, one vertex and one face ("n i0 …",
//     0-based) per line, colours and "#" comments ignored, polygons
//     triangulated (below; CGAL's sample meshes are OFF files);
//   * STL: binary (when the size is 84 + 50 × the facet count) or ASCII
//     ("solid" … "facet normal" / "outer loop" / three "vertex x y z" /
//     "endloop" / "endfacet" … "endsolid"); every facet's corners are new
//     vertices (STL shares none), normals ignored.
// A polygon of n corners becomes n − 2 triangles: the fan from its first
// corner when it is convex, otherwise ear clipping in its plane, so that a
// non-convex polygon is covered once and three corners on a line leave no
// triangle of zero area.
// Errors are InputError located at the path and, where there is one, the line
// ("mesh.obj: line 12: face index 40 outside [1, 39]"). Faces are optional:
// a point set is a mesh without triangles.
#pragma once

#include <cstddef>
#include <filesystem>
#include <limits>

#include "skelconv/mesh/triangle_mesh.hpp"

namespace skelconv {

/// Reads `path` (.ply, .obj, .off or .stl, by extension, case insensitive). The returned
/// mesh has no normals. Throws InputError for an unknown extension, an
/// unreadable file, a malformed header or body, a non-finite coordinate or a
/// face index out of range, and (naming the option --max-triangles of the
/// command that passes it) for a mesh of more than `max_triangles` triangles
/// after triangulation: refused as soon as the count passes the limit,
/// and for a PLY file whose header declares more faces, before its body is
/// read.
TriangleMesh read_mesh(const std::filesystem::path& path,
                       std::size_t max_triangles = std::numeric_limits<std::size_t>::max());

}  // namespace skelconv
