// src/simd/segment_kernels.hpp — the segment kernels compiled for the vector
// targets (src/simd/segment_batch.cpp): X(family, degree i, weight degree).
// Each entry is compiled once per target (three times; ~6 CPU-seconds an
// entry), so the list holds the kernels the benchmarks measure (a list of 24
// cost CI two CPU-minutes); any other kernel is evaluated point by point by
// the scalar path (same results, no speed-up). Add entries here to vectorise
// more kernels.
#pragma once

#define SKELCONV_SIMD_SEGMENT_KERNELS(X)                                               \
  X(inverse, 3, 0) X(inverse, 3, 1) X(cauchy, 4, 0) X(cauchy, 4, 1) X(cauchy, 4, 3)    \
  X(compact, 4, 0) X(compact, 4, 1) X(compact, 6, 0)
