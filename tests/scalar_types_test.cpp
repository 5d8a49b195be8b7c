// The generated kernels are templates on the scalar type (docs/generated_api.md):
// double is what users call, long double and Boost.Multiprecision types let
// the verifier separate formula error from rounding. This instantiates a
// sample of the table for long double (every family; low, middle and the
// highest degrees; every weight degree) and one kernel for cpp_bin_float_50,
// and checks that each agrees with double at a point in general position: the
// same formula evaluated with more digits must agree to double's accuracy
// there (docs/mathematics.md §2; verify/ holds the comparison against quadrature of the
// definition). The whole table is instantiated in binary128 by the verifier
// (verify/generated_kernels_extended_<family>.cpp); instantiating it here again in
// long double cost 110 s of compiling for no further check.
#include <gtest/gtest.h>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <cmath>

#include "generated/segment_cauchy.hpp"
#include "generated/segment_compact.hpp"
#include "generated/segment_inverse.hpp"
#include "skelconv/primitives/polygon_field.hpp"

namespace {

template <class T>
skelconv::SegmentInput<T> general_position_input() {
  skelconv::SegmentInput<T> in;
  in.a = {T(0.25), T(-0.5), T(0.125)};
  in.b = {T(1.5), T(0.75), T(-0.375)};
  in.p = {T(0.625), T(0.875), T(0.5)};
  in.w = {T(1), T(0.5), T(0.25), T(0.125)};
  in.s = T(1.5);
  in.R = T(2.5);
  // P is inside the ball of radius R around every point of the segment.
  in.t0 = T(0);
  in.t1 = T(1);
  return in;
}

/// One kernel of the table in double and in T.
template <class T>
struct KernelPair {
  const char* name;
  double (*f_and_grad_d)(const skelconv::SegmentInput<double>&, std::array<double, 3>&);
  T (*f_and_grad_t)(const skelconv::SegmentInput<T>&, std::array<T, 3>&);
};

// A kernel's f and ∇f at one point in U: its preparation, then its per-point function.
#define SKELCONV_AT_ONE_POINT(U, name, which)                                                          \
  &skelconv::generated::prepared_##which<U, skelconv::generated::name##_prepared_size,                  \
                                         &skelconv::generated::name##_prepare<U>, &skelconv::generated::name##_##which<U>, \
                                         skelconv::SegmentInput<U>>
#define SKELCONV_KERNEL_PAIR(name) \
  KernelPair<T> { #name, SKELCONV_AT_ONE_POINT(double, name, f_and_grad), SKELCONV_AT_ONE_POINT(T, name, f_and_grad) }

template <class T>
void expect_agrees_with_double(double tolerance) {
  const KernelPair<T> sample[] = {
      SKELCONV_KERNEL_PAIR(segment_inverse_i1_w0),  SKELCONV_KERNEL_PAIR(segment_inverse_i2_w1),
      SKELCONV_KERNEL_PAIR(segment_inverse_i3_w3),  SKELCONV_KERNEL_PAIR(segment_inverse_i8_w2),
      SKELCONV_KERNEL_PAIR(segment_inverse_i16_w3), SKELCONV_KERNEL_PAIR(segment_cauchy_i1_w0),
      SKELCONV_KERNEL_PAIR(segment_cauchy_i2_w2),   SKELCONV_KERNEL_PAIR(segment_cauchy_i4_w3),
      SKELCONV_KERNEL_PAIR(segment_cauchy_i9_w1),   SKELCONV_KERNEL_PAIR(segment_cauchy_i16_w3),
      SKELCONV_KERNEL_PAIR(segment_compact_i2_w0),  SKELCONV_KERNEL_PAIR(segment_compact_i6_w3),
      SKELCONV_KERNEL_PAIR(segment_compact_i11_w1), SKELCONV_KERNEL_PAIR(segment_compact_i16_w2),
  };
  const auto in_d = general_position_input<double>();
  const auto in_t = general_position_input<T>();
  for (const KernelPair<T>& kernel : sample) {
    std::array<double, 3> g_d;
    std::array<T, 3> g_t;
    const double f_d = kernel.f_and_grad_d(in_d, g_d);
    const T f_t = kernel.f_and_grad_t(in_t, g_t);
    const double f_t_d = static_cast<double>(f_t);
    EXPECT_LE(std::abs(f_d - f_t_d), tolerance * std::abs(f_t_d)) << kernel.name;
    for (int c = 0; c < 3; ++c)
      EXPECT_LE(std::abs(g_d[c] - static_cast<double>(g_t[c])), tolerance * std::abs(f_t_d) + 1e-300)
          << kernel.name << " grad[" << c << "]";
  }
}
#undef SKELCONV_KERNEL_PAIR

TEST(ScalarTypes, LongDoubleInstantiatesAndAgrees) { expect_agrees_with_double<long double>(1e-13); }

TEST(ScalarTypes, CppBinFloat50CompilesForOneFamily) {
  using Big = boost::multiprecision::cpp_bin_float_50;
  const auto in_big = general_position_input<Big>();
  const auto in_d = general_position_input<double>();
  const Big f_big = (SKELCONV_AT_ONE_POINT(Big, segment_cauchy_i4_w3, f))(in_big);
  const double f_d = (SKELCONV_AT_ONE_POINT(double, segment_cauchy_i4_w3, f))(in_d);
  EXPECT_LE(std::abs(f_d - static_cast<double>(f_big)), 1e-13 * std::abs(f_d));
}
#undef SKELCONV_AT_ONE_POINT

}  // namespace

// The polygon edge kernels and their driver (skelconv/primitives/polygon_field.hpp) on
// long double: every family and degree of the table, near the plane (the
// angle-integral forms) and off it (the recurrences), agree with double.
TEST(ScalarTypes, PolygonKernelsInLongDoubleAgree) {
  const std::vector<std::array<double, 3>> square_d = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const std::vector<std::array<long double, 3>> square_l = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (const auto& kernel : skelconv::generated::polygon_edge_kernels<double>()) {
    for (const std::array<double, 3> p : {std::array<double, 3>{0.375, 0.25, 0.625}, {1.25, 0.5, 0.001}}) {
      const skelconv::PolygonInput<double> in_d{square_d, {0, 0, 1}, kernel.family, kernel.degree, 1.5, 1.75};
      const skelconv::PolygonInput<long double> in_l{square_l, {0, 0, 1}, kernel.family, kernel.degree, 1.5L, 1.75L};
      std::array<double, 3> g_d;
      std::array<long double, 3> g_l;
      const double f_d = skelconv::polygon_f_and_grad(in_d, p, g_d);
      const long double f_l = skelconv::polygon_f_and_grad(in_l, {p[0], p[1], p[2]}, g_l);
      EXPECT_NEAR(f_d, static_cast<double>(f_l), 1e-13 * std::abs(f_d)) << kernel.name;
      const double g_norm = std::hypot(g_d[0], g_d[1], g_d[2]);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(g_d[c], static_cast<double>(g_l[c]), 1e-13 * g_norm) << kernel.name;
    }
  }
}
