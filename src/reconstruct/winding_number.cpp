// Implementation of winding_number.hpp.
#include "winding_number.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace skelconv::detail {

namespace {
constexpr std::uint32_t leaf_size = 8;
}

WindingNumber::WindingNumber(const std::vector<Vec3>& vertices,
                             const std::vector<std::array<std::int32_t, 3>>& triangles, double accuracy)
    : vertices_(vertices), triangles_(triangles), accuracy_(accuracy), order_(triangles.size()) {
  for (std::uint32_t i = 0; i < order_.size(); ++i) order_[i] = i;
  nodes_.reserve(2 * triangles.size() / leaf_size + 2);
  if (!triangles.empty()) build(0, std::uint32_t(triangles.size()));
}

std::int32_t WindingNumber::build(std::uint32_t begin, std::uint32_t end) {
  const auto corner = [&](std::uint32_t t, int k) -> const Vec3& {
    return vertices_[std::size_t(triangles_[t][std::size_t(k)])];
  };
  Node node{Vec3::Zero(), Vec3::Zero(), 0.0, begin, end};
  double total = 0.0;
  Vec3 lo = Vec3::Constant(INFINITY), hi = -lo, mean = Vec3::Zero();
  for (std::uint32_t i = begin; i < end; ++i) {
    const std::uint32_t t = order_[i];
    const Vec3 n = 0.5 * (corner(t, 1) - corner(t, 0)).cross(corner(t, 2) - corner(t, 0));
    const Vec3 centroid = (corner(t, 0) + corner(t, 1) + corner(t, 2)) / 3.0;
    const double area = n.norm();
    node.area += n;
    node.centre += area * centroid;
    mean += centroid;
    total += area;
    lo = lo.cwiseMin(centroid), hi = hi.cwiseMax(centroid);
  }
  // Zero-area clusters have no area-weighted centre: the centroids' mean.
  node.centre = total > 0.0 ? Vec3(node.centre / total) : Vec3(mean / double(end - begin));
  for (std::uint32_t i = begin; i < end; ++i)
    for (int k = 0; k < 3; ++k) node.radius = std::max(node.radius, (corner(order_[i], k) - node.centre).norm());
  const std::int32_t index = std::int32_t(nodes_.size());
  nodes_.push_back(node);
  if (end - begin <= leaf_size) return index;
  // Split at the median centroid along the widest axis of the centroids.
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  const std::uint32_t middle = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                   [&](std::uint32_t a, std::uint32_t b) {
                     const double ca = corner(a, 0)[axis] + corner(a, 1)[axis] + corner(a, 2)[axis];
                     const double cb = corner(b, 0)[axis] + corner(b, 1)[axis] + corner(b, 2)[axis];
                     return ca < cb || (ca == cb && a < b);
                   });
  const std::int32_t left = build(begin, middle);
  const std::int32_t right = build(middle, end);
  nodes_[std::size_t(index)].left = left;
  nodes_[std::size_t(index)].right = right;
  return index;
}

double WindingNumber::triangle_fraction(const Vec3& a0, const Vec3& b0, const Vec3& c0, const Vec3& p) {
  const Vec3 a = a0 - p, b = b0 - p, c = c0 - p;
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  return std::atan2(a.dot(b.cross(c)), la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la) /
         (2.0 * std::numbers::pi);
}

double WindingNumber::at(const Vec3& p, std::size_t skip) const {
  if (nodes_.empty()) return 0.0;
  double sum = 0.0;
  std::vector<std::int32_t> stack{0};
  while (!stack.empty()) {
    const Node& node = nodes_[std::size_t(stack.back())];
    stack.pop_back();
    const Vec3 d = node.centre - p;
    const double distance = d.norm();
    if (distance > accuracy_ * node.radius) {
      sum += node.area.dot(d) / (4.0 * std::numbers::pi * distance * distance * distance);
    } else if (node.left < 0) {
      for (std::uint32_t i = node.begin; i < node.end; ++i) {
        const std::uint32_t t = order_[i];
        if (t == skip) continue;
        const auto& tri = triangles_[t];
        sum += triangle_fraction(vertices_[std::size_t(tri[0])], vertices_[std::size_t(tri[1])],
                                 vertices_[std::size_t(tri[2])], p);
      }
    } else {
      stack.push_back(node.left);
      stack.push_back(node.right);
    }
  }
  return sum;
}

}  // namespace skelconv::detail
