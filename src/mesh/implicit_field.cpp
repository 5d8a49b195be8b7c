// Implementation of skelconv/mesh/implicit_field.hpp.
#include "skelconv/mesh/implicit_field.hpp"

#include "skelconv/skeleton.hpp"

namespace skelconv {

ImplicitField skeleton_field(const Skeleton& skeleton, int points_per_element) {
  ImplicitField field;
  field.value_and_gradient = [&skeleton](const Vec3& p) { return skeleton.value_and_gradient(p); };
  field.value = [&skeleton](const Vec3& p) { return skeleton.value(p); };
  field.skeleton_points = skeleton.skeleton_points(points_per_element);
  field.far_field = 0.0;  // every kernel family (SPEC §1, §4) decays to 0 at infinity
  return field;
}

}  // namespace skelconv
