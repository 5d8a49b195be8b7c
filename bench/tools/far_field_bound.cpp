// bench/tools/far_field_bound.cpp — derives the far-field node counts of
// include/skelconv/detail/gauss_moments.hpp (far_field_min_y_*_nodes): for each
// Gauss–Legendre node count N, the smallest imaginary distance y of the poles
// (in x ∈ [−1, 1]) at which the bound of Trefethen, ATAP Theorem 19.3, for
// the N-point rule, (64/15) M r^(2−2N)/(r² − 1), divided by the integral, is
// ≤ 2^−55 for every pole position x*, weight t^k and pole order m/2 the
// generated kernels use. Theorem 19.3's I_n is the (n + 1)-point rule, exact
// to degree 2n + 1: for N points n = N − 1, hence the exponent 2 − 2N.
// With --radius: the smallest distance |z| of the poles from the interval's
// midpoint, in any direction (segment_moments_beyond_end's far case).
// Not built by CMake (a derivation, a few minutes):
//   g++ -O2 -std=c++20 bench/tools/far_field_bound.cpp -o /tmp/far_field_bound && /tmp/far_field_bound [--radius] [--panels]
// --panels widens the weights and orders to the SCALIS segments' Gauss
// panels with weights up to t^10 (gauss_moments.hpp, panel_node_thresholds);
// --low-order narrows the orders to m ≤ 6 (weights t^k, k ≤ 4: the SCALIS
// kernels of degree ≤ 4).
#include <boost/math/quadrature/gauss.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

namespace {
using Complex = std::complex<double>;

/// The integrand on [−1, 1]: t^k ((x − x*)² + y²)^(−m/2), t = (1 + x)/2.
double integral(double y, double x_star, int k, int m) {
  auto f = [&](double x) { return std::pow((1 + x) / 2, k) * std::pow((x - x_star) * (x - x_star) + y * y, -m / 2.0); };
  double sum = 0;  // 8 panels of the 30-point rule: exact to rounding for y ≥ 1
  for (int p = 0; p < 8; ++p)
    sum += boost::math::quadrature::gauss<double, 30>::integrate(f, -1 + p / 4.0, -1 + (p + 1) / 4.0);
  return sum;
}

/// The bound divided by the integral, minimised over the ellipses E_r inside
/// the one through the pole.
double relative_bound(int N, double y, double x_star, int k, int m) {
  const double I = integral(y, x_star, k, m);
  const Complex z(x_star, y);
  double r_pole = std::abs(z + std::sqrt(z * z - 1.0));
  if (r_pole < 1) r_pole = 1 / r_pole;
  double best = INFINITY;
  for (int j = 1; j < 40; ++j) {
    const double r = 1 + (r_pole - 1) * j / 40.0;
    double M = 0;  // max of |integrand| on ∂E_r
    for (int s = 0; s < 256; ++s) {
      const double theta = 2 * std::numbers::pi * s / 256;
      const Complex x = (r * std::exp(Complex(0, theta)) + std::exp(Complex(0, -theta)) / r) / 2.0;
      M = std::max(M, std::pow(std::abs((1.0 + x) / 2.0), k) *
                          std::pow(std::abs((x - x_star) * (x - x_star) + y * y), -m / 2.0));
    }
    best = std::min(best, 64.0 / 15 * M * std::pow(r, 2 - 2 * N) / (r * r - 1) / I);
  }
  return best;
}

/// The weights t^k and pole orders m/2 covered: the extremes of the
/// classical kernels' far field (k ≤ 4, m ≤ 18), or with --panels also the
/// SCALIS segments' Gauss panels (k ≤ 10: weights τ(t)^(i−1) and ∇f, m ≤ 12).
std::vector<int> weights_k = {0, 1, 4};
std::vector<int> orders_m = {1, 2, 3, 18};

/// The worst case over pole positions, weights and orders.
double worst(int N, double y) {
  std::vector<double> positions;
  for (int i = -12; i <= 12; ++i) positions.push_back(i * 0.5);
  for (double v : {-20.0, 20.0, -100.0, 100.0}) positions.push_back(v);
  double w = 0;
  for (double x_star : positions)
    for (int k : weights_k)
      for (int m : orders_m) w = std::max(w, relative_bound(N, y, x_star, k, m));
  return w;
}

/// The same for poles at distance `radius` from the interval's midpoint in
/// any direction (x* = radius cos φ, y = radius sin φ; the real axis
/// included, y → 0 beyond an end).
double worst_at_radius(int N, double radius) {
  double w = 0;
  for (int j = 0; j <= 12; ++j) {
    const double phi = j == 0 ? 1e-3 : std::numbers::pi / 2 * j / 12;
    for (int k : weights_k)
      for (int m : orders_m) w = std::max(w, relative_bound(N, radius * std::sin(phi), radius * std::cos(phi), k, m));
  }
  return w;
}
}  // namespace

int main(int argc, char** argv) {
  const double target = std::ldexp(1.0, -55);  // a quarter of double's rounding unit
  bool by_radius = false;
  for (int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    if (option == "--radius") by_radius = true;
    if (option == "--low-order") orders_m = {1, 2, 3, 4, 5, 6};
    if (option == "--panels") {
      weights_k = {0, 1, 4, 10};
      orders_m = {1, 2, 3, 12, 18};
    }
  }
  auto bound = [&](int N, double distance) { return by_radius ? worst_at_radius(N, distance) : worst(N, distance); };
  for (int N : {7, 10, 15, 20}) {
    double lo = 1.01, hi = 1000;  // bisection in log
    // The weights t^10 of --panels keep the 7-point rule's bound above the
    // target beyond 1000: widen the bracket by decades until it holds.
    while (bound(N, hi) > target) {
      lo = hi;
      hi *= 10;
    }
    for (int step = 0; step < 14; ++step) {
      const double mid = std::sqrt(lo * hi);
      (bound(N, mid) <= target ? hi : lo) = mid;
    }
    if (by_radius)
      std::printf("N = %d: |z| >= %.4g (|P - midpoint| >= %.4g |AB|)\n", N, hi, hi / 2);
    else
      std::printf("N = %d: y >= %.4g (D/a^2 >= %.4g on [0, 1])\n", N, hi, hi * hi / 4);
    std::fflush(stdout);
  }
}
