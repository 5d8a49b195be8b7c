// Implementation of skelconv/interval/octree.hpp.
#include "skelconv/interval/octree.hpp"

namespace skelconv::interval {

std::vector<LevelCounts> classify_octree(const Skeleton& skeleton, const Box& box, int depth, double iso,
                                         const EnclosureOptions& options) {
  std::vector<LevelCounts> counts;
  std::vector<Box> cells{box};
  for (int level = 0; level <= depth; ++level) {
    LevelCounts level_counts;
    std::vector<Box> next;
    for (const Box& cell : cells) {
      switch (classify(enclose(skeleton, cell, options), iso)) {
        case Classification::inside: ++level_counts.inside; break;
        case Classification::outside: ++level_counts.outside; break;
        case Classification::undetermined:
          ++level_counts.undetermined;
          if (level < depth) {
            const Vec3 mid = cell.center();
            for (int k = 0; k < 8; ++k) {
              Box child;
              for (int i = 0; i < 3; ++i) {
                const bool upper = (k >> i) & 1;
                child.lo[i] = upper ? mid[i] : cell.lo[i];
                child.hi[i] = upper ? cell.hi[i] : mid[i];
              }
              next.push_back(child);
            }
          }
          break;
      }
    }
    counts.push_back(level_counts);
    cells = std::move(next);
  }
  return counts;
}

}  // namespace skelconv::interval
