// skelconv/skeleton/skeleton.hpp — a skeleton: a tree of blend nodes whose leaves are
// primitives, and the field it defines.
//
// The root is a sum (the file's top-level "primitives"): convolution is
// linear in the skeleton (Hubert 2012 §2), so a skeleton without blend nodes
// has f = Σ_k f_k, ∇f = Σ_k ∇f_k, as before blends existed. Any child of a
// node may be a primitive (primitives/primitive.hpp) or another blend node
// (skeleton/blend.hpp: sum, union, super_elliptic), to any depth.
//
// Evaluation (docs/field.md):
//   - every sum, union and (not angle-weighted) super-elliptic node with at
//     least min_indexed_children children indexes its compact-support
//     primitive children in a SupportGrid (field/support_grid.hpp): a point
//     visits only those whose support box contains it, and every
//     infinite-support child. The indexed sum is bit-identical to the plain
//     one (Acceleration::plain), which visits every child: same terms, same
//     order, minus exact zeros; a union or super-elliptic node sees the
//     skipped children as exact zeros in their places (docs/field.md: the
//     same bits, up to the sign of a zero maximum of a union);
//   - the index is built on first evaluation after a change (or by
//     prepare()), once, safely from several threads;
//   - errors are located like the file: a primitive's InputError or
//     EvaluationError is rethrown at its location, e.g.
//     "primitives[1].children[0].kernel.R"; a blend node's at its own.
// A Skeleton is safe to evaluate from many threads at once (field/batch.hpp),
// but add(), add_blend() and set_iso() must not run concurrently with
// anything else.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "skelconv/geometry.hpp"
#include "skelconv/primitives/primitive.hpp"
#include "skelconv/skeleton/blend.hpp"

namespace skelconv {

namespace detail {
struct SkeletonIndex;  // src/skeleton/skeleton_index.hpp
struct IndexCache;
}  // namespace detail

class Skeleton {
 public:
  using NodeId = std::size_t;
  /// The root: the sum of the top-level "primitives".
  static constexpr NodeId root = 0;
  /// Sum nodes with fewer children are evaluated by the plain loop: below
  /// this, a grid costs more than it saves (and both give the same bits).
  static constexpr std::size_t min_indexed_children = 8;
  /// Relative step of the central differences that give the Hessian-vector
  /// products of the angle-weighted super_elliptic blend (blend.hpp):
  /// h = step · (1 + |P|∞). The error of a central difference of the
  /// children's exact gradients is ~h² |∇³f|/6 + ε |∇f|/h; at 1e-5 both are
  /// ~1e-10 relative on a skeleton of unit size.
  static constexpr double angle_hessian_step = 1e-5;

  enum class Acceleration {
    indexed,  ///< sum, union and super-elliptic nodes skip compact primitives whose support misses P
    plain,    ///< every primitive is evaluated (same bits; a union's zero maximum may differ in sign, docs/field.md)
  };

  Skeleton();
  /// The sum of `primitives` (the top-level list), surface level `iso`.
  explicit Skeleton(std::vector<Primitive> primitives, double iso = 1.0);
  Skeleton(const Skeleton&) = default;
  Skeleton& operator=(const Skeleton&) = default;
  /// Moves leave `other` an empty skeleton (f = 0), still safe to use.
  Skeleton(Skeleton&& other);
  Skeleton& operator=(Skeleton&& other);
  void swap(Skeleton& other) noexcept;

  /// Adds `primitive` as the last child of blend node `parent`; returns its
  /// index in primitives().
  std::size_t add(Primitive primitive, NodeId parent = root);
  /// Adds a blend node as the last child of `parent`; returns its id, the
  /// parent of its own children. Its parameters are checked against its
  /// children on first evaluation (validate()).
  NodeId add_blend(Blend blend, NodeId parent = root);

  /// Every primitive of the tree, in the order added (depth-first, file
  /// order, for a file).
  const std::vector<Primitive>& primitives() const { return primitives_; }
  std::size_t size() const { return primitives_.size(); }
  bool empty() const { return primitives_.empty(); }
  /// Where primitive k stands, as in the file: "primitives[1].children[0]".
  const std::string& location(std::size_t k) const { return primitive_locations_[k]; }
  /// The blend of node `id` and its number of children.
  const Blend& blend(NodeId id) const { return nodes_[id].blend; }
  std::size_t child_count(NodeId id) const { return nodes_[id].children.size(); }
  /// Child k of node `id`, for walking the tree from outside (the interval
  /// enclosures of skelconv/interval/): {true, node id} for a blend node,
  /// {false, index into primitives()} for a primitive.
  std::pair<bool, std::size_t> child(NodeId id, std::size_t k) const {
    const Child& c = nodes_[id].children[k];
    return {c.is_blend, c.index};
  }

  /// The level of the surface the skeleton describes (the file's "iso",
  /// default 1). set_iso throws InputError ("iso") unless finite and > 0.
  double iso() const { return iso_; }
  void set_iso(double iso);

  /// Checks every blend node against its children (validate_blend),
  /// throwing InputError located at the node ("primitives[2].children").
  void validate() const;
  /// Validates and builds the index now (otherwise the first evaluation
  /// does). Throws what validate() throws.
  void prepare() const;

  /// f(P), ∇f(P), both. An inverse primitive evaluated on its own skeleton
  /// contributes +inf (segment.hpp, polygon.hpp, primitives/point.hpp), and
  /// every blend above it returns +inf with gradient (+inf, +inf, +inf).
  /// InputError for a non-finite P (no location) or an invalid blend node;
  /// EvaluationError where a value cannot be computed.
  double value(const Vec3& p) const;
  Vec3 gradient(const Vec3& p) const;
  FieldSample value_and_gradient(const Vec3& p) const;
  /// With `tolerance` > 0: the tolerance mode below.
  FieldSample value_and_gradient(const Vec3& p, Acceleration acceleration, double tolerance = 0.0) const;

  /// The tolerance mode (docs/field.md, "Tolerance"): on a skeleton that is a
  /// list of at least min_far_rule_segments Cauchy segments, classical (no
  /// negative weight coefficient) or SCALIS (both radii > 0), of one kind or
  /// both, segments far from P are evaluated by short Gauss–Legendre rules
  /// whose a-priori bounds keep f within tolerance · f of the exact field
  /// (to rounding), and each component of ∇f within tolerance · f times the
  /// mean over the segments of (i_k/2) g_k, g_k = √s_k (classical) or
  /// 1/(σ_k min τ_k) (SCALIS): the bound of |∇f|/f of each kernel. Other
  /// skeletons, and tolerance 0, give the exact evaluation above.
  /// InputError ("tolerance") unless 0 ≤ tolerance < 1.
  double value(const Vec3& p, double tolerance) const;
  /// Whether f(P) ≥ level, as value(p, tolerance) >= level decides it, for
  /// less work where f is well above the level: a sum whose terms are all
  /// ≥ 0 (SCALIS primitives, points of positive weight, sums of them)
  /// stops adding once its running total, in value's order, is twice the
  /// level (adding terms ≥ 0 never lowers a sum of doubles; the margin
  /// covers a term that rounds a few units in the last place below 0).
  /// Other skeletons, and a level ≤ 0, take value(p, tolerance). Errors as
  /// value's, except those of terms it no longer needs.
  bool reaches(const Vec3& p, double level, double tolerance = 0.0) const;
  FieldSample value_and_gradient(const Vec3& p, double tolerance) const;
  /// The tolerance mode's rules chosen once for every point within `radius`
  /// of `centre` (docs/field.md, "Tolerance", "Near a point"): each
  /// segment's rule meets its bound at every point of that ball, so a
  /// sequence of evaluations there (Newton's iterates towards the surface)
  /// pays for the choice once. Evaluated at a point outside the ball, or on
  /// a skeleton the tolerance mode does not cover, it is the plain
  /// tolerance mode. InputError ("tolerance") as above.
  class NearbyRules {
   public:
    NearbyRules() = default;

   private:
    friend class Skeleton;
    Vec3 centre_ = Vec3::Zero();
    double radius_ = -1;  ///< < 0: no choice made
    double tolerance_ = 0;
    std::vector<std::uint8_t> nodes_;  ///< per far rule, as the tolerance mode chooses them
    /// The index they were chosen from (kept alive): a skeleton changed
    /// since has another, and the choice no longer applies.
    std::shared_ptr<const void> index_;
  };
  NearbyRules rules_near(const Vec3& centre, double radius, double tolerance) const;
  FieldSample value_and_gradient(const Vec3& p, const NearbyRules& rules) const;
  double value(const Vec3& p, const NearbyRules& rules) const;
  /// The mesher's and the Python module's default (docs/field.md, "Tolerance").
  static constexpr double default_tolerance = 1e-12;
  /// Lists of fewer segments stay exact in the tolerance mode: choosing the
  /// rules costs ~20 ns a segment, more than they save on a handful
  /// (Skeleton.field, one thread: 0.85× the exact speed on 1 segment, 1.03×
  /// on 10, 1.18× on 24, 1.56× on 100).
  static constexpr std::size_t min_far_rule_segments = 16;
  /// `tolerance`, or InputError ("tolerance") unless 0 ≤ tolerance < 1.
  static double checked_tolerance(double tolerance);

  /// Points on the skeleton itself: for every primitive of the tree its
  /// defining points (ends, vertices, a point's centre) and `per_element` − 1
  /// evenly spaced points between them (along each segment and polygon
  /// edge, and a fan of points inside each polygon and triangle towards its
  /// centroid), so that every connected piece of the skeleton holds some of
  /// them. The mesher (skelconv mesh) shoots rays from them to find every
  /// component of the surface. `per_element` ≥ 1.
  std::vector<Vec3> skeleton_points(int per_element = 4) const;

 private:
  /// What an evaluation must produce.
  enum class Need { value, gradient, both };
  struct Child {
    bool is_blend = false;
    std::size_t index = 0;  ///< into nodes_ or primitives_
  };
  struct Node {
    Blend blend;
    std::vector<Child> children;
    std::string location;  ///< "" for the root, else "primitives[1].children[2]"
  };

  std::string child_location(NodeId parent) const;
  void changed();
  FieldSample evaluate(const Vec3& p, Need need, Acceleration acceleration, double tolerance,
                       const std::uint8_t* chosen_nodes = nullptr) const;
  FieldSample evaluate_primitive_list(const Vec3& p, Need need) const;
  FieldSample evaluate_child(const Child& child, const Vec3& p, Need need, const detail::SkeletonIndex* index) const;
  FieldSample evaluate_leaf(std::size_t k, const Vec3& p, Need need) const;
  FieldSample evaluate_node(NodeId id, const Vec3& p, Need need, const detail::SkeletonIndex* index) const;
  FieldSample evaluate_sum(NodeId id, const Vec3& p, Need need, const detail::SkeletonIndex* index) const;
  FieldSample evaluate_angle_blend(NodeId id, const Vec3& p, Need need, const detail::SkeletonIndex* index) const;
  /// reaches' walk of sum node `id` (SkeletonIndex::nonnegative_sum), its
  /// parents' running total `before`: true once before + the running total
  /// reaches `stop`, else false with `total` the node's value.
  bool sum_reaches(NodeId id, const Vec3& p, double stop, const detail::SkeletonIndex& index, double before,
                   double& total) const;

  std::vector<Primitive> primitives_;
  std::vector<std::string> primitive_locations_;
  std::vector<Node> nodes_;
  double iso_ = 1.0;
  /// The lazily built index, shared by copies (it holds no pointers into
  /// the skeleton) and replaced on every change.
  mutable std::shared_ptr<detail::IndexCache> cache_;
};

}  // namespace skelconv
