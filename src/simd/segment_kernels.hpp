// src/simd/segment_kernels.hpp — the segment kernels compiled for the vector
// targets (src/simd/segment_batch.cpp): X(family, degree i, weight degree).
// Each entry is compiled once per target (three times), so the list holds the
// kernels the benchmarks and the common skeletons use; any other kernel is
// evaluated point by point by the scalar path (same results, no speed-up).
#pragma once

#define SKELCONV_SIMD_SEGMENT_KERNELS(X)                                                    \
  X(inverse, 1, 0) X(inverse, 2, 0) X(inverse, 3, 0) X(inverse, 3, 1) X(inverse, 3, 2)      \
  X(inverse, 4, 0) X(inverse, 5, 0) X(inverse, 6, 0) X(inverse, 7, 0) X(inverse, 8, 0)      \
  X(cauchy, 2, 0) X(cauchy, 3, 0) X(cauchy, 4, 0) X(cauchy, 4, 1) X(cauchy, 4, 3)          \
  X(cauchy, 5, 0) X(cauchy, 6, 0) X(cauchy, 8, 0)                                         \
  X(compact, 2, 0) X(compact, 3, 0) X(compact, 4, 0) X(compact, 4, 1) X(compact, 6, 0)     \
  X(compact, 8, 0)
