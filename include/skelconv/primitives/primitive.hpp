// skelconv/primitives/primitive.hpp — one skeleton element, any type.
//
// Segments (docs/mathematics.md §2), polygons (docs/mathematics.md §3), SCALIS segments and triangles
// (docs/mathematics.md §4) and points (primitives/point.hpp); every alternative provides
// value(), gradient() and value_and_gradient() at a Vec3.
#pragma once

#include <variant>

#include "skelconv/primitives/polygon.hpp"
#include "skelconv/primitives/point.hpp"
#include "skelconv/primitives/scalis_segment.hpp"
#include "skelconv/primitives/scalis_triangle.hpp"
#include "skelconv/primitives/segment.hpp"

namespace skelconv {

using Primitive = std::variant<Segment, Polygon, ScalisSegment, ScalisTriangle, PointPrimitive>;

}  // namespace skelconv
