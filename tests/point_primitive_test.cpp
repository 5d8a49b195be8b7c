// The point primitive (skelconv/primitives/point.hpp): values against the
// kernels' definitions (docs/mathematics.md §1, written out here independently of the
// traits), gradients against 50-digit central differences
// (extended_difference.hpp), the singular centre, the compact support, and
// the validation of every field.
#include "skelconv/primitives/point.hpp"

#include <cmath>
#include <stdexcept>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "expect_input_error.hpp"
#include "extended_difference.hpp"
#include "src/detail/infinity.hpp"  // skelconv::infinity

namespace skelconv {
namespace {

using test::Extended;

/// docs/mathematics.md §1 in long double, straight from the definitions.
long double reference_kernel(const KernelSpec& k, long double r) {
  switch (k.family) {
    case KernelFamily::inverse: return std::pow(r, -(long double)k.degree);
    case KernelFamily::cauchy: return std::pow(1.0L + k.s * r * r, -0.5L * k.degree);
    case KernelFamily::compact: return r < k.R ? std::pow(1.0L - r * r / (k.R * k.R), 0.5L * k.degree) : 0.0L;
    default: throw std::logic_error("the generated families only (the others: kernel_families_test.cpp)");
  }
  return 0.0L;
}

std::vector<KernelSpec> point_kernels() {
  return {KernelSpec::inverse(1), KernelSpec::inverse(3), KernelSpec::inverse(16), KernelSpec::cauchy(1, 0.7),
          KernelSpec::cauchy(4, 2.0),  KernelSpec::cauchy(9, 5.0),  KernelSpec::compact(2, 1.3),
          KernelSpec::compact(3, 0.9), KernelSpec::compact(16, 2.0)};
}

/// Random points at distances 0.05 … 2 from the centre.
std::vector<Vec3> points_around(const Vec3& center, int count) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> distance(0.05, 2.0);
  std::vector<Vec3> points;
  for (int k = 0; k < count; ++k) {
    const Vec3 direction = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
    points.push_back(center + distance(rng) * direction);
  }
  return points;
}

/// w K'(r) and w K''(r) in 50 digits (K'' by a central difference of the
/// trait's K', extended_difference.hpp's bound), for the tolerances below.
std::pair<double, double> extended_slopes(const PointPrimitive& point, double r_double) {
  return std::visit(
      [&](const auto& kernel) {
        const Extended r(r_double), h(1e-15), w(point.weight());
        const Extended second = (kernel.derivative(r + h) - kernel.derivative(r - h)) / (2 * h);
        return std::pair<double, double>(static_cast<double>(w * kernel.derivative(r)),
                                         static_cast<double>(w * second));
      },
      point.radial_kernel());
}

constexpr double epsilon = 1.1e-16;  // double's unit roundoff

// Tolerances. f is formed from r = |P − C| by at most ~20 roundings (r², the
// power by squaring, a square root, a division), each a relative error ≤ ε
// of an intermediate that reaches f multiplied by at most the condition
// number of f in r, r |f'| / |f|: hence |error| ≤ 32 ε (|f| + r |f'|). The
// same argument for ∇f = f'(r) (P − C)/r gives 64 ε (|f'| + r |f''|). The
// r |f'| and r |f''| terms matter near a compact kernel's support edge,
// where 1 − r²/R² cancels: the definition itself is ill-conditioned there.
TEST(PointPrimitive, ValueIsTheWeightedKernelOfTheDistance) {
  const Vec3 center(0.3, -0.2, 0.5);
  for (const KernelSpec& kernel : point_kernels()) {
    const PointPrimitive point(center, kernel, -1.75);
    for (const Vec3& p : points_around(center, 200)) {
      const long double r = std::sqrt((long double)(p - center).squaredNorm());
      const double expected = double(-1.75L * reference_kernel(kernel, r));
      const double slope = extended_slopes(point, double(r)).first;
      EXPECT_NEAR(point.value(p), expected, 32 * epsilon * (std::abs(expected) + double(r) * std::abs(slope)))
          << family_name(kernel.family) << " " << kernel.degree;
    }
  }
}

TEST(PointPrimitive, GradientMatchesExtendedPrecisionDifferences) {
  const Vec3 center(0.3, -0.2, 0.5);
  for (const KernelSpec& kernel : point_kernels()) {
    const PointPrimitive point(center, kernel, 2.5);
    const auto extended_value = [&](const std::array<Extended, 3>& q) {
      return std::visit(
          [&](const auto& trait) {
            return point_field(trait, std::array<Extended, 3>{center.x(), center.y(), center.z()}, Extended(2.5), q)
                .value;
          },
          point.radial_kernel());
    };
    for (const Vec3& p : points_around(center, 100)) {
      const double r = (p - center).norm();
      // The difference's step must not straddle the support edge (where
      // K'' jumps for degrees 2 and 3).
      if (kernel.family == KernelFamily::compact && std::abs(r - kernel.R) < 1e-9) continue;
      const Vec3 expected = to_vec3(test::extended_gradient(extended_value, to_array(p)));
      const auto [slope, curvature] = extended_slopes(point, r);
      const FieldSample sample = point.value_and_gradient(p);
      EXPECT_LE((sample.gradient - expected).norm(), 64 * epsilon * (std::abs(slope) + r * std::abs(curvature)))
          << family_name(kernel.family) << " " << kernel.degree << " at " << p.transpose();
      EXPECT_EQ(sample.gradient, point.gradient(p));
      EXPECT_EQ(sample.value, point.value(p));
    }
  }
}

TEST(PointPrimitive, InverseCentreIsTheInfiniteMarker) {
  const PointPrimitive point(Vec3(1, 2, 3), KernelSpec::inverse(3), -2.0);
  const FieldSample sample = point.value_and_gradient(Vec3(1, 2, 3));
  EXPECT_EQ(sample.value, infinity);
  EXPECT_EQ(sample.gradient, Vec3::Constant(infinity));
}

TEST(PointPrimitive, SmoothKernelsHaveZeroGradientAtTheCentre) {
  for (const KernelSpec& kernel : {KernelSpec::cauchy(4, 2.0), KernelSpec::compact(4, 1.0)}) {
    const PointPrimitive point(Vec3(1, 2, 3), kernel, 3.0);
    const FieldSample sample = point.value_and_gradient(Vec3(1, 2, 3));
    EXPECT_EQ(sample.value, 3.0);  // K(0) = 1 for both
    EXPECT_EQ(sample.gradient, Vec3::Zero());
  }
}

TEST(PointPrimitive, CompactSupportEndsExactlyAtR) {
  const PointPrimitive point(Vec3(0, 0, 0), KernelSpec::compact(4, 2.0));
  EXPECT_EQ(point.value_and_gradient(Vec3(2, 0, 0)).value, 0.0);
  EXPECT_EQ(point.value_and_gradient(Vec3(0, 0, -2.5)).gradient, Vec3::Zero());
  EXPECT_GT(point.value(Vec3(0, 1.999, 0)), 0.0);
}

TEST(PointPrimitive, OverflowIsAnEvaluationError) {
  const PointPrimitive point(Vec3(0, 0, 0), KernelSpec::inverse(16));
  EXPECT_THROW(point.value(Vec3(1e-30, 0, 0)), EvaluationError);
}

TEST(PointPrimitiveErrors, EveryFieldIsChecked) {
  using test::expect_input_error;
  const double nan = std::nan("");
  expect_input_error([&] { PointPrimitive(Vec3(nan, 0, 0), KernelSpec::cauchy(4, 1.0)); }, "center",
                     "must be finite");
  expect_input_error([] { PointPrimitive(Vec3(0, 0, 0), KernelSpec::cauchy(4, 1.0), 0.0); }, "weight",
                     "must be non-zero");
  expect_input_error([] { PointPrimitive(Vec3(0, 0, 0), KernelSpec::cauchy(4, 1.0), infinity); }, "weight",
                     "must be finite");
  expect_input_error([] { PointPrimitive(Vec3(0, 0, 0), KernelSpec::cauchy(4, 0.0)); }, "kernel.s",
                     "must be > 0, got 0");
  expect_input_error([] { PointPrimitive(Vec3(0, 0, 0), KernelSpec::compact(4, -1.0)); }, "kernel.R",
                     "must be > 0, got -1");
  expect_input_error([] { PointPrimitive(Vec3(0, 0, 0), KernelSpec::compact(1, 1.0)); }, "kernel.degree",
                     "unsupported degree 1 for the compact family on a point; supported: 2..16");
  expect_input_error([] { PointPrimitive(Vec3(0, 0, 0), KernelSpec::inverse(17)); }, "kernel.degree",
                     "unsupported degree 17 for the inverse family on a point; supported: 1..16");
}

}  // namespace
}  // namespace skelconv
