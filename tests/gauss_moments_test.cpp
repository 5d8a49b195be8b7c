// The Gauss moments' sums in registers (skelconv/detail/gauss_moments.hpp,
// add_sums_in_registers: one order, or two side by side in a vector): they
// must give every moment the bits of the plain form written out below,
// which adds the nodes' terms to each moment one at a time in node order,
// each term formed by one product per step. The generated kernels' values
// (and so every mesh's bytes) rest on that order.
#include <array>
#include <cmath>
#include <cstring>
#include <random>

#include <gtest/gtest.h>

#include "skelconv/detail/gauss_moments.hpp"

namespace skelconv {
namespace {

/// The plain form: for the highest order (l = levels − 1) down to the
/// lowest (l = 0), for k = 0…K, out[l (K + 1) + k] + term_0 + term_1 + …
/// with term_j = weight_j · q_j^(levels − 1 − l) · t_j^k, the powers taken
/// one product at a time.
template <unsigned N>
void plain_sums(int levels, int K, const std::array<double, N>& t, const std::array<double, N>& q,
                std::array<double, N> weight, double* out) {
  for (int l = levels - 1; l >= 0; --l) {
    std::array<double, N> term = weight;
    for (int k = 0; k <= K; ++k) {
      double sum = out[l * (K + 1) + k];
      for (unsigned j = 0; j < N; ++j) sum += term[j];
      out[l * (K + 1) + k] = sum;
      for (unsigned j = 0; j < N; ++j) term[j] *= t[j];
    }
    for (unsigned j = 0; j < N; ++j) weight[j] *= q[j];
  }
}

template <unsigned N>
void expect_same_bits_as_plain(int levels, std::mt19937_64& rng) {
  // Magnitudes spread over many binades, so that a changed order of the
  // additions or products rounds differently (checked below).
  std::uniform_real_distribution<double> mantissa(0.5, 1.0);
  std::uniform_int_distribution<int> exponent(-20, 20);
  const auto draw = [&] { return std::ldexp(mantissa(rng), exponent(rng)); };
  for (int K = 0; K <= 4; ++K) {
    for (int trial = 0; trial < 50; ++trial) {
      std::array<double, N> t, q, weight;
      for (unsigned j = 0; j < N; ++j) {
        t[j] = mantissa(rng);
        q[j] = draw();
        weight[j] = draw();
      }
      std::array<double, 10> start;
      for (double& s : start) s = draw();
      std::array<double, 10> plain = start, fast = start;
      plain_sums<N>(levels, K, t, q, weight, plain.data());
      ASSERT_TRUE((add_sums_in_registers<double, N>(levels, K, t, q, weight, fast.data())));
      for (int i = 0; i < 10; ++i) {  // the moments, and the rest of `out` untouched
        EXPECT_EQ(std::memcmp(&plain[i], &fast[i], sizeof(double)), 0)
            << "N = " << N << ", " << levels << " orders, K = " << K << ", moment " << i << ": " << plain[i]
            << " vs " << fast[i];
      }
    }
  }
}

TEST(GaussMoments, SumsInRegistersHaveTheBitsOfThePlainSums) {
  std::mt19937_64 rng(11);
  for (int levels : {1, 2}) {
    expect_same_bits_as_plain<7>(levels, rng);
    expect_same_bits_as_plain<10>(levels, rng);
    expect_same_bits_as_plain<15>(levels, rng);
    expect_same_bits_as_plain<20>(levels, rng);
  }
}

TEST(GaussMoments, ThePlainSumsDependOnTheOrder) {
  // The check above can fail: on these terms, adding the nodes in reverse
  // order changes some moment's last bit.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> mantissa(0.5, 1.0);
  std::uniform_int_distribution<int> exponent(-20, 20);
  int differing = 0;
  for (int trial = 0; trial < 50; ++trial) {
    std::array<double, 15> terms;
    for (double& v : terms) v = std::ldexp(mantissa(rng), exponent(rng));
    double forward = 0, backward = 0;
    for (unsigned j = 0; j < terms.size(); ++j) forward += terms[j];
    for (unsigned j = terms.size(); j-- > 0;) backward += terms[j];
    differing += forward != backward;
  }
  EXPECT_GT(differing, 10);
}

TEST(GaussMoments, OtherShapesAreLeftToThePlainSums) {
  std::array<double, 7> t{}, q{}, weight{};
  std::array<double, 33> out{};
  EXPECT_FALSE((add_sums_in_registers<double, 7>(1, 5, t, q, weight, out.data())));
  EXPECT_FALSE((add_sums_in_registers<double, 7>(2, 10, t, q, weight, out.data())));
  EXPECT_FALSE((add_sums_in_registers<double, 7>(3, 0, t, q, weight, out.data())));
  // Two orders as a vector in double only.
  std::array<long double, 7> tl{}, ql{}, wl{};
  std::array<long double, 33> outl{};
  EXPECT_FALSE((add_sums_in_registers<long double, 7>(2, 4, tl, ql, wl, outl.data())));
  EXPECT_TRUE((add_sums_in_registers<long double, 7>(1, 4, tl, ql, wl, outl.data())));
}

}  // namespace
}  // namespace skelconv
