// skelconv/reconstruct/weighted_point.hpp — a point of the input surface
// standing for a piece of its area: what the ball fit (ball_fit.hpp) and
// the spur rule (branch_graph.hpp, explained_area) weigh the surface by.
#pragma once

#include "skelconv/geometry.hpp"

namespace skelconv::reconstruct {

struct WeightedPoint {
  Vec3 point;
  double weight = 0.0;  ///< the area it stands for
};

}  // namespace skelconv::reconstruct
