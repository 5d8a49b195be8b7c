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

/// The topology of the closed solid a closed mesh bounds, as that of a
/// closed surface: `t` where the mesh is manifold; where it touches itself
/// at a vertex (two parts of a union that meet at a point, which
/// --repair's union may leave), the solid is one piece through that point,
/// and its boundary thickened there, k fans joined by one neck, has χ
/// lower by k − 1 (the k − 1 vertices a split would add, less the 2(k − 1)
/// the neck takes), the same components. V − E + F alone counts such a
/// vertex once and gives an odd χ that no closed surface has; a sum of
/// fields joins the parts there, so this is the topology a reconstruction
/// is compared with.
MeshTopology solid_topology(const MeshTopology& t);

/// How many defects separate the topology of closed surfaces `result` from
/// `reference`'s: each component too many or too few counts one, and each
/// handle (tunnel) too many or too few counts one, the handles summed over
/// the components (2·components − χ = 2 Σ g). A detached piece or a cavity
/// (one more component of genus 0) is one defect, and an extra tunnel with
/// a cavity is two: the difference in χ alone would let them cancel.
long long topology_defects(const MeshTopology& reference, const MeshTopology& result);

}  // namespace skelconv
