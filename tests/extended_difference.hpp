// tests/extended_difference.hpp — central differences in 50-digit arithmetic,
// the reference gradient of the point and blend tests.
//
// Error bound. For a function g smooth near x, the central difference
//     D = (g(x + h) − g(x − h)) / (2h)
// differs from g'(x) by at most h²/6 · max|g'''| (Taylor) plus the rounding
// of the two evaluations, ~ε_T |g| / h. In cpp_bin_float_50 (ε_T ≈ 1e-50)
// with h = 1e-15 ℓ, ℓ the length scale on which g varies (here ≥ 0.1: the
// kernels' R, 1/√s and the distances to the centres), both terms are below
// 1e-29 relative: the reference is exact to every digit a double can hold,
// so a double gradient must agree with it to a few ulps of the terms it
// adds up (the tolerances in the tests, with their reasons).
#pragma once

#include <array>

#include <boost/multiprecision/cpp_bin_float.hpp>

namespace skelconv::test {

using Extended = boost::multiprecision::cpp_bin_float_50;

/// The central-difference gradient of `g` (a function of std::array<Extended, 3>)
/// at p, step h.
template <class Function>
std::array<double, 3> extended_gradient(Function g, const std::array<double, 3>& p, double h = 1e-15) {
  std::array<double, 3> gradient{};
  for (int axis = 0; axis < 3; ++axis) {
    std::array<Extended, 3> ahead{p[0], p[1], p[2]}, behind{p[0], p[1], p[2]};
    ahead[axis] += Extended(h);
    behind[axis] -= Extended(h);
    gradient[axis] = static_cast<double>((g(ahead) - g(behind)) / (2 * Extended(h)));
  }
  return gradient;
}

}  // namespace skelconv::test
