// src/detail/infinity.hpp — +∞ in double, as the runtime's and the interval
// objects' files use it: the value of an inverse field on its skeleton, and
// "no limit" for bounds and allowances. Internal: not an installed header.
//
// One definition here rather than one per file: those libraries are compiled
// as unity builds (src/CMakeLists.txt), where two files' copies would clash.
#pragma once

#include <limits>

namespace skelconv {

inline constexpr double infinity = std::numeric_limits<double>::infinity();

}  // namespace skelconv
