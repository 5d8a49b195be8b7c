// skelconv/primitives/polygon.hpp — the polygon primitive: the convolution field of a
// planar polygon (docs/mathematics.md §3, Hubert 2012 §5–8).
//
//     f(P) = ∬_Ω K(|P − Q|) dQ
//
// over the closed polygon Ω, with the kernel K of a KernelSpec. The closed
// forms live in skelconv/primitives/polygon_field.hpp; this class validates the polygon
// once (the guarantees that contract asks of its caller), stores it in a
// canonical orientation, and handles the two cases the closed forms must
// not see:
//   - compact kernels: P at distance ≥ R from the whole closed polygon. The
//     ball of radius R around P misses Ω, and f = 0, ∇f = 0 exactly, as for
//     a segment. The distance is |z| (the height of P above the plane) when
//     the foot of P in the plane lies inside Ω, else the distance from P to
//     the nearest edge; the edges are asked first (a few flops each), the
//     foot's location only when every edge is out of reach; computed in
//     double: a point
//     misjudged by rounding lies where the kernel and its derivative vanish
//     (the compact kernels here are at least (1 − r²/R²)²).
//   - inverse kernels: P in the closed polygon. The integrand r^(-i) is not
//     integrable there (i ≥ 2), f = +∞. By convention value() returns +inf
//     and gradient() returns (+inf, +inf, +inf), as for a segment
//     (segment.hpp). "In the closed polygon" is decided on the doubles:
//     z = normal() · (P − vertices()[0]) is exactly 0, and P lies inside Ω
//     or on its boundary, decided with exact predicates on the polygon
//     projected along the normal's largest coordinate axis. For a polygon in
//     an axis-aligned plane (z = c) both steps are exact: P is on it iff
//     P.z == c and P is inside or on the boundary. For a tilted plane a
//     double P rarely lies exactly on it; a P that misses it by rounding is
//     evaluated by the closed form (a large finite f).
// Everything else goes to the closed form, evaluated in the polygon's own
// frame (skelconv/detail/scaled_frame.hpp: coordinates scaled by a power of two
// that brings the diameter into [1, 2), s and R with it) and
// scaled back exactly by the kernel's homogeneity, so that polygons at any
// position and scale give the same relative accuracy. Its result is
// checked: the field is finite there, so a NaN or ±inf result, or a value
// outside the double range, throws EvaluationError.
//
// Validation (constructor, InputError naming the field), scale invariant:
// lengths without squaring; area, planarity and the exact predicates on the
// given doubles scaled by a power of two to the diameter (a valid polygon scaled by 2^±400 stays valid, with the same messages
// scaled):
//   - at least 3 vertices, all finite;
//   - no vertex equal to the next one; the last vertex equal to the first is
//     rejected too (the boundary closes by itself: list each vertex once) —
//     rejected rather than silently dropped, like every other surprise in a
//     skeleton file;
//   - every edge at least Segment::degenerate_length_ratio times the largest
//     coordinate magnitude of its end points (each edge contributes a segment
//     integral: the same accuracy argument as for a segment);
//   - non-zero area: |N|/2 ≥ degenerate_area_ratio · diameter², N Newell's
//     normal (twice the vector area), diameter the largest distance between
//     two vertices;
//   - coplanar: every vertex within coplanarity_tolerance · diameter of the
//     plane through the vertices' centroid with normal N (Newell's plane);
//   - simple: no two edges meet except consecutive edges at their common
//     vertex (CGAL::is_simple_2, exact predicates, on the projection along
//     the normal's largest coordinate axis);
//   - a kernel degree the closed forms offer (polygon_supported_degrees):
//     inverse 3…12, cauchy 3…12, compact 4, 6, …, 12; inverse degree 2 is
//     excluded by the contour formula (docs/mathematics.md §3); s > 0 (cauchy), R > 0
//     (compact).
//
// Orientation: the field does not depend on it, so either boundary order is
// accepted. The polygon is stored canonically: the unit normal is Newell's
// normal turned so that its largest-magnitude coordinate is positive (the
// first such axis on a tie), the vertices counter-clockwise about it (the
// given order, or reversed), starting at the lexicographically smallest
// vertex. Both orientations of one polygon therefore store the same vertex
// sequence and give bit-identical fields.
#pragma once

#include <array>
#include <initializer_list>
#include <utility>
#include <span>
#include <vector>

#include "skelconv/errors.hpp"
#include "skelconv/geometry.hpp"
#include "skelconv/kernels/kernel_spec.hpp"
#include "skelconv/detail/scaled_frame.hpp"
#include "skelconv/primitives/segment_input.hpp"  // KernelFamily

namespace skelconv {

// The closed forms' input (skelconv/primitives/polygon_field.hpp). That header pulls in
// the generated polygon table (~7,000 lines): only src/primitives/polygon.cpp
// and code that asks for the closed forms directly include it.
template <class T>
struct PolygonInput;
namespace generated {
template <class T>
struct PolygonEdgeKernel;
}

class Polygon {
 public:
  /// Coplanarity: the largest distance of a vertex from Newell's plane may
  /// be this fraction of the diameter. A deviation δ changes the field by a
  /// relative O(δ / diameter), far below anything a convolution surface
  /// shows, while vertices computed in double (rotated, transformed) or
  /// printed with 12 or more significant digits stay well inside it.
  static constexpr double coplanarity_tolerance = 1e-9;

  /// Zero area: a polygon whose area is below this fraction of diameter² is
  /// degenerate, and rejected. Its normal, and with it the plane, would be
  /// known to fewer than ~8 significant digits from vertices rounded to
  /// double (the same limit as Segment::degenerate_length_ratio).
  static constexpr double degenerate_area_ratio = 1e-8;

  /// Validates everything (see the file comment); throws InputError naming
  /// the offending field ("vertices", "vertices[3]", "kernel.degree",
  /// "kernel.s", "kernel.R") and the problem. Vertex indices in messages are
  /// those of `vertices` as given.
  Polygon(std::span<const Vec3> vertices, const KernelSpec& kernel);
  Polygon(std::initializer_list<Vec3> vertices, const KernelSpec& kernel)
      : Polygon(std::span<const Vec3>(vertices.begin(), vertices.size()), kernel) {}

  /// The vertices in canonical order: counter-clockwise about normal(),
  /// starting at the lexicographically smallest one.
  const std::vector<Vec3>& vertices() const { return vertices_; }
  /// Unit normal of the plane (canonical direction, see the file comment).
  const Vec3& normal() const { return normal_; }
  /// Area of the polygon, |N|/2 with Newell's N.
  double area() const { return area_; }
  const KernelSpec& kernel() const { return kernel_; }

  /// The kernel degrees the polygon closed forms offer for `family`,
  /// ascending (polygon_supported_degrees).
  static std::vector<int> supported_degrees(KernelFamily family);

  /// f(P). Throws InputError if P is not finite, EvaluationError if the
  /// closed form fails in double precision (see the file comment).
  double value(const Vec3& p) const;
  /// ∇f(P), same rules as value().
  Vec3 gradient(const Vec3& p) const;
  /// f(P) and ∇f(P) together.
  FieldSample value_and_gradient(const Vec3& p) const;

 private:
  /// What an evaluation at P has to do (see the file comment).
  enum class Case {
    call_closed_form,         ///< the closed form applies
    outside_compact_support,  ///< compact kernel, P farther than R: f = 0
    on_inverse_singularity,   ///< inverse kernel, P in the closed polygon: f = +inf
  };
  /// Checks that P is finite, puts it in the frame (frame_p) and picks the case.
  Case prepare(const Vec3& p, Vec3& frame_p) const;
  /// Exact on the (frame's) doubles, see the file comment.
  bool in_closed_polygon(const Vec3& frame_p) const;
  /// Finite support: the ball of radius R around P misses the closed polygon (P in the frame).
  bool support_misses_polygon(const Vec3& frame_p) const;
  /// The closed forms' view of this polygon, in the frame (spans
  /// vertex_arrays_), with the generated kernel of `level` (one of levels_).
  struct Level;
  PolygonInput<double> closed_form_input(const Level& level) const;
  /// Σ_j c_j × closed form j at P in the frame (a family given as compact
  /// levels, or one level of weight 1): f', and ∇f' into `gradient` when not null.
  double sum_of_levels(const Vec3& frame_p, std::array<double, 3>* gradient) const;
  /// f' and ∇f' of the frame back in the world (scaled_frame.hpp); throws
  /// EvaluationError for a non-finite result or one outside the double range.
  double restore_value(double f, const char* function, const Vec3& p) const;
  Vec3 restore_gradient(const std::array<double, 3>& g, const char* function, const Vec3& p) const;

  std::vector<Vec3> vertices_;
  /// The polygon's frame (skelconv/detail/scaled_frame.hpp): the diameter scaled
  /// into [1, 2). The checks, the predicates and the closed forms run there.
  ScaledFrame frame_;
  /// f has units length^value_power_: 2 − i (inverse) or 2.
  int value_power_ = 2;
  /// frame_'s powers of two for value_power_, computed once: prepare and
  /// the restore functions run at every evaluation.
  FrameFactors factors_;
  std::vector<std::array<double, 3>> vertex_arrays_;  ///< vertices_ in the frame, as the closed forms take them
  Vec3 normal_ = Vec3::UnitZ();
  double area_ = 0.0;
  KernelSpec kernel_;
  /// The generated kernels whose weighted sum is the field: {1, kernel_} for
  /// the families of the generated table, {c_j, k_R^(i_j)} for a trait with
  /// compact_levels (soft, wyvill). Their s and R in the frame (frame_).
  struct Level {
    double coefficient = 1.0;
    KernelSpec kernel;
    /// Its generated edge kernels, looked up once here rather than at every
    /// point (a static table: the pointer survives copies of the Polygon).
    const generated::PolygonEdgeKernel<double>* edge_kernel = nullptr;
  };
  std::vector<Level> levels_;
  double support_radius_ = 0.0;  ///< from the trait, world units: K = 0 beyond (+inf: none)
  /// Finite support only: support_radius_ in the frame, and each edge
  /// vertex_arrays_[k] → [k + 1] with its squared length (support_misses_polygon).
  double frame_support_radius_ = 0.0;
  std::vector<Vec3> frame_edges_;
  std::vector<double> frame_edge_length2_;
  bool singular_at_zero_ = false;
  /// The vertices in the frame projected along normal_'s largest axis
  /// (dropped_axis_), keeping the other two in cyclic order:
  /// counter-clockwise in 2D too.
  int dropped_axis_ = 2;
  std::vector<std::array<double, 2>> projected_vertices_;
};

}  // namespace skelconv
