// skelconv/mesh/triangle_mesh.hpp — a triangle mesh with per-vertex normals,
// and the one way skelconv writes meshes to disk (PLY or OBJ).
//
// Every producer of surfaces in skelconv (`skelconv mesh`, the canal-surface
// sweep, the figure programs) fills a TriangleMesh and calls write_mesh, so
// there is one writer, one file layout and one atomicity rule:
//
//   * the format follows the file extension: ".ply" (binary little-endian by
//     default, ASCII on request) or ".obj" (always ASCII, with `vn` normals);
//   * numbers are written with 17 significant digits in ASCII, as raw IEEE
//     doubles in binary PLY: the same mesh gives the same bytes;
//   * the file is written to a temporary sibling and renamed into place, so a
//     failure (bad path, full disk) leaves nothing half-written. Failures
//     throw InputError("cannot write ...") located at the path.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "skelconv/geometry.hpp"

namespace skelconv {

/// Vertices, optional unit normals (empty, or one per vertex) and triangles
/// as counter-clockwise vertex index triples seen from outside (the side the
/// normals point to).
struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<Vec3> normals;
  std::vector<std::array<std::int32_t, 3>> triangles;
};

enum class PlyEncoding { binary, ascii };

/// Writes `mesh` to `path` (.ply or .obj, chosen by extension, case
/// insensitive). Throws InputError for another extension, an invalid mesh
/// (index out of range, normals count ≠ vertex count) or an I/O failure; the
/// destination is then left as it was.
void write_mesh(const TriangleMesh& mesh, const std::filesystem::path& path,
                PlyEncoding ply_encoding = PlyEncoding::binary);

}  // namespace skelconv
