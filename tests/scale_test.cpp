// Any scale, never silently wrong (skelconv/detail/scaled_frame.hpp).
//
// A generic skeleton of every primitive type and kernel family is scaled by
// 2^k, k ∈ {−400, −200, 0, 200, 400} — coordinates, radii and kernel
// parameters with it (s by 2^−2k, R by 2^k; SCALIS σ is dimensionless) —
// which is exact in double. The field must then scale exactly by the
// kernel's homogeneity, f_k = 2^(m k) f_0 and ∇f_k = 2^((m − 1) k) ∇f_0
// (m the units of f: 1 − i for an inverse segment, 2 − i for an inverse
// polygon, 1 and 2 for the others, 0 for SCALIS), to relative_tolerance,
// wherever 2^(m k) f_0 is a normal double; where it is not, the evaluation
// must throw EvaluationError (never print 0, inf, NaN or a wrong number).
// Segments are also compared with long-double quadrature of the definition
// AT the scaled coordinates (long double reaches 2^±16382), so the scaled
// values are checked against the definition, not only against each other.
// Inputs that break a form which is not scale-invariant are checked one by
// one below.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "reference_quadrature.hpp"
#include "skelconv/errors.hpp"
#include "skelconv/primitives/polygon.hpp"
#include "skelconv/primitives/scalis_segment.hpp"
#include "skelconv/primitives/scalis_triangle.hpp"
#include "skelconv/primitives/segment.hpp"

namespace skelconv {
namespace {

/// The exponents k of the scales 2^k: far beyond any modelling scale, and
/// still inside the double range for these skeletons' fields (docs/stable_forms.md,
/// "Any scale").
constexpr int scale_exponents[] = {-400, -200, 0, 200, 400};

/// f_k against 2^(m k) f_0, relative. The frame makes the scaled and the
/// unscaled evaluations run on bit-identical frame coordinates, so the
/// measured difference is 0; 1e-13 is the closed forms' accuracy target for f
/// (docs/verify_reference.md), the most a scaling may cost.
constexpr double relative_tolerance = 1e-13;

/// Segments against long-double quadrature at the scaled coordinates:
/// the accuracy segment_test.cpp demands at generic points (its largest
/// tolerance, compact; measured here: printed).
constexpr double reference_tolerance = 3e-13;

/// Generic query points around a unit-size skeleton (none on a skeleton,
/// none farther than a few sizes: the generic region).
const std::vector<Vec3> generic_points = {
    {0.3, 0.7, 0.4}, {1.4, -0.6, 0.9}, {-0.5, 0.2, -0.35}, {0.55, 0.45, 1.3}, {2.1, 1.7, -0.8}};

/// An evaluation at scale 2^k: f and ∇f, or the EvaluationError it threw.
struct Outcome {
  bool threw = false;
  FieldSample sample;
};

Outcome evaluate(const std::function<FieldSample()>& f) {
  try {
    return {false, f()};
  } catch (const EvaluationError&) {
    return {true, {}};
  }
}

/// The largest relative differences seen, printed at the end of each test.
struct Worst {
  double value = 0, gradient = 0, reference = 0;
  int checked = 0, refused = 0;
};

/// Checks f_k and ∇f_k against the unscaled sample by homogeneity (see the
/// file comment); counts a refusal where the expected value is outside the
/// double range, and fails on any other outcome.
void expect_homogeneous(const FieldSample& unit, const Outcome& scaled, int value_power, int k, Worst& worst) {
  if (unit.value == 0.0) {  // compact support missed: exactly 0 at every scale
    ASSERT_FALSE(scaled.threw);
    EXPECT_EQ(scaled.sample.value, 0.0);
    EXPECT_EQ(scaled.sample.gradient, Vec3::Zero());
    return;
  }
  const double expected_value = std::ldexp(unit.value, value_power * k);
  const Vec3 expected_gradient = unit.gradient.unaryExpr([&](double g) { return std::ldexp(g, (value_power - 1) * k); });
  const bool representable = std::isnormal(expected_value) && std::isnormal(expected_gradient.cwiseAbs().maxCoeff());
  if (!representable) {
    EXPECT_TRUE(scaled.threw) << "expected an EvaluationError: f = " << unit.value << " · 2^" << value_power * k
                              << " is outside the double range, got f = " << scaled.sample.value;
    // A value that is representable while only the gradient is not may
    // legitimately be refused too; nothing else may happen.
    worst.refused += scaled.threw;
    return;
  }
  ASSERT_FALSE(scaled.threw) << "refused although f = " << expected_value << " is a normal double";
  const double value_error = std::abs(scaled.sample.value - expected_value) / std::abs(expected_value);
  // Largest component difference over the largest component: no squares,
  // which would overflow at these scales.
  const double gradient_error = (scaled.sample.gradient - expected_gradient).cwiseAbs().maxCoeff() /
                                expected_gradient.cwiseAbs().maxCoeff();
  EXPECT_LE(value_error, relative_tolerance) << "f at scale 2^" << k;
  EXPECT_LE(gradient_error, relative_tolerance) << "grad f at scale 2^" << k;
  worst.value = std::max(worst.value, value_error);
  worst.gradient = std::max(worst.gradient, gradient_error);
  ++worst.checked;
}

void print(const char* what, const Worst& worst, bool against_quadrature = false) {
  std::printf("[ scale ] %-26s %3d scaled samples checked, %3d refused (out of range); worst relative change "
              "f %.2e, grad f %.2e",
              what, worst.checked, worst.refused, worst.value, worst.gradient);
  if (against_quadrature) std::printf("; f vs quadrature at 2^0 and 2^±400: %.2e", worst.reference);
  std::printf("\n");
}

// --- segments ---------------------------------------------------------------

struct SegmentCase {
  KernelSpec kernel;
  std::vector<double> weight;
};

const std::vector<SegmentCase> segment_cases = {
    {KernelSpec::inverse(1), {1}},        {KernelSpec::inverse(3), {1, 0.5}},
    {KernelSpec::inverse(8), {1}},        {KernelSpec::inverse(16), {0.5, 0, 0, 1}},
    {KernelSpec::cauchy(2, 1.5), {1}},    {KernelSpec::cauchy(4, 0.7), {1, -0.4}},
    {KernelSpec::cauchy(16, 2.0), {1, 0.3, 0.2}},
    {KernelSpec::compact(3, 1.8), {1}},   {KernelSpec::compact(6, 2.5), {1, 0.5}},
    {KernelSpec::compact(16, 3.0), {1}},
};

KernelSpec scaled_kernel(KernelSpec kernel, int k) {
  kernel.s = std::ldexp(kernel.s, -2 * k);  // s has units length^−2
  kernel.R = std::ldexp(kernel.R, k);
  return kernel;
}

using test::to_reference;

/// Long-double quadrature of the definition at the scaled coordinates.
test::ReferenceSample segment_reference(const Vec3& a, const Vec3& b, const SegmentCase& c, const KernelSpec& kernel,
                                        const Vec3& p) {
  test::ReferenceSegment reference;
  reference.a = to_reference(a);
  reference.b = to_reference(b);
  reference.weight.assign(c.weight.begin(), c.weight.end());
  reference.family = kernel.family == KernelFamily::inverse  ? test::ReferenceFamily::inverse
                     : kernel.family == KernelFamily::cauchy ? test::ReferenceFamily::cauchy
                                                             : test::ReferenceFamily::compact;
  reference.degree = kernel.degree;
  reference.s = kernel.s;
  reference.R = kernel.R;
  return test::integrate_definition(reference, to_reference(p));
}

// A segment whose frame factor 2^−e is not a normal double (e = 1023: |AB|
// ≥ 2^1023) takes the frame's careful product instead of the factor
// prepared at construction: the same frame coordinates, so exactly the
// scaled field (compact: f has units length, ∇f none).
TEST(AnyScale, ASegmentAtTheTopOfTheDoubleRangeScalesExactly) {
  const Vec3 a(-0.4, 0.1, 0.2), b(0.9, 0.5, -0.3);  // |AB| in [1, 2)
  const KernelSpec kernel = KernelSpec::compact(3, 1.8);
  const int k = 1023;
  const Segment unit(a, b, kernel);
  const Segment scaled(std::ldexp(1.0, k) * a, std::ldexp(1.0, k) * b, scaled_kernel(kernel, k));
  int inside = 0;
  for (const Vec3& p : generic_points) {
    if (p.cwiseAbs().maxCoeff() >= 2.0) continue;  // 2·2^1023 overflows
    const FieldSample u = unit.value_and_gradient(p);
    const FieldSample o = scaled.value_and_gradient(std::ldexp(1.0, k) * p);
    EXPECT_EQ(o.value, std::ldexp(u.value, k)) << p.transpose();
    EXPECT_EQ(o.gradient, u.gradient) << p.transpose();
    inside += u.value != 0.0;
  }
  EXPECT_GE(inside, 2);
}

TEST(AnyScale, SegmentsScaleByTheirHomogeneity) {
  const Vec3 a(-0.4, 0.1, 0.2), b(0.9, 0.5, -0.3);
  Worst worst;
  for (const SegmentCase& c : segment_cases) {
    const int m = c.kernel.family == KernelFamily::inverse ? 1 - c.kernel.degree : 1;
    const Segment unit(a, b, c.kernel, c.weight);
    for (int k : scale_exponents) {
      const KernelSpec kernel = scaled_kernel(c.kernel, k);
      const Segment scaled(std::ldexp(1.0, k) * a, std::ldexp(1.0, k) * b, kernel, c.weight);
      for (const Vec3& p : generic_points) {
        SCOPED_TRACE(testing::Message() << unit.generated_name() << " k = " << k << " P = " << p.transpose());
        const FieldSample u = unit.value_and_gradient(p);
        const Vec3 pk = std::ldexp(1.0, k) * p;
        const Outcome o = evaluate([&] { return scaled.value_and_gradient(pk); });
        expect_homogeneous(u, o, m, k, worst);
        if (o.threw || k % 400 != 0) continue;
        const test::ReferenceSample r = segment_reference(scaled.a(), scaled.b(), c, kernel, pk);
        const double error = std::abs(o.sample.value - double(r.value)) / std::abs(double(r.value));
        EXPECT_LE(error, reference_tolerance) << "against quadrature at scale 2^" << k;
        worst.reference = std::max(worst.reference, error);
      }
    }
  }
  print("segments", worst, true);
  EXPECT_GT(worst.checked, 100);
  EXPECT_GT(worst.refused, 10);  // inverse degree 16 at 2^±200 is out of range
}

// --- polygons ---------------------------------------------------------------

TEST(AnyScale, PolygonsScaleByTheirHomogeneity) {
  // A tilted non-convex pentagon (planar: z = 0.2 x − 0.1 y + 0.3).
  const auto plane = [](double x, double y) { return Vec3(x, y, 0.2 * x - 0.1 * y + 0.3); };
  const std::vector<Vec3> vertices = {plane(0, 0), plane(1.2, 0.1), plane(0.8, 0.5), plane(1.1, 1.0),
                                      plane(-0.1, 0.9)};
  Worst worst;
  for (const KernelSpec& kernel :
       {KernelSpec::inverse(3), KernelSpec::inverse(8), KernelSpec::inverse(12), KernelSpec::cauchy(3, 1.3),
        KernelSpec::cauchy(10, 0.6), KernelSpec::compact(4, 1.9), KernelSpec::compact(12, 2.4)}) {
    const int m = kernel.family == KernelFamily::inverse ? 2 - kernel.degree : 2;
    const Polygon unit(vertices, kernel);
    for (int k : scale_exponents) {
      std::vector<Vec3> scaled_vertices;
      for (const Vec3& v : vertices) scaled_vertices.push_back(std::ldexp(1.0, k) * v);
      const Polygon scaled(scaled_vertices, scaled_kernel(kernel, k));  // not rejected at any scale
      EXPECT_EQ(scaled.area(), std::ldexp(unit.area(), 2 * k));
      for (const Vec3& p : generic_points) {
        SCOPED_TRACE(testing::Message() << family_name(kernel.family) << kernel.degree << " k = " << k);
        const Outcome o = evaluate([&] { return scaled.value_and_gradient(std::ldexp(1.0, k) * p); });
        expect_homogeneous(unit.value_and_gradient(p), o, m, k, worst);
      }
    }
  }
  print("polygons", worst);
  EXPECT_GT(worst.checked, 100);
}

// --- SCALIS segments and triangles --------------------------------------------

TEST(AnyScale, ScalisSegmentsAreScaleInvariant) {
  const Vec3 a(0.2, -0.3, 0.1), b(1.1, 0.4, 0.6);
  Worst worst;
  for (const ScalisKernel& kernel : {ScalisKernel::inverse(2, 1.0), ScalisKernel::inverse(7, 0.8),
                                     ScalisKernel::cauchy(4, 1.5), ScalisKernel::cauchy(10, 0.5),
                                     ScalisKernel::compact(3, 2.5), ScalisKernel::compact(8, 4.0)}) {
    for (const auto& [tau0, tau1] : {std::pair{0.3, 0.5}, std::pair{0.0, 0.4}}) {
      const ScalisSegment unit(a, b, tau0, tau1, kernel);
      for (int k : scale_exponents) {
        const double scale = std::ldexp(1.0, k);
        const ScalisSegment scaled(scale * a, scale * b, scale * tau0, scale * tau1, kernel);
        for (const Vec3& p : generic_points) {
          SCOPED_TRACE(testing::Message() << unit.evaluator_name() << " k = " << k);
          const Outcome o = evaluate([&] { return scaled.value_and_gradient(scale * p); });
          expect_homogeneous(unit.value_and_gradient(p), o, 0, k, worst);
        }
      }
    }
  }
  print("SCALIS segments", worst);
  EXPECT_EQ(worst.refused, 0);
}

TEST(AnyScale, ScalisTrianglesAreScaleInvariant) {
  const std::array<Vec3, 3> vertices = {Vec3(0, 0, 0.1), Vec3(1.3, 0.2, 0), Vec3(0.3, 1.1, -0.2)};
  Worst worst;
  // Constant radius (closed form) for every family; varying radius
  // (numerical path, ~1 ms per point) for one kernel.
  const std::vector<std::pair<ScalisKernel, std::array<double, 3>>> cases = {
      {ScalisKernel::inverse(4, 1.0), {0.3, 0.3, 0.3}},
      {ScalisKernel::cauchy(6, 1.4), {0.3, 0.3, 0.3}},
      {ScalisKernel::compact(6, 3.0), {0.3, 0.3, 0.3}},
      {ScalisKernel::cauchy(4, 1.2), {0.2, 0.4, 0.3}},
  };
  for (const auto& [kernel, radii] : cases) {
    const ScalisTriangle unit(vertices, radii, kernel);
    for (int k : scale_exponents) {
      const double scale = std::ldexp(1.0, k);
      const ScalisTriangle scaled({scale * vertices[0], scale * vertices[1], scale * vertices[2]},
                                  {scale * radii[0], scale * radii[1], scale * radii[2]}, kernel);
      for (const Vec3& p : {generic_points[0], generic_points[3]}) {
        SCOPED_TRACE(testing::Message() << family_name(kernel.family) << kernel.degree << " k = " << k);
        const Outcome o = evaluate([&] { return scaled.value_and_gradient(scale * p); });
        expect_homogeneous(unit.value_and_gradient(p), o, 0, k, worst);
      }
    }
  }
  print("SCALIS triangles", worst);
  EXPECT_EQ(worst.refused, 0);
}

// --- inputs that break scale-dependent forms, one by one ---------------------

TEST(AnyScale, CauchySegmentAtTinyCoordinatesIsPositiveAndRight) {
  // Coordinates ~1e-121, s ~ 1e240: an unscaled form loses every digit here
  // (relative error up to 9e4, and f < 0).
  const double k = -400;
  const Vec3 a = std::ldexp(1.0, k) * Vec3(-0.4, 0.1, 0.2), b = std::ldexp(1.0, k) * Vec3(0.9, 0.5, -0.3);
  const KernelSpec kernel = KernelSpec::cauchy(8, std::ldexp(1.7, 800));
  const Segment segment(a, b, kernel, {1, 0.5});
  for (const Vec3& p : generic_points) {
    const Vec3 pk = std::ldexp(1.0, k) * p;
    const double f = segment.value(pk);
    const test::ReferenceSample r = segment_reference(a, b, {kernel, {1, 0.5}}, kernel, pk);
    EXPECT_GT(f, 0.0);
    EXPECT_LE(std::abs(f - double(r.value)) / double(r.value), reference_tolerance);
  }
}

TEST(AnyScale, InverseSegmentsFarOutGiveTheFieldOrAnError) {
  // Coordinates ~1e120: an unscaled form gives f = 0 where the field is
  // 6e-121 (i = 2).
  const double scale = std::ldexp(1.0, 400);
  const Segment segment(scale * Vec3(0, 0, 0), scale * Vec3(1, 0, 0), KernelSpec::inverse(2));
  const Vec3 p = scale * Vec3(0.5, 0.3, 0);
  const double f = segment.value(p);
  const test::ReferenceSample r = segment_reference(segment.a(), segment.b(), {KernelSpec::inverse(2), {1}},
                                                    KernelSpec::inverse(2), p);
  EXPECT_LE(std::abs(f - double(r.value)) / double(r.value), reference_tolerance);
  // i = 16 there: f ~ 1e-1800, below every double: an error, never 0.
  const Segment steep(segment.a(), segment.b(), KernelSpec::inverse(16));
  EXPECT_THROW(steep.value(p), EvaluationError);
  // Coordinates ~1e-121 (where an unscaled form returns inf/nan), and near
  // 1e150 (where i16 overflows): i = 3 at 2^-400 is ~1e242, a double.
  const double tiny = std::ldexp(1.0, -400);
  const Segment small(tiny * Vec3(0, 0, 0), tiny * Vec3(1, 0, 0), KernelSpec::inverse(3));
  const Vec3 q = tiny * Vec3(0.5, 0.3, 0);
  const double g = small.value(q);
  const test::ReferenceSample s = segment_reference(small.a(), small.b(), {KernelSpec::inverse(3), {1}},
                                                    KernelSpec::inverse(3), q);
  EXPECT_LE(std::abs(g - double(s.value)) / double(s.value), reference_tolerance);
  const Segment big(Vec3(1e150, 2e150, 0), Vec3(1.5e150, 2e150, 3e149), KernelSpec::inverse(16));
  EXPECT_THROW(big.value(Vec3(1.2e150, 2.1e150, 1e149)), EvaluationError);  // f ~ 1e-2250
}

TEST(AnyScale, TinySegmentsAndPolygonsAreValid) {
  // Length 1e-200 at the origin: a check on the squared length would call it
  // "length 0" (its square underflows).
  const Segment segment(Vec3(0, 0, 0), Vec3(1e-200, 0, 0), KernelSpec::cauchy(4, 1e300));
  EXPECT_GT(segment.value(Vec3(5e-201, 1e-200, 0)), 0.0);
  // Polygons scaled by 2^±400: were "self-intersecting" and "zero area".
  for (int k : {-400, 400}) {
    const double scale = std::ldexp(1.0, k);
    EXPECT_NO_THROW(Polygon({scale * Vec3(0, 0, 0), scale * Vec3(2, 0, 0), scale * Vec3(2, 1, 0), scale * Vec3(1, 0.3, 0),
                             scale * Vec3(0, 1, 0)},
                            KernelSpec::compact(4, scale)));
  }
}

TEST(AnyScale, MessagesPrintTheWorldsNumbers) {
  // A collinear-ish polygon at 2^400: the area in the message is ~1e240,
  // printed, not inf or 0.
  const double scale = std::ldexp(1.0, 400);
  try {
    Polygon({scale * Vec3(0, 0, 0), scale * Vec3(2, 0, 0), scale * Vec3(1, 1e-12, 0)}, KernelSpec::inverse(3));
    ADD_FAILURE() << "a sliver was accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    // area 1e-12·2^800 ≈ 6.7e228, squared diameter 4·2^800 ≈ 2.7e241
    EXPECT_NE(message.find("zero area: area 6.66"), std::string::npos) << message;
    EXPECT_NE(message.find("e+228"), std::string::npos) << message;
    EXPECT_NE(message.find("2.66"), std::string::npos) << message;
    EXPECT_NE(message.find("e+241"), std::string::npos) << message;
  }
}

TEST(AnyScale, ScalisSigmaOutsideTheRangeIsRefusedOrCancels) {
  // σ = 5e-324 (the smallest subnormal): printed "-nan" with exit 0.
  const double sigma = std::numeric_limits<double>::denorm_min();
  EXPECT_THROW(ScalisSegment(Vec3(0, 0, 0), Vec3(1, 0, 0), 0.2, 0.4, ScalisKernel::cauchy(4, sigma)), InputError);
  EXPECT_THROW(ScalisTriangle({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, {0.2, 0.2, 0.2},
                              ScalisKernel::cauchy(4, sigma)),
               InputError);
  // The inverse family does not depend on σ at all (σ^i cancels in F/h).
  const ScalisSegment any(Vec3(0, 0, 0), Vec3(1, 0, 0), 0.2, 0.4, ScalisKernel::inverse(4, sigma));
  const ScalisSegment one(Vec3(0, 0, 0), Vec3(1, 0, 0), 0.2, 0.4, ScalisKernel::inverse(4, 1.0));
  EXPECT_EQ(any.value(Vec3(0.3, 0.2, 0)), one.value(Vec3(0.3, 0.2, 0)));
}

TEST(AnyScale, ScalisInverseJustBeyondAnEndIsFiniteOrTheSingularMarker) {
  // "A SCALIS inverse segment evaluated 1e-17–1e-20 beyond an end prints
  // inf": beyond the end B = (1, 0, 0) by δ the double P is either B itself
  // (δ below half an ulp of 1: P == B, on the segment, +inf by convention)
  // or a point where f is finite, and then f must be finite.
  const ScalisSegment segment(Vec3(0, 0, 0), Vec3(1, 0, 0), 0.3, 0.2, ScalisKernel::inverse(5, 1.0));
  for (double delta : {1e-15, 1e-16, 2e-16, 1e-17, 1e-20}) {
    const Vec3 p(1.0 + delta, 0, 0);
    SCOPED_TRACE(testing::Message() << "delta = " << delta);
    if (p.x() == 1.0) {
      EXPECT_EQ(segment.value(p), std::numeric_limits<double>::infinity());
      continue;
    }
    try {
      const double f = segment.value(p);
      EXPECT_TRUE(std::isfinite(f) && f > 0) << f;
    } catch (const EvaluationError&) {
      // refused with a message: allowed, never a wrong number
    }
  }
  // The same at the origin end, where doubles are dense: P = A − δ. Below
  // δ ~ ε|AB| the Gauss panels of the generated code cannot resolve the pole
  // next to the end and refuse (EvaluationError, "did not converge"): a
  // refusal is allowed, never a wrong number.
  int refused = 0;
  for (double delta : {1e-14, 1e-17, 1e-20, 1e-60}) {
    try {
      const double f = segment.value(Vec3(-delta, 0, 0));
      EXPECT_TRUE(std::isfinite(f) && f > 0) << "delta = " << delta << ": f = " << f;
    } catch (const EvaluationError&) {
      ++refused;
    }
  }
  std::printf("[ scale ] SCALIS inverse beyond the end A by 1e-14 … 1e-60: %d of 4 refused\n", refused);
}

}  // namespace
}  // namespace skelconv
