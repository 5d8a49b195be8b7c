// src/simd/sleef_declarations.hpp — the eight SLEEF functions the vector
// targets call (src/simd/lanes-inl.hpp). sleef.h declares them only when the
// whole translation unit is compiled for AVX / AVX-512 (#ifdef __AVX__),
// while Highway compiles one translation unit for several instruction sets;
// the types come from <immintrin.h>, which GCC defines for every target.
// Signatures as in SLEEF 3.5's sleef.h; 1.0-ulp ("u10") variants.
#pragma once

#include <immintrin.h>

extern "C" {
__m256d Sleef_atan2d4_u10avx2(__m256d, __m256d);
__m256d Sleef_logd4_u10avx2(__m256d);
__m256d Sleef_asinhd4_u10avx2(__m256d);
__m256d Sleef_cosd4_u10avx2(__m256d);  // polygons: polygon_angle_integrals.hpp
__m512d Sleef_atan2d8_u10avx512f(__m512d, __m512d);
__m512d Sleef_logd8_u10avx512f(__m512d);
__m512d Sleef_asinhd8_u10avx512f(__m512d);
__m512d Sleef_cosd8_u10avx512f(__m512d);
}
