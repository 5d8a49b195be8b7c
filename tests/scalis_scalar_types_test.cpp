// The generated SCALIS segment kernels on other scalar types (as
// scalar_types_test.cpp does for the segment table): the whole table in
// long double and one function in cpp_bin_float_50, each agreeing with
// double at a point in general position, for growing, shrinking and cone
// radii. Accuracy against the definition is scalis_segment_test.cpp's job.
#include <gtest/gtest.h>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <cmath>

#include "generated/scalis_segment_table.hpp"

namespace {

template <class T>
skelconv::ScalisSegmentInput<T> general_position_input(double tau0, double tau1) {
  skelconv::ScalisSegmentInput<T> in;
  in.a = {T(0.25), T(-0.5), T(0.125)};
  in.b = {T(1.5), T(0.75), T(-0.375)};
  in.p = {T(0.625), T(0.875), T(0.5)};
  in.tau0 = T(tau0);
  in.tau1 = T(tau1);
  in.sigma = T(1.25);
  return in;
}

template <class T>
void expect_agrees_with_double(double tolerance) {
  const auto& table_d = skelconv::generated::scalis_segment_kernels<double>();
  const auto& table_t = skelconv::generated::scalis_segment_kernels<T>();
  ASSERT_EQ(table_d.size(), table_t.size());
  for (const auto& [tau0, tau1] : {std::pair{0.3, 0.8}, std::pair{0.8, 0.3}, std::pair{0.0, 0.5}}) {
    const auto in_d = general_position_input<double>(tau0, tau1);
    const auto in_t = general_position_input<T>(tau0, tau1);
    for (size_t i = 0; i < table_d.size(); ++i) {
      std::array<double, 3> g_d;
      std::array<T, 3> g_t;
      const double f_d = table_d[i].f_and_grad(in_d, g_d);
      const T f_t = table_t[i].f_and_grad(in_t, g_t);
      const double f_t_d = static_cast<double>(f_t);
      EXPECT_LE(std::abs(f_d - f_t_d), tolerance * std::abs(f_t_d)) << table_d[i].name;
      for (int c = 0; c < 3; ++c)
        EXPECT_LE(std::abs(g_d[c] - static_cast<double>(g_t[c])), tolerance * std::abs(f_t_d) + 1e-300)
            << table_d[i].name << " grad[" << c << "]";
    }
  }
}

TEST(ScalisScalarTypes, LongDoubleInstantiatesAndAgrees) { expect_agrees_with_double<long double>(1e-13); }

TEST(ScalisScalarTypes, CppBinFloat50CompilesForOneFunction) {
  using Big = boost::multiprecision::cpp_bin_float_50;
  const auto in_big = general_position_input<Big>(0.3, 0.8);
  const auto in_d = general_position_input<double>(0.3, 0.8);
  using namespace skelconv::generated;
  constexpr std::size_t n = scalis_segment_cauchy_i4_prepared_size;
  const Big f_big =
      prepared_f<Big, n, &scalis_segment_cauchy_i4_prepare<Big>, &scalis_segment_cauchy_i4_f<Big>>(in_big);
  const double f_d =
      prepared_f<double, n, &scalis_segment_cauchy_i4_prepare<double>, &scalis_segment_cauchy_i4_f<double>>(in_d);
  EXPECT_LE(std::abs(f_d - static_cast<double>(f_big)), 1e-13 * std::abs(f_d));
}

}  // namespace
