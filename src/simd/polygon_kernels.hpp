// src/simd/polygon_kernels.hpp — the polygon edge kernels compiled for the
// vector targets (src/simd/polygon_batch.cpp): X(family, degree i). Each
// entry is compiled once per target, so the list holds what the benchmark
// measures (bench/batch_bench.cpp) and the tests check; any other polygon
// kernel (and every compact one: its support clip and levels stay scalar)
// is evaluated point by point by the scalar path, with the same results.
#pragma once

#define SKELCONV_SIMD_POLYGON_KERNELS(X) X(inverse, 3) X(cauchy, 4)
