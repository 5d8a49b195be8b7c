// skelconv/mesh/implicit_field.hpp — what the mesher needs to know about a
// field: f and ∇f at a point, points on its skeleton, and its limit at
// infinity.
//
// The mesher (mesh_iso_surface.hpp) sees a field only through this struct, so
// that any field — a Skeleton (the sum of its primitives), a blend tree, a
// test function — can be meshed without the mesher knowing where it comes
// from. Convention: f is larger inside the surface f = iso than outside.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "skelconv/geometry.hpp"
#include "skelconv/skeleton/skeleton.hpp"

namespace skelconv {

/// The relative accuracy of skeleton_field's coarse field: its error (at
/// most 1e-6 of f) moves a grid vertex's start by a few 1e-6 of a voxel,
/// far less than the ~1% of a voxel the grid's linear interpolation leaves
/// it from the surface, so Newton takes as many steps from it; and the
/// grid nodes whose sign it cannot decide (|iso − f| within a few 1e-6 of
/// f) are rare. Tighter costs longer rules; looser moves the starts and
/// leaves more nodes undecided (docs/mesh.md, "Coarse samples", has the
/// measurements).
inline constexpr double skeleton_coarse_tolerance = 1e-6;

/// The mesher calls value, value_and_gradient, the _near ones and the
/// functions they return from several threads at once (the seeds' rays,
/// the grid's continuation and the projection run on every core): they
/// must be safe to, as a Skeleton's are.
struct ImplicitField {
  /// f(p) and ∇f(p). May return +inf (on an inverse-kernel skeleton); may
  /// throw InputError / EvaluationError.
  std::function<FieldSample(const Vec3&)> value_and_gradient;
  /// f(p) alone (cheaper where the gradient is not needed).
  std::function<double(const Vec3&)> value;
  /// When set: whether f(p) ≥ level, the same answer as value(p) >= level
  /// for less work where f is well above the level (Skeleton::reaches).
  /// Unset: value(p) >= level. The seeds' rays ask only this. A field
  /// that replaces `value` must replace or unset this too.
  std::function<bool(const Vec3&, double level)> reaches;
  /// When set: f and ∇f for a run of points within `radius` of `centre`
  /// (a Newton projection's iterates), with what they share done once
  /// (Skeleton::rules_near); as accurate as value_and_gradient, not
  /// necessarily the same bits. Points farther away are evaluated as
  /// value_and_gradient does. Unset: value_and_gradient everywhere.
  std::function<std::function<FieldSample(const Vec3&)>(const Vec3& centre, double radius)> value_and_gradient_near;
  /// The same for value (a grid cell's corners).
  std::function<std::function<double(const Vec3&)>(const Vec3& centre, double radius)> value_near;
  /// Points on the skeleton, so that every connected piece of the skeleton
  /// holds some. The mesher shoots rays from those inside the surface to
  /// seed every component (docs/mesh.md, "Seeding").
  std::vector<Vec3> skeleton_points;
  /// lim f(p) as |p| → ∞. A surface f = iso with iso ≤ far_field is not
  /// bounded. Every skeleton kernel decays to 0, hence the default.
  double far_field = 0.0;
  /// When set: f = 0 exactly at every point outside all these boxes (a
  /// field of compact support). The grid method then skips the blocks of
  /// nodes no box meets (docs/mesh.md, "The grid method"). Unset: no claim.
  std::optional<std::vector<Eigen::AlignedBox3d>> support_boxes;
  /// When set: a sound enclosure [lo, hi] of f over a box (every f(p), p in
  /// the box, exact or as computed, lies in it); may throw, which the
  /// mesher takes as "no claim". The grid method samples only the blocks
  /// whose enclosure contains the iso (docs/mesh.md, "The grid method").
  std::function<std::pair<double, double>(const Eigen::AlignedBox3d&)> enclosure;
  /// When set: the same field to a coarser relative accuracy, for less
  /// work: |f̃ − f| ≤ coarse_tolerance · |f| (and ∇f as the tolerance mode
  /// bounds it, docs/field.md, "Tolerance"). The mesher reads it where that
  /// accuracy is enough: the grid's samples, whose sign it takes from this
  /// field only where |iso − f̃| leaves no doubt about it, and the first
  /// Newton step of each vertex, whose end is checked on this field
  /// (docs/mesh.md, "Coarse samples"). Its own `coarse` is unset.
  std::shared_ptr<const ImplicitField> coarse;
  double coarse_tolerance = 0.0;
  /// True when f is infinite on part of the skeleton (a primitive of a
  /// kernel singular at distance 0, such as the inverse family, or a SCALIS
  /// primitive with a zero radius). Only then may an evaluation on or next to
  /// the skeleton be refused (EvaluationError) and a seed ray be skipped for
  /// it; otherwise every EvaluationError reaches the caller.
  bool infinite_on_skeleton = false;
};

/// The field of `skeleton` (which must outlive the returned object), with
/// `points_per_element` skeleton points per segment / polygon edge
/// (Skeleton::skeleton_points). support_boxes is set when every primitive
/// has compact support (field/support_box.hpp) and every blend node is a sum
/// or a union: sums and maxima of exact zeros are zero (a super-elliptic
/// node may add a constant where its children are 0, Ferley's r_k > c).
/// enclosure is interval::enclose (interval/enclosure.hpp). f and ∇f are
/// Skeleton's tolerance mode at `tolerance` (0: exact; docs/field.md,
/// "Tolerance"), the default for meshes. With 0 < tolerance <
/// skeleton_coarse_tolerance, `coarse` is the tolerance mode at
/// skeleton_coarse_tolerance (on a skeleton the mode does not cover, the
/// exact field: the same values).
ImplicitField skeleton_field(const Skeleton& skeleton, int points_per_element = 4,
                             double tolerance = Skeleton::default_tolerance);

}  // namespace skelconv
