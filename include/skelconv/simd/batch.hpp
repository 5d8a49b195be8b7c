// skelconv/simd/batch.hpp — f and ∇f of one primitive at many points,
// vectorised with Highway (AVX-512, AVX2, or a portable fallback chosen at run
// time). Results equal the scalar path (Segment::value_and_gradient, …) per
// point to ≤ 1e-13 relative; errors are the scalar path's (docs/simd.md).
//
// Points and results are structures of arrays. Kernels without a vector
// instantiation (src/simd/segment_kernels.hpp lists those with one) are
// evaluated point by point through the scalar path, with the same results.
#pragma once

#include <cstddef>
#include <string>

namespace skelconv {
class Segment;
class ScalisSegment;
class Polygon;
}

namespace skelconv::simd {

/// Query points: point k is (x[k], y[k], z[k]), k < n.
struct PointsSoA {
  const double* x;
  const double* y;
  const double* z;
  std::size_t n;
};

/// Results: f[k] and ∇f = (gx[k], gy[k], gz[k]) at point k.
struct FieldSoA {
  double* f;
  double* gx;
  double* gy;
  double* gz;
};

/// Where the points of one call went (for the benchmarks and tests).
struct BatchCounts {
  std::size_t group_runs = 0;      ///< vector evaluations of a generated kernel
  std::size_t set_aside = 0;       ///< lanes re-run because their group took another branch
  std::size_t scalar_points = 0;   ///< points evaluated by the scalar path (other forms, singular points, no vector kernel)
  std::size_t zero_points = 0;     ///< compact kernels: points outside the support (f = 0 without a call)
};

/// f and ∇f of `segment` at every point. Throws what
/// Segment::value_and_gradient throws for the first failing point.
BatchCounts value_and_gradient(const Segment& segment, PointsSoA points, FieldSoA out);

/// True when `segment`'s kernel has a vector instantiation.
bool has_vector_kernel(const Segment& segment);

/// The same for a SCALIS segment (ScalisSegment::value_and_gradient per point).
BatchCounts value_and_gradient(const ScalisSegment& segment, PointsSoA points, FieldSoA out);
bool has_vector_kernel(const ScalisSegment& segment);

/// The same for a polygon (Polygon::value_and_gradient per point; inverse
/// and Cauchy kernels of src/simd/polygon_kernels.hpp run vectorised).
BatchCounts value_and_gradient(const Polygon& polygon, PointsSoA points, FieldSoA out);
bool has_vector_kernel(const Polygon& polygon);

/// The instruction set the next call will use: "AVX3" (AVX-512), "AVX2", "SCALAR".
std::string active_target();

/// Tests and benchmarks: restrict the run-time choice to one compiled target
/// ("AVX3", "AVX2", "SCALAR"); false if it is not compiled or not supported
/// by this CPU. An empty name restores the automatic choice.
bool force_target(const std::string& name);

}  // namespace skelconv::simd
