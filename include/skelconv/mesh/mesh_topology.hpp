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
  /// Where the surface touches itself at a vertex: over the vertices, the
  /// fans of triangles about each beyond its first (0 on a manifold).
  std::size_t pinches = 0;
};

MeshTopology mesh_topology(const TriangleMesh& mesh);


/// How many defects separate the topology of closed surfaces `result` from
/// `reference`'s: each component too many or too few counts one, and each
/// handle (tunnel) too many or too few counts one, the handles summed over
/// the components (2·components − χ = 2 Σ g). A detached piece or a cavity
/// (one more component of genus 0) is one defect, and an extra tunnel with
/// a cavity is two: the difference in χ alone would let them cancel.
///
/// Where `reference` touches itself at vertices (`pinches`, as --repair's
/// union of parts that meet at a point may), its V − E + F is odd for an odd
/// count, as no closed surface's is, and each such point reads two ways: as
/// a neck joining the fans (χ one lower for each fan beyond the first: the
/// vertices a split adds, less the two a neck takes) or as the fans apart
/// (the vertex split, χ one higher). Which one the solid means depends on
/// whether its parts or the outside's meet there, and where crossing curves
/// end the fans are slivers that do not say; a reconstruction of either
/// reading is counted as keeping the topology, the nearest one taken.
long long topology_defects(const MeshTopology& reference, const MeshTopology& result);

/// True where `result` has `reference`'s components and the χ of one of its
/// readings (for a manifold reference, its χ exactly).
bool same_topology(const MeshTopology& reference, const MeshTopology& result);

}  // namespace skelconv
