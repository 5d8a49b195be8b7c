// skelconv/reconstruct/bspline.hpp — smoothing a branch by a uniform cubic
// B-spline in 4-D, (x, y, z, r) (Ferley 1996 §3.1.3).
//
// Ferley's matrix form of one span with control points V0…V3, u ∈ [0, 1]:
//   Q(u) = 1/6 (V0 + 4V1 + V2 + 3u(V2 − V0) + 3u²(V0 − 2V1 + V2)
//               + u³(V3 − V0 + 3(V1 − V2)))
// (the text's formula, checked: it is the uniform cubic B-spline basis
// (1−u)³/6, (3u³ − 6u² + 4)/6, (−3u³ + 3u² + 3u + 1)/6, u³/6). The control
// polygon is the simplified branch with both end points tripled, so that the
// curve starts and ends exactly at them (Q(0) of the span V0 = V1 = V2 is V0)
// and the branches still meet at their junctions.
#pragma once

#include <vector>

#include "skelconv/reconstruct/branch_graph.hpp"

namespace skelconv::reconstruct {

/// Q(u) of one span.
Vec4 bspline_span_point(const Vec4& v0, const Vec4& v1, const Vec4& v2, const Vec4& v3, double u);

/// The B-spline of `control` (ends tripled), sampled at `samples_per_span` ≥ 1
/// equal steps of u per span; the first and last points are the ends of
/// `control` exactly. Fewer than 2 control points are returned unchanged.
std::vector<Vec4> smooth_bspline(const std::vector<Vec4>& control, int samples_per_span);

/// The periodic B-spline of a closed polygon (`control`'s last point repeats
/// its first; fewer than 3 distinct points are returned unchanged): span s
/// uses V(s−1), V(s), V(s+1), V(s+2) cyclically, so the curve is C² all
/// round (no kink where the cycle was cut) and passes near, not through,
/// the control points. The result is closed too (last point = first).
std::vector<Vec4> smooth_closed_bspline(const std::vector<Vec4>& control, int samples_per_span);

}  // namespace skelconv::reconstruct
