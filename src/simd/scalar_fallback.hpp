// src/simd/scalar_fallback.hpp — the points a vector batch hands back to the
// scalar path (src/simd/segment_batch.cpp, scalis_batch.cpp): all of them when
// the kernel has no vector version, else the lanes the vectors could not
// finish (singular points, non-finite lanes).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "skelconv/geometry.hpp"
#include "skelconv/simd/batch.hpp"

namespace skelconv::simd::detail {

/// Evaluates `primitive.value_and_gradient` at the points listed in `scalar`
/// (every point when `vectorised` is false) into `out`, in index order, so
/// that the error thrown is the first failing point's whatever the target.
template <class Primitive>
void finish_on_scalar_path(const Primitive& primitive, bool vectorised, std::vector<std::uint32_t>& scalar,
                           PointsSoA points, FieldSoA out, BatchCounts& counts) {
  if (!vectorised) {
    scalar.resize(points.n);
    for (std::size_t p = 0; p < points.n; ++p) scalar[p] = std::uint32_t(p);
  }
  std::sort(scalar.begin(), scalar.end());
  for (const std::uint32_t p : scalar) {
    const FieldSample s = primitive.value_and_gradient(Vec3(points.x[p], points.y[p], points.z[p]));
    out.f[p] = s.value;
    out.gx[p] = s.gradient[0];
    out.gy[p] = s.gradient[1];
    out.gz[p] = s.gradient[2];
  }
  counts.scalar_points += scalar.size();
}

}  // namespace skelconv::simd::detail
