// skelconv/interval/octree.hpp — classifying space with the enclosures
// (docs/bound.md): a box is cut into 8 children level by level; a cell
// whose enclosure decides it (inside / outside) is not cut further, every
// undetermined cell is. Near a smooth surface the undetermined cells at
// level d number about area / (cell size)², i.e. ×4 per level, not ×8.
#pragma once

#include <cstddef>
#include <vector>

#include "skelconv/interval/enclosure.hpp"

namespace skelconv::interval {

/// The deepest octree `skelconv bound --octree` and the Python module
/// accept: 8 levels already mean up to 8^8 cells near a surface of fractal
/// area; 10 keeps a run within minutes.
inline constexpr int max_octree_depth = 10;

struct LevelCounts {
  std::size_t inside = 0, outside = 0, undetermined = 0;
};

/// Counts per level 0..depth (level 0 = the box itself), cells of level
/// d + 1 being the children of the undetermined cells of level d.
std::vector<LevelCounts> classify_octree(const Skeleton& skeleton, const Box& box, int depth, double iso,
                                         const EnclosureOptions& options = {});

}  // namespace skelconv::interval
