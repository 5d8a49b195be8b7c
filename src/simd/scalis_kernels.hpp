// src/simd/scalis_kernels.hpp — the SCALIS segment kernels compiled for the
// vector targets (src/simd/scalis_batch.cpp): X(family, degree i). Each is
// compiled once per target; other kernels (and the compact family, which is
// not generated: include/skelconv/scalis_compact.hpp) are evaluated point by
// point by the scalar path, with the same results.
#pragma once

#define SKELCONV_SIMD_SCALIS_KERNELS(X) X(inverse, 3) X(inverse, 4) X(cauchy, 3) X(cauchy, 4)
