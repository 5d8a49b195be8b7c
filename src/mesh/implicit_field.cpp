// Implementation of skelconv/mesh/implicit_field.hpp.
#include "skelconv/mesh/implicit_field.hpp"

#include <type_traits>
#include <variant>

#include "skelconv/field/support_box.hpp"
#include "skelconv/interval/enclosure.hpp"
#include "skelconv/kernels/kernel_list.hpp"
#include "skelconv/skeleton/skeleton.hpp"

namespace skelconv {
namespace {

/// Whether every node under `id` is a sum or a union (see the header).
bool sums_and_unions_only(const Skeleton& skeleton, Skeleton::NodeId id) {
  if (skeleton.blend(id).kind == BlendKind::super_elliptic) return false;
  for (std::size_t k = 0; k < skeleton.child_count(id); ++k) {
    const auto [is_blend, index] = skeleton.child(id, k);
    if (is_blend && !sums_and_unions_only(skeleton, index)) return false;
  }
  return true;
}

/// The primitives' support boxes, if the field is 0 outside them.
std::optional<std::vector<Eigen::AlignedBox3d>> support_boxes_of(const Skeleton& skeleton) {
  if (!sums_and_unions_only(skeleton, Skeleton::root)) return std::nullopt;
  std::vector<Eigen::AlignedBox3d> boxes;
  for (const Primitive& primitive : skeleton.primitives()) {
    const std::optional<SupportBox> box = support_box(primitive);
    if (!box) return std::nullopt;  // infinite support
    boxes.emplace_back(box->lo, box->hi);
  }
  return boxes;
}

/// Coarse enclosures for the mesher's block test: a segment in pieces of
/// about two box diagonals (not half of one), a triangle cut at most once.
/// Looser, but each costs a few primitive evaluations' worth: the test only
/// has to prove blocks far from the surface empty; a block it cannot
/// decide is sampled, so the mesh does not depend on these values.
constexpr interval::EnclosureOptions mesher_enclosure_options{.pieces_per_box = 0.5, .max_triangle_levels = 1};
/// Whether f is infinite somewhere on the skeleton (see the header).
bool infinite_on_skeleton(const Skeleton& skeleton) {
  for (const Primitive& primitive : skeleton.primitives()) {
    const bool infinite = std::visit(
        [](const auto& p) {
          using P = std::decay_t<decltype(p)>;
          if (kernels::family_facts(p.kernel().family).singular_at_zero) return true;
          if constexpr (std::is_same_v<P, ScalisSegment>) return p.tau0() == 0.0 || p.tau1() == 0.0;
          if constexpr (std::is_same_v<P, ScalisTriangle>) {
            return p.radii()[0] == 0.0 || p.radii()[1] == 0.0 || p.radii()[2] == 0.0;
          }
          return false;
        },
        primitive);
    if (infinite) return true;
  }
  return false;
}

/// skeleton_field's evaluations of `skeleton` at `tolerance`, into `field`.
void set_evaluations(ImplicitField& field, const Skeleton& skeleton, double tolerance) {
  field.value_and_gradient = [&skeleton, tolerance](const Vec3& p) {
    return skeleton.value_and_gradient(p, tolerance);
  };
  field.value = [&skeleton, tolerance](const Vec3& p) { return skeleton.value(p, tolerance); };
  field.reaches = [&skeleton, tolerance](const Vec3& p, double level) {
    return skeleton.reaches(p, level, tolerance);
  };
  if (tolerance > 0.0) {
    field.value_and_gradient_near = [&skeleton, tolerance](const Vec3& centre, double radius) {
      return [&skeleton, rules = skeleton.rules_near(centre, radius, tolerance)](const Vec3& p) {
        return skeleton.value_and_gradient(p, rules);
      };
    };
    field.value_near = [&skeleton, tolerance](const Vec3& centre, double radius) {
      return [&skeleton, rules = skeleton.rules_near(centre, radius, tolerance)](const Vec3& p) {
        return skeleton.value(p, rules);
      };
    };
  }
}

}  // namespace

ImplicitField skeleton_field(const Skeleton& skeleton, int points_per_element, double tolerance) {
  Skeleton::checked_tolerance(tolerance);
  ImplicitField field;
  set_evaluations(field, skeleton, tolerance);
  if (tolerance > 0.0 && tolerance < skeleton_coarse_tolerance) {
    auto coarse = std::make_shared<ImplicitField>();
    set_evaluations(*coarse, skeleton, skeleton_coarse_tolerance);
    field.coarse = std::move(coarse);
    field.coarse_tolerance = skeleton_coarse_tolerance;
  }
  field.skeleton_points = skeleton.skeleton_points(points_per_element);
  field.far_field = 0.0;  // every kernel family (docs/mathematics.md §1, §4) decays to 0 at infinity
  field.support_boxes = support_boxes_of(skeleton);
  field.enclosure = [&skeleton](const Eigen::AlignedBox3d& box) {
    const interval::Interval f =
        interval::enclose(skeleton, interval::Box{box.min(), box.max()}, mesher_enclosure_options);
    return std::pair{f.lower(), f.upper()};
  };
  field.infinite_on_skeleton = infinite_on_skeleton(skeleton);
  return field;
}

}  // namespace skelconv
