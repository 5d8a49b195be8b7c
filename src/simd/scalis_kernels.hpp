// src/simd/scalis_kernels.hpp — the SCALIS segment kernels compiled for the
// vector targets (src/simd/scalis_batch.cpp): X(family, degree i). Each is
// compiled once per target, ~22 CPU-seconds an entry (the full f_and_grad with
// its Gauss panels, flattened), so the list holds the kernels the benchmarks
// measure (Zanni's Table 4 rows inverse 3 and Cauchy 4; a list with inverse 4
// and Cauchy 3 too cost CI 1.5 CPU-minutes more). Other kernels (and the
// compact family, include/skelconv/primitives/scalis_compact.hpp: its support
// by hand, its even degrees' integral by the generated closed forms of
// generated/scalis_segment_compact.hpp) are evaluated point by point by the
// scalar path, with the same results.
#pragma once

#define SKELCONV_SIMD_SCALIS_KERNELS(X) X(inverse, 3) X(cauchy, 4)
