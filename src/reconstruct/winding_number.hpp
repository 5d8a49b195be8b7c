// src/reconstruct/winding_number.hpp — the generalized winding number of a
// triangle soup (Jacobson, Kavan and Sorkine-Hornung 2013): the sum of its
// triangles' signed solid angles at a point over 4π, 1 inside a closed
// outward surface and 0 outside, k where k sheets overlap, whether or not
// the surface crosses itself. Evaluated through a bounding-volume hierarchy
// whose distant clusters count as dipoles (Barill et al. 2018, first
// order), for `skeletonize --repair` (join_overlaps.cpp). Plain C++:
// internal, not installed.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "skelconv/mesh/triangle_mesh.hpp"

namespace skelconv::detail {

class WindingNumber {
 public:
  /// `accuracy`: a cluster counts as a dipole at a point farther from its
  /// centre than `accuracy` times its radius (the error falls as the
  /// square of that ratio; 2 keeps it under a few hundredths of a turn).
  WindingNumber(const std::vector<Vec3>& vertices, const std::vector<std::array<std::int32_t, 3>>& triangles,
                double accuracy = 2.0);

  /// The winding number at p of every triangle but triangle `skip` (none:
  /// any index past the end). At a point inside triangle `skip`, that is
  /// the mean of the values on its two sides, which differ by one: a point
  /// on the surface itself has no winding number.
  double at(const Vec3& p, std::size_t skip = SIZE_MAX) const;

  /// The signed solid angle of triangle abc seen from p, over 4π (Van
  /// Oosterom and Strackee): positive when p is on its back side.
  static double triangle_fraction(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p);

 private:
  struct Node {
    Vec3 centre;      ///< area-weighted centroid of its triangles
    Vec3 area;        ///< Σ area × unit normal: the dipole
    double radius;    ///< farthest corner from the centre
    std::uint32_t begin, end;  ///< its triangles: order_[begin, end)
    std::int32_t left = -1, right = -1;
  };
  std::int32_t build(std::uint32_t begin, std::uint32_t end);

  const std::vector<Vec3>& vertices_;
  const std::vector<std::array<std::int32_t, 3>>& triangles_;
  double accuracy_;
  std::vector<std::uint32_t> order_;
  std::vector<Node> nodes_;
};

}  // namespace skelconv::detail
