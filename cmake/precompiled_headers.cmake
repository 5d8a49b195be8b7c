# cmake/precompiled_headers.cmake — one precompiled header for the GoogleTest
# executables of tests/ and verify/ (top-level builds only; included after
# every subdirectory, so that every target named here exists).
#
# Why: most of a test file's compile time is parsing the same ~200,000 lines
# of headers (GoogleTest, Eigen, Boost.Math's constants and Gauss tables,
# <skelconv/skeleton/skeleton.hpp>); parsed once into a precompiled header, a typical
# test file compiles in 9–12 s instead of 13–16 s on one core.
#
# The header is built once, for the executable skelconv_pch_donor (an empty
# main with the test executables' flags and no definitions of its own: GCC
# would carry the donor's -D macros into every user), and reused by the test
# executables (REUSE_FROM). GCC uses a precompiled header only when the flags
# that shape it match: these targets share the donor's (-O3 -fPIE, then
# SKELCONV_TEST_OPTIMIZATION, which overrides the -O3,
# GTEST_HAS_PTHREAD, no -frounding-math); their own -D macros do not appear
# in the header. Targets that link CGAL (which adds -frounding-math) and the
# interval tests are not listed: they parse as before. (GCC folds constant
# expressions while it parses, so a header parsed without -frounding-math
# carries values folded in round-to-nearest: with it, the interval test's
# 0.1 + 0.2 lost its outward rounding and Interval.RoundsOutward failed.)
# If GCC ever rejects the header (-Winvalid-pch says so), it includes the
# headers as text: slower, never different.
#
# SKELCONV_PRECOMPILED_HEADERS=OFF turns it off (e.g. with ccache, which
# caches precompiled-header builds only with extra sloppiness settings).
# (The command's seven files gain nothing from one: 74.6 → 71.1 CPU-s with
# <skelconv/skeleton/skeleton_file.hpp> precompiled; their time is their own code.)
option(SKELCONV_PRECOMPILED_HEADERS "Precompile the headers every test includes" ON)

if(NOT SKELCONV_PRECOMPILED_HEADERS OR NOT TARGET skelconv_tests)
  return()
endif()
find_package(GTest REQUIRED)  # (imported targets are directory-scoped: tests/ found its own)

add_executable(skelconv_pch_donor ${CMAKE_CURRENT_LIST_DIR}/pch_donor.cpp)
target_link_libraries(skelconv_pch_donor PRIVATE skelconv_kernels Eigen3::Eigen Boost::boost GTest::gtest)
target_compile_options(skelconv_pch_donor PRIVATE ${SKELCONV_TEST_OPTIMIZATION})
target_precompile_headers(skelconv_pch_donor PRIVATE
  <algorithm> <array> <cmath> <functional> <limits> <random> <string> <vector>
  <gtest/gtest.h>
  <Eigen/Core> <Eigen/Geometry>
  <boost/math/constants/constants.hpp> <boost/math/quadrature/gauss.hpp>
  <skelconv/skeleton/skeleton.hpp>)

foreach(target IN ITEMS
    skelconv_tests skelconv_scalar_types_test
    skelconv_scalis_scalar_types_test skelconv_canal_tests skelconv_reconstruct_tests
    skelconv_reconstruct_table_tests
    verify_reference_selfcheck verify_properties verify_base_cases verify_verdict verify_report_tools
    verify_far_field_series verify_scalis_properties verify_polygon_reference verify_polygon_properties)
  if(TARGET ${target})
    target_compile_options(${target} PRIVATE ${SKELCONV_TEST_OPTIMIZATION})  # (tests/ has it already)
    target_precompile_headers(${target} REUSE_FROM skelconv_pch_donor)
  endif()
endforeach()
