// Segment: values against quadrature of the definition integral, the two
// special cases (compact support, inverse singularity), and validation.
#include "skelconv/primitives/segment.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "expect_input_error.hpp"
#include "reference_quadrature.hpp"
#include "src/detail/infinity.hpp"  // skelconv::infinity

namespace skelconv {
namespace {

using test::expect_input_error;
using test::ReferenceFamily;
using test::ReferenceSegment;

/// Relative accuracy demanded of the generated functions against quadrature
/// of the definition (f, and ∇f over its scale), per test: about ten times
/// the worst error measured over that test's points, kernels and weights
/// so that a regression of a few digits fails. Measured against
/// the long double reference of reference_quadrature.hpp (the test prints
/// each test's worst values).
constexpr double tolerance_inverse_off_line = 4e-14;  // measured 3.6e-15 (∇f; f 3.2e-15)
constexpr double tolerance_inverse_on_line = 3e-14;   // measured 2.3e-15 (f and ∇f)
constexpr double tolerance_cauchy = 1.5e-13;          // measured 1.2e-14 (f and ∇f)
constexpr double tolerance_compact = 3e-13;           // measured 2.6e-14 (∇f; f 2.2e-14)
constexpr double tolerance_bounded_exactly_on_line = 3e-14;  // measured 2.1e-15 (f; ∇f 1.6e-15)

ReferenceFamily reference_family(KernelFamily family) {
  switch (family) {
    case KernelFamily::inverse: return ReferenceFamily::inverse;
    case KernelFamily::cauchy: return ReferenceFamily::cauchy;
    case KernelFamily::compact: return ReferenceFamily::compact;
    default: throw std::logic_error("the generated families only (the others: kernel_families_test.cpp)");
  }
  return ReferenceFamily::inverse;
}

using test::to_reference;

/// The degrees the generated table offers for `family` (weight degree 0).
std::vector<int> generated_degrees(KernelFamily family) { return Segment::supported_degrees(family); }

/// Worst relative errors (f; ∇f over its scale) seen by
/// expect_matches_definition since the last reset; each test prints them.
struct WorstErrors {
  double value = 0, gradient = 0;
  void print(const char* what) const {
    std::printf("%s: worst relative error of f %.1e, of grad f %.1e\n", what, value, gradient);
  }
};
WorstErrors worst_errors;

/// Compares value, gradient and value_and_gradient of `segment` at p with
/// the quadrature of the definition, to the relative `tolerance`.
void expect_matches_definition(const Segment& segment, const Vec3& p, double tolerance) {
  ReferenceSegment reference;
  reference.a = to_reference(segment.a());
  reference.b = to_reference(segment.b());
  reference.weight.assign(segment.weight().begin(), segment.weight().end());
  reference.family = reference_family(segment.kernel().family);
  reference.degree = segment.kernel().degree;
  reference.s = segment.kernel().s;
  reference.R = segment.kernel().R;
  const test::ReferenceSample expected = test::integrate_definition(reference, to_reference(p));

  const double length = (segment.b() - segment.a()).norm();
  const double expected_value = double(expected.value);
  const Vec3 expected_gradient(double(expected.gradient[0]), double(expected.gradient[1]),
                               double(expected.gradient[2]));
  // Gradient scale: |∇f| itself, or f / |AB| where the gradient nearly
  // cancels (a component can be 0 by symmetry).
  const double gradient_scale = std::max(expected_gradient.norm(), std::abs(expected_value) / length);

  SCOPED_TRACE(testing::Message() << segment.generated_name() << " at P = (" << p.transpose() << ")");
  try {
    const FieldSample both = segment.value_and_gradient(p);
    const double scale = std::abs(expected_value);
    worst_errors.value = std::max({worst_errors.value, std::abs(segment.value(p) - expected_value) / scale,
                                   std::abs(both.value - expected_value) / scale});
    worst_errors.gradient =
        std::max({worst_errors.gradient, (segment.gradient(p) - expected_gradient).norm() / gradient_scale,
                  (both.gradient - expected_gradient).norm() / gradient_scale});
    EXPECT_NEAR(segment.value(p), expected_value, tolerance * std::abs(expected_value));
    EXPECT_NEAR(both.value, expected_value, tolerance * std::abs(expected_value));
    EXPECT_LE((segment.gradient(p) - expected_gradient).norm(), tolerance * gradient_scale);
    EXPECT_LE((both.gradient - expected_gradient).norm(), tolerance * gradient_scale);
  } catch (const EvaluationError& error) {
    ADD_FAILURE() << error.what();  // report, and go on with the other cases
  }
}

/// w_0 … w_d for weight degree d: 1, 0.5, -0.3, 0.2 (positive on [0,1]).
std::vector<double> test_weight(int weight_degree) {
  const std::vector<double> all{1.0, 0.5, -0.3, 0.2};
  return {all.begin(), all.begin() + weight_degree + 1};
}

// A segment in general position, and a frame around it for placing points.
const Vec3 A(0.3, -0.2, 0.1);
const Vec3 B(1.4, 0.5, -0.3);
Vec3 on_line(double t) { return A + t * (B - A); }
const Vec3 normal1 = (B - A).cross(Vec3::UnitZ()).normalized();
const Vec3 normal2 = (B - A).cross(normal1).normalized();

// A segment with exactly representable points on its line:
// AB = (1, 2, -2), |AB| = 3, and A + t AB is exact for t = 1.25, -0.5, 0.25.
const Vec3 exact_A(0.5, -1.0, 2.0);
const Vec3 exact_B(1.5, 1.0, 0.0);

/// Points off the segment's line, where every kernel is smooth along the
/// segment.
std::vector<Vec3> points_off_line() {
  return {
      on_line(0.5) + 0.3 * normal1,   // beside the middle
      on_line(0.1) + 1.0 * normal2,   // beside, near A
      on_line(0.0) + 0.25 * normal1,  // over the end point A
      on_line(-0.4) + 0.5 * normal1,  // beyond A
      on_line(1.3) + 0.2 * normal2,   // beyond B
      Vec3(8.0, -5.0, 3.0),           // far away
  };
}

/// Points on (to rounding) or very near the segment's line but outside the
/// segment: there b² ≈ ac and the general closed forms divide 0 by 0
/// (on the line, b² = ac, Hubert 2012 §3 gives separate closed forms). The
/// field is smooth there, so the same accuracy applies.
std::vector<Vec3> points_near_line_outside_segment() {
  return {
      on_line(1.4),                   // on the line beyond B (to rounding)
      on_line(-0.6),                  // on the line before A (to rounding)
      on_line(1.4) + 1e-6 * normal1,  // next to the line beyond B
      on_line(-0.6) + 1e-9 * normal2, // next to the line before A
  };
}

TEST(SegmentValues, InverseMatchesDefinitionIntegral) {
  worst_errors = {};
  for (int degree : generated_degrees(KernelFamily::inverse)) {
    for (int weight_degree = 0; weight_degree <= max_weight_degree; ++weight_degree) {
      const Segment segment(A, B, KernelSpec::inverse(degree), test_weight(weight_degree));
      for (const Vec3& p : points_off_line()) expect_matches_definition(segment, p, tolerance_inverse_off_line);
    }
  }
  worst_errors.print("InverseMatchesDefinitionIntegral");
}

TEST(SegmentValues, InverseOnTheLineOutsideTheSegment) {
  worst_errors = {};
  for (int degree : generated_degrees(KernelFamily::inverse)) {
    for (int weight_degree = 0; weight_degree <= max_weight_degree; ++weight_degree) {
      const std::vector<double> weight = test_weight(weight_degree);
      const Segment segment(A, B, KernelSpec::inverse(degree), weight);
      for (const Vec3& p : points_near_line_outside_segment())
        expect_matches_definition(segment, p, tolerance_inverse_on_line);
      // Exactly on the line: b² = ac holds in floating point too.
      const Segment exact(exact_A, exact_B, KernelSpec::inverse(degree), weight);
      for (const Vec3& p : {Vec3(1.75, 1.5, -0.5), Vec3(0.0, -2.0, 3.0)})
        expect_matches_definition(exact, p, tolerance_inverse_on_line);
    }
  }
  worst_errors.print("InverseOnTheLineOutsideTheSegment");
}

TEST(SegmentValues, CauchyMatchesDefinitionIntegral) {
  worst_errors = {};
  for (int degree : generated_degrees(KernelFamily::cauchy)) {
    for (int weight_degree = 0; weight_degree <= max_weight_degree; ++weight_degree) {
      for (double s : {0.5, 2.0}) {
        const Segment segment(A, B, KernelSpec::cauchy(degree, s), test_weight(weight_degree));
        for (const Vec3& p : points_off_line()) expect_matches_definition(segment, p, tolerance_cauchy);
        for (const Vec3& p : points_near_line_outside_segment())
          expect_matches_definition(segment, p, tolerance_cauchy);
        expect_matches_definition(segment, on_line(0.5), tolerance_cauchy);  // bounded kernel: on the segment too
      }
    }
  }
  worst_errors.print("CauchyMatchesDefinitionIntegral");
}

TEST(SegmentValues, CompactMatchesDefinitionIntegral) {
  worst_errors = {};
  // R = 0.5 against |AB| ≈ 1.36: the ball clips the segment on one side, on
  // both sides, or not at all (R = 3).
  const std::vector<Vec3> points{
      on_line(0.5) + 0.3 * normal1,  // clipped on both sides
      on_line(0.1) + 0.2 * normal2,  // clipped at t = 0 (end) and inside
      on_line(1.2) + 0.1 * normal1,  // beyond B, clipped inside
      on_line(-0.2),                 // on the line before A
      on_line(0.5),                  // on the segment
  };
  for (int degree : generated_degrees(KernelFamily::compact)) {
    for (int weight_degree = 0; weight_degree <= max_weight_degree; ++weight_degree) {
      for (double R : {0.5, 3.0}) {
        const Segment segment(A, B, KernelSpec::compact(degree, R), test_weight(weight_degree));
        for (const Vec3& p : points) expect_matches_definition(segment, p, tolerance_compact);
      }
    }
  }
  worst_errors.print("CompactMatchesDefinitionIntegral");
}

TEST(SegmentValues, BoundedKernelsExactlyOnTheLineOutsideTheSegment) {
  worst_errors = {};
  // b² = ac exactly (the inverse family is covered above).
  for (int degree : {2, 3, 4, 5, 8}) {
    for (int weight_degree = 0; weight_degree <= max_weight_degree; ++weight_degree) {
      const std::vector<double> weight = test_weight(weight_degree);
      for (const Vec3& p : {Vec3(1.75, 1.5, -0.5), Vec3(0.0, -2.0, 3.0)}) {
        expect_matches_definition(Segment(exact_A, exact_B, KernelSpec::cauchy(degree, 0.7), weight), p,
                                  tolerance_bounded_exactly_on_line);
        expect_matches_definition(Segment(exact_A, exact_B, KernelSpec::compact(degree, 2.0), weight), p,
                                  tolerance_bounded_exactly_on_line);
      }
    }
  }
  worst_errors.print("BoundedKernelsExactlyOnTheLineOutsideTheSegment");
}

// ---------------------------------------------------------------------------
// Special cases decided by the runtime before calling generated code.

TEST(SegmentSpecialCases, InverseOnTheSegmentIsPlusInfinity) {
  const Segment segment(Vec3(0, 0, 0), Vec3(2, 0, 0), KernelSpec::inverse(3), {1.0, 0.5});
  for (const Vec3& p : {Vec3(1, 0, 0), Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0.125, 0, 0)}) {
    SCOPED_TRACE(testing::Message() << "P = " << p.transpose());
    EXPECT_EQ(segment.value(p), infinity);
    EXPECT_EQ(segment.gradient(p), Vec3::Constant(infinity));
    const FieldSample both = segment.value_and_gradient(p);
    EXPECT_EQ(both.value, infinity);
    EXPECT_EQ(both.gradient, Vec3::Constant(infinity));
  }
  // In general position, exactly on the segment: A + 0.25 AB.
  const Segment oblique(exact_A, exact_B, KernelSpec::inverse(1));
  EXPECT_EQ(oblique.value(Vec3(0.75, -0.5, 1.5)), infinity);
}

TEST(SegmentSpecialCases, CompactBeyondTheSupportIsExactlyZero) {
  const Segment segment(Vec3(0, 0, 0), Vec3(1, 0, 0), KernelSpec::compact(4, 1.0), {1.0, 2.0});
  // Farther than R from every point of the segment, and exactly at distance
  // R from the end point B (the open ball misses the segment).
  for (const Vec3& p : {Vec3(10, 10, 10), Vec3(0.5, 1.5, 0), Vec3(2, 0, 0), Vec3(0.5, 0, -1)}) {
    SCOPED_TRACE(testing::Message() << "P = " << p.transpose());
    EXPECT_EQ(segment.value(p), 0.0);
    EXPECT_EQ(segment.gradient(p), Vec3::Zero());
    const FieldSample both = segment.value_and_gradient(p);
    EXPECT_EQ(both.value, 0.0);
    EXPECT_EQ(both.gradient, Vec3::Zero());
  }
}

TEST(SegmentSpecialCases, NeverNaNNearTheLine) {
  // Near and on the segment's line every family returns a finite value,
  // +inf (inverse, exactly on the segment), or throws EvaluationError; never
  // NaN. At offsets ≥ 1e-4 |AB| the closed forms must succeed.
  for (KernelFamily family : {KernelFamily::inverse, KernelFamily::cauchy, KernelFamily::compact}) {
    for (int degree : generated_degrees(family)) {
      const KernelSpec kernel{family, degree, 1.5, 0.9};
      const Segment segment(A, B, kernel, {1.0, 0.5});
      for (double t : {-0.5, 0.0, 0.3, 1.0, 1.5}) {
        for (double offset : {1e-2, 1e-4, 1e-8, 1e-12, 0.0}) {
          const Vec3 p = on_line(t) + offset * normal1;
          SCOPED_TRACE(testing::Message() << segment.generated_name() << " t = " << t << " offset " << offset);
          try {
            const FieldSample sample = segment.value_and_gradient(p);
            EXPECT_FALSE(std::isnan(sample.value));
            EXPECT_FALSE(sample.gradient.hasNaN());
            if (!std::isfinite(sample.value)) {
              EXPECT_EQ(family, KernelFamily::inverse);
            }
          } catch (const EvaluationError& error) {
            EXPECT_LT(offset, 1e-4) << error.what();
          }
        }
      }
    }
  }
}

// ---------------------------------------------------------------------------
// Validation in the constructor: each problem names its field.


TEST(SegmentValidation, RejectsBadInputWithItsLocation) {
  const Vec3 a(0, 0, 0), b(1, 0, 0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expect_input_error([&] { Segment(a, a, KernelSpec::inverse(3)); }, "", "degenerate segment: a and b are the same");
  expect_input_error([&] { Segment(Vec3(1e6, 0, 0), Vec3(1e6 + 1e-5, 0, 0), KernelSpec::inverse(3)); }, "",
                     "degenerate segment: length");
  expect_input_error([&] { Segment(Vec3(0, 0, 0), Vec3(1e-310, 0, 0), KernelSpec::inverse(3)); }, "",
                     "below the normal range of double precision");
  EXPECT_NO_THROW(Segment(Vec3(-1e200, 0, 0), Vec3(1e200, 0, 0), KernelSpec::inverse(3)));  // any scale
  expect_input_error([&] { Segment(Vec3(-1.5e308, 0, 0), Vec3(1.5e308, 0, 0), KernelSpec::inverse(3)); }, "",
                     "segment too long");
  expect_input_error([&] { Segment(Vec3(nan, 0, 0), b, KernelSpec::inverse(3)); }, "a", "must be finite");
  expect_input_error([&] { Segment(a, Vec3(0, infinity, 0), KernelSpec::inverse(3)); }, "b", "must be finite");
  expect_input_error([&] { Segment(a, b, KernelSpec::compact(4, -1.0)); }, "kernel.R", "must be > 0, got -1");
  expect_input_error([&] { Segment(a, b, KernelSpec::compact(4, 0.0)); }, "kernel.R", "must be > 0, got 0");
  expect_input_error([&] { Segment(a, b, KernelSpec::cauchy(4, -0.5)); }, "kernel.s", "must be > 0, got -0.5");
  expect_input_error([&] { Segment(a, b, KernelSpec::cauchy(4, nan)); }, "kernel.s", "must be finite");
  expect_input_error([&] { Segment(a, b, KernelSpec::inverse(0)); }, "kernel.degree",
                     "unsupported degree 0 for the inverse family; supported: ");
  expect_input_error([&] { Segment(a, b, KernelSpec::inverse(1000)); }, "kernel.degree",
                     "unsupported degree 1000 for the inverse family; supported: ");
  expect_input_error([&] { Segment(a, b, KernelSpec::compact(1, 1.0)); }, "kernel.degree",
                     "unsupported degree 1 for the compact family; supported: ");
  expect_input_error([&] { Segment(a, b, KernelSpec::inverse(3), {1, 2, 3, 4, 5}); }, "weight",
                     "at most 4 coefficients");
  expect_input_error([&] { Segment(a, b, KernelSpec::inverse(3), std::vector<double>{}); }, "weight",
                     "at least one coefficient");
  expect_input_error([&] { Segment(a, b, KernelSpec::inverse(3), {0.0, 0.0}); }, "weight", "all coefficients are zero");
  expect_input_error([&] { Segment(a, b, KernelSpec::inverse(3), {1.0, nan}); }, "weight[1]", "must be finite");
}

TEST(SegmentValidation, UnsupportedDegreeNamesTheGeneratedRange) {
  try {
    Segment(Vec3(0, 0, 0), Vec3(1, 0, 0), KernelSpec::inverse(1000));
    FAIL();
  } catch (const InputError& error) {
    const std::vector<int> degrees = generated_degrees(KernelFamily::inverse);
    const std::string range = std::to_string(degrees.front()) + ".." + std::to_string(degrees.back());
    EXPECT_NE(error.problem().find("supported: " + range), std::string::npos) << error.what();
  }
}

TEST(SegmentValidation, QueryPointMustBeFinite) {
  const Segment segment(Vec3(0, 0, 0), Vec3(1, 0, 0), KernelSpec::cauchy(4, 1.0));
  EXPECT_THROW(segment.value(Vec3(std::nan(""), 0, 0)), InputError);
  EXPECT_THROW(segment.gradient(Vec3(infinity, 0, 0)), InputError);
}

TEST(SegmentWeight, TrailingZerosSelectTheLowerWeightDegree) {
  const Segment segment(Vec3(0, 0, 0), Vec3(1, 0, 0), KernelSpec::inverse(3), {1.0, 0.5, 0.0, 0.0});
  EXPECT_EQ(segment.weight_degree(), 1);
  EXPECT_EQ(segment.weight().size(), 2u);
}

}  // namespace
}  // namespace skelconv
