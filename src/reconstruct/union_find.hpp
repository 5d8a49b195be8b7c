// src/reconstruct/union_find.hpp — the root of a union-find forest, shared by
// the pruning's and the branch graph's connected pieces. Internal: not
// installed.
#pragma once

#include <cstdint>
#include <vector>

namespace skelconv::detail {

/// The root of x in the forest `parent` (parent[r] == r at a root), halving
/// the path on the way (every node visited then points to its grandparent).
inline std::int32_t find_root(std::vector<std::int32_t>& parent, std::int32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

}  // namespace skelconv::detail
