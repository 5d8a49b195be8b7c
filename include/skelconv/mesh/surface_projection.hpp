// skelconv/mesh/surface_projection.hpp — moving mesh vertices exactly onto
// f = iso and giving them the exact normal.
//
// Each vertex p is moved by Newton steps along the exact gradient,
//     p ← p − (f(p) − iso) ∇f(p) / |∇f(p)|²,
// until the first-order distance to the surface |f − iso| / |∇f| is at most
// `tolerance` (skelconv mesh: 1e-9 × the mesh's bounding-box diagonal). A
// step is never longer than `max_step` and is halved while it does not
// reduce |f − iso| (Newton from a vertex already close to the surface
// converges quadratically; the safeguards only matter near critical points).
// Where Newton cannot go on (outside every compact support f = 0 and
// ∇f = 0; or steps that stop reducing |f − iso| at a kink), a point on the
// other side of the level is looked for within `max_step` and the segment
// to it bisected down to `tolerance`: the surface crosses it, so the vertex
// ends within the tolerance of the surface all the same.
// The normal written is the exact outward unit normal −∇f/|∇f| at the final
// position (f is larger inside).
#pragma once

#include "skelconv/mesh/implicit_field.hpp"
#include "skelconv/mesh/triangle_mesh.hpp"

namespace skelconv {

struct ProjectionOptions {
  double tolerance = 0.0;  ///< bound on |f − iso| / |∇f| (a length)
  double max_step = 0.0;   ///< longest single move (a length)
  int max_iterations = 60;
  /// Threads projecting the vertices (0: every core); the mesh is the same
  /// for any count.
  unsigned threads = 0;
};

/// Projects every vertex of `mesh` onto f = iso and fills mesh.normals.
/// Throws EvaluationError naming the vertex if one cannot be brought within
/// the tolerance (no point on the other side of the level within max_step,
/// or a zero gradient at the end).
void project_to_surface(TriangleMesh& mesh, const ImplicitField& field, double iso, const ProjectionOptions& options);

}  // namespace skelconv
