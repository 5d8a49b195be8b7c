// Implementation of skelconv/field/support_grid.hpp.
#include "skelconv/field/support_grid.hpp"

#include <algorithm>

namespace skelconv {
namespace {

/// The median of the boxes' largest sides: the cell side to start from, so
/// that a typical support spans about 2 cells per axis.
double median_extent(std::span<const SupportBox> boxes) {
  std::vector<double> extents;
  for (const SupportBox& box : boxes) extents.push_back((box.hi - box.lo).maxCoeff());
  std::nth_element(extents.begin(), extents.begin() + std::ptrdiff_t(extents.size() / 2), extents.end());
  return extents[extents.size() / 2];
}

}  // namespace

SupportGrid::SupportGrid(std::span<const std::optional<SupportBox>> boxes, const Limits& limits)
    : item_count_(boxes.size()), boxes_(boxes.size()) {
  std::vector<SupportBox> bounded;
  for (std::size_t k = 0; k < boxes.size(); ++k) {
    if (boxes[k]) {
      boxes_[k] = *boxes[k];
      bounded.push_back(*boxes[k]);
    }
  }
  if (bounded.empty()) {
    for (std::size_t k = 0; k < boxes.size(); ++k) always_.push_back(std::uint32_t(k));
    return;
  }
  lo_ = bounded[0].lo;
  hi_ = bounded[0].hi;
  for (const SupportBox& box : bounded) {
    lo_ = lo_.cwiseMin(box.lo);
    hi_ = hi_.cwiseMax(box.hi);
  }
  // Cells about half a typical support across, coarsened until the grid
  // has at most cells_per_item cells per gridded item.
  const double max_cells = std::max(1.0, limits.cells_per_item * double(bounded.size()));
  cell_ = median_extent(bounded) / 2.0;
  for (;;) {
    double total = 1.0;
    for (int axis = 0; axis < 3; ++axis) {
      dims_[axis] = std::max(1, int(std::ceil((hi_[axis] - lo_[axis]) / cell_)));
      total *= double(dims_[axis]);
    }
    if (total <= max_cells) break;
    cell_ *= std::cbrt(total / max_cells) * 1.0001;  // 1.0001: no endless loop on rounding
  }

  // Counting pass, then filling: items in ascending order, so every cell's
  // list is ascending.
  const std::size_t cells = std::size_t(dims_[0]) * std::size_t(dims_[1]) * std::size_t(dims_[2]);
  std::vector<std::array<int, 6>> ranges(boxes.size());
  std::vector<std::uint32_t> count(cells + 1, 0);
  std::vector<bool> gridded(boxes.size(), false);
  for (std::size_t k = 0; k < boxes.size(); ++k) {
    if (!boxes[k]) {
      always_.push_back(std::uint32_t(k));
      continue;
    }
    auto& r = ranges[k];
    for (int axis = 0; axis < 3; ++axis) {
      r[std::size_t(axis)] = coordinate(boxes[k]->lo[axis], axis);
      r[std::size_t(axis) + 3] = coordinate(boxes[k]->hi[axis], axis);
    }
    const std::size_t spanned =
        std::size_t(r[3] - r[0] + 1) * std::size_t(r[4] - r[1] + 1) * std::size_t(r[5] - r[2] + 1);
    if (spanned > limits.max_cells_per_item) {
      always_.push_back(std::uint32_t(k));
      continue;
    }
    gridded[k] = true;
    for (int z = r[2]; z <= r[5]; ++z)
      for (int y = r[1]; y <= r[4]; ++y)
        for (int x = r[0]; x <= r[3]; ++x) ++count[cell_index(x, y, z) + 1];
  }
  cell_start_.assign(cells + 1, 0);
  for (std::size_t c = 0; c < cells; ++c) cell_start_[c + 1] = cell_start_[c] + count[c + 1];
  cell_items_.resize(cell_start_[cells]);
  std::vector<std::uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t k = 0; k < boxes.size(); ++k) {
    if (!gridded[k]) continue;
    const auto& r = ranges[k];
    for (int z = r[2]; z <= r[5]; ++z)
      for (int y = r[1]; y <= r[4]; ++y)
        for (int x = r[0]; x <= r[3]; ++x) cell_items_[fill[cell_index(x, y, z)]++] = std::uint32_t(k);
  }
}

}  // namespace skelconv
