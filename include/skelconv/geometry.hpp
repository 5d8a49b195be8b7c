// skelconv/geometry.hpp — the vector types of the public API, and FieldSample
// (a field value with its gradient).
//
// The public API speaks Eigen; the generated kernels take plain
// std::array (include/skelconv/primitives/segment_input.hpp) so that they do not depend
// on Eigen and work on any scalar type. These helpers convert between both.
#pragma once

#include <array>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

namespace skelconv {

using Vec3 = Eigen::Vector3d;

/// Eigen vector → the std::array form that SegmentInput uses.
inline std::array<double, 3> to_array(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

/// std::array (as returned by generated gradients) → Eigen vector.
inline Vec3 to_vec3(const std::array<double, 3>& v) { return {v[0], v[1], v[2]}; }

/// A field value and its gradient at one point.
struct FieldSample {
  double value = 0.0;
  Vec3 gradient = Vec3::Zero();
};

}  // namespace skelconv
