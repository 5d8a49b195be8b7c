// skelconv/field/support_grid.hpp — the bounding-volume index of a sum: a
// uniform grid of cells over the support boxes of its compact-support items,
// so that a point visits only the items whose support box contains it.
//
// Why a uniform grid (docs/field.md, "Choice of the index"): the supports of
// a skeleton's compact primitives have similar sizes (a kernel radius R, or
// σ·τ), the query is a point (not a ray or a box), and the answer must come
// out in item order for the sum to be bit-identical to the plain one
// (below). A grid with cells about one support across answers with one
// cell lookup and a short list already sorted by item; a CGAL AABB tree
// would need a tree descent, a sort of its answer, and CGAL (with its
// -frounding-math) in the runtime. Items whose box would cover more than
// Limits::max_cells_per_item cells (a support much larger than the typical
// one) are not gridded: they are visited at every point, like the items of
// infinite support, which keeps the grid small whatever the input.
//
// Order: for_each_active() visits items in ascending index, merging the
// point's cell list with the always-visited list, so a sum taken in that
// order adds the same terms in the same order as the plain loop over all
// items, minus terms that are exactly zero (support_box.hpp).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "skelconv/field/support_box.hpp"
#include "skelconv/geometry.hpp"

namespace skelconv {

class SupportGrid {
 public:
  struct Limits {
    /// At most this many cells per gridded item (memory: one cell start
    /// per cell); the cell side grows until the grid fits.
    double cells_per_item = 8.0;
    /// An item whose box spans more cells than this is visited everywhere.
    std::size_t max_cells_per_item = 64;
  };

  /// boxes[k] is item k's support box, std::nullopt for infinite support.
  explicit SupportGrid(std::span<const std::optional<SupportBox>> boxes) : SupportGrid(boxes, Limits{}) {}
  SupportGrid(std::span<const std::optional<SupportBox>> boxes, const Limits& limits);

  /// Calls visit(k) for every item k in ascending order, except the
  /// gridded items whose support box does not contain p.
  template <class Visit>
  void for_each_active(const Vec3& p, Visit&& visit) const;

  std::size_t item_count() const { return item_count_; }
  /// Items in the grid (the others are visited everywhere).
  std::size_t gridded_count() const { return item_count_ - always_.size(); }
  std::size_t cell_count() const { return cell_start_.empty() ? 0 : cell_start_.size() - 1; }
  double cell_size() const { return cell_; }

 private:
  /// The cell coordinate of x along `axis`, clamped to the grid: monotone in
  /// x, so a box's cell range holds the cell of every point in the box.
  int coordinate(double x, int axis) const {
    const double t = std::floor((x - lo_[axis]) / cell_);
    return t < 0.0 ? 0 : t >= double(dims_[axis]) ? dims_[axis] - 1 : int(t);
  }
  std::size_t cell_index(int i, int j, int k) const {
    return (std::size_t(k) * std::size_t(dims_[1]) + std::size_t(j)) * std::size_t(dims_[0]) + std::size_t(i);
  }

  std::size_t item_count_ = 0;
  Vec3 lo_ = Vec3::Zero(), hi_ = Vec3::Zero();  ///< bounds of the gridded boxes
  double cell_ = 1.0;
  std::array<int, 3> dims_{0, 0, 0};
  std::vector<std::uint32_t> cell_start_;  ///< cell c holds cell_items_[cell_start_[c] .. cell_start_[c+1])
  std::vector<std::uint32_t> cell_items_;  ///< ascending within each cell
  std::vector<std::uint32_t> always_;      ///< ascending: infinite support, or boxes too large
  std::vector<SupportBox> boxes_;          ///< per item (unused for always_ items)
};

template <class Visit>
void SupportGrid::for_each_active(const Vec3& p, Visit&& visit) const {
  std::span<const std::uint32_t> cell;
  const bool inside_grid = !cell_start_.empty() && p.x() >= lo_.x() && p.x() <= hi_.x() && p.y() >= lo_.y() &&
                           p.y() <= hi_.y() && p.z() >= lo_.z() && p.z() <= hi_.z();
  if (inside_grid) {
    const std::size_t c = cell_index(coordinate(p.x(), 0), coordinate(p.y(), 1), coordinate(p.z(), 2));
    cell = std::span<const std::uint32_t>(cell_items_).subspan(cell_start_[c], cell_start_[c + 1] - cell_start_[c]);
  }
  // Merge the two ascending lists.
  std::size_t i = 0, j = 0;
  while (i < cell.size() || j < always_.size()) {
    if (j == always_.size() || (i < cell.size() && cell[i] < always_[j])) {
      const std::uint32_t item = cell[i++];
      if (boxes_[item].contains(p)) visit(std::size_t(item));
    } else {
      visit(std::size_t(always_[j++]));
    }
  }
}

}  // namespace skelconv
