// skelconv/mesh/mesh_topology.hpp — the numbers `skelconv mesh` prints about
// a triangle mesh: connected components, Euler characteristic, closed,
// manifold.
//
// Only vertices used by some triangle count. Definitions:
//   * components: classes of triangles connected through shared vertices;
//   * χ = V − E + F (for a closed orientable surface of genus g, 2 − 2g per
//     component);
//   * closed: every edge belongs to exactly two triangles;
//   * manifold: every edge belongs to at most two triangles, no triangle
//     repeats a vertex, and around every vertex the incident triangles form
//     a single fan (connected through edges at that vertex).
#pragma once

#include <cstddef>

#include "skelconv/mesh/triangle_mesh.hpp"

namespace skelconv {

struct MeshTopology {
  std::size_t vertices = 0;  ///< used by a triangle
  std::size_t edges = 0;
  std::size_t triangles = 0;
  std::size_t components = 0;
  long long euler_characteristic = 0;
  bool closed = false;
  bool manifold = false;
};

MeshTopology mesh_topology(const TriangleMesh& mesh);

/// How many defects separate the topology of closed surfaces `result` from
/// `reference`'s: each component too many or too few counts one, and each
/// handle (tunnel) too many or too few counts one, the handles summed over
/// the components (2·components − χ = 2 Σ g). A detached piece or a cavity
/// (one more component of genus 0) is one defect, and an extra tunnel with
/// a cavity is two: the difference in χ alone would let them cancel.
long long topology_defects(const MeshTopology& reference, const MeshTopology& result);

}  // namespace skelconv
