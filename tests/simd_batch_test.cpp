// skelconv::simd batches (include/skelconv/simd/batch.hpp) against the
// scalar path they must reproduce: Segment::value_and_gradient at every
// point, to 1e-13 relative (f over |f|, ∇f over |∇f|), on every compiled
// Highway target, for every kernel with a vector instantiation, on points
// that take every form of the generated code: far from the line (Gauss
// rule), beside the segment (recurrence), beyond an end near the line (the
// Miller recurrences), on the segment (inverse: the scalar path's +inf),
// outside, across, inside and grazing a compact support.
#include "skelconv/simd/batch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "skelconv/primitives/polygon.hpp"
#include "skelconv/primitives/scalis_segment.hpp"
#include "skelconv/primitives/segment.hpp"

namespace skelconv {
namespace {

/// Demanded agreement with the scalar path (docs/simd.md): the lanes do
/// the scalar operations exactly except atan2, log and asinh (SLEEF, 1 ulp).
constexpr double batch_tolerance = 1e-13;

const Vec3 A(0.1, -0.2, 0.3), B(1.1, 0.4, -0.2);

/// Points in every region of the segment's forms (see the file comment).
std::vector<Vec3> form_covering_points() {
  std::mt19937_64 random(15);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Vec3 ab = B - A;
  const double length = ab.norm();
  const Vec3 n1 = ab.unitOrthogonal(), n2 = ab.normalized().cross(n1);
  std::vector<Vec3> points;
  auto around = [&](double t, double distance) {
    const double angle = 3.14159265358979 * u(random);
    points.push_back(A + t * ab + distance * length * (std::cos(angle) * n1 + std::sin(angle) * n2));
  };
  for (int k = 0; k < 96; ++k) around(0.5 + 0.7 * u(random), 1.5 + 0.5 * u(random));      // far: Gauss
  for (int k = 0; k < 96; ++k) around(0.5 + 0.5 * u(random), 0.05 + 0.04 * u(random));    // beside
  for (int k = 0; k < 64; ++k) around(1.3 + 0.25 * u(random), 0.02 * (1 + u(random)));   // beyond B
  for (int k = 0; k < 64; ++k) around(-0.3 + 0.25 * u(random), 0.02 * (1 + u(random)));  // beyond A
  for (int k = 0; k < 32; ++k) around(0.5 + 2.0 * u(random), 0.3 + 0.3 * u(random));     // mixed
  // The compact support (R = 0.9, vector_segments) grazing the segment:
  // P at 0.9 (1 − δ) from the line over the middle (the chord inside), from
  // B beyond it (the part inside), and from the line beside B (the chord
  // straddling B): the support-root forms of the generated code.
  std::uniform_real_distribution<double> log_delta(-6.0, -2.0);
  for (int k = 0; k < 16; ++k) around(0.5 + 0.2 * u(random), 0.9 * (1 - std::pow(10.0, log_delta(random))) / length);
  for (int k = 0; k < 16; ++k) {
    const double reach = 0.9 * (1 - std::pow(10.0, log_delta(random))) / length, angle = 0.5 * (1 + u(random));
    around(1 + reach * std::cos(angle), reach * std::sin(angle));
  }
  for (int k = 0; k < 16; ++k) around(0.97, 0.9 * (1 - std::pow(10.0, log_delta(random))) / length);
  for (int k = 0; k < 256; ++k) {  // anywhere in the box grown by 1.5 (the compact rims included)
    const Vec3 lo = A.cwiseMin(B) - Vec3::Constant(1.5), hi = A.cwiseMax(B) + Vec3::Constant(1.5);
    points.push_back(lo + (0.5 * (Vec3(u(random), u(random), u(random)) + Vec3::Ones())).cwiseProduct(hi - lo));
  }
  // Exactly on the segment (inverse: +inf): its ends, where AB × AP is 0 in
  // doubles. (A + t AB for other t is off the line by rounding, ~1e-17: a
  // point where f ~ 1e33 and ∇f is rounding noise, on either path.)
  points.push_back(A);
  points.push_back(B);
  std::shuffle(points.begin(), points.end(), random);  // forms mixed within every vector
  return points;
}

/// |batch − scalar| against the scalar value's scale; both +inf is equal.
double difference(double batch, double scalar, double scale) {
  if (batch == scalar) return 0.0;
  return std::abs(batch - scalar) / scale;
}

/// The largest relative difference of the batch to the scalar path.
template <class Primitive>
double batch_against_scalar(const Primitive& segment, const std::vector<Vec3>& points, simd::BatchCounts& counts) {
  const std::size_t n = points.size();
  std::vector<double> x(n), y(n), z(n), f(n, -1), gx(n, -1), gy(n, -1), gz(n, -1);
  for (std::size_t k = 0; k < n; ++k) {
    x[k] = points[k][0];
    y[k] = points[k][1];
    z[k] = points[k][2];
  }
  counts = simd::value_and_gradient(segment, {x.data(), y.data(), z.data(), n}, {f.data(), gx.data(), gy.data(), gz.data()});
  double worst = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const FieldSample s = segment.value_and_gradient(points[k]);
    const double g_scale = std::max(s.gradient.norm(), 1e-300);
    const double here = std::max({difference(f[k], s.value, std::max(std::abs(s.value), 1e-300)),
                                  difference(gx[k], s.gradient[0], g_scale), difference(gy[k], s.gradient[1], g_scale),
                                  difference(gz[k], s.gradient[2], g_scale)});
    if (here > batch_tolerance) {
      ADD_FAILURE() << " at (" << points[k].transpose() << "): batch " << f[k] << " "
                    << gx[k] << " " << gy[k] << " " << gz[k] << ", scalar " << s.value << " "
                    << s.gradient.transpose();
    }
    worst = std::max(worst, here);
  }
  return worst;
}

std::vector<Segment> vector_segments() {
  std::vector<Segment> segments;
  const double weights[4] = {1.0, 0.5, 0.25, 0.125};
  for (const KernelFamily family : {KernelFamily::inverse, KernelFamily::cauchy, KernelFamily::compact}) {
    for (int w = 0; w <= max_weight_degree; ++w) {
      for (const int degree : Segment::supported_degrees(family, w)) {
        const KernelSpec kernel = family == KernelFamily::inverse  ? KernelSpec::inverse(degree)
                                  : family == KernelFamily::cauchy ? KernelSpec::cauchy(degree, 2.0)
                                                                   : KernelSpec::compact(degree, 0.9);
        Segment segment(A, B, kernel, std::span<const double>(weights, std::size_t(w + 1)));
        if (simd::has_vector_kernel(segment)) segments.push_back(segment);
      }
    }
  }
  return segments;
}

class SimdSegmentBatch : public testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    if (!simd::force_target(GetParam())) GTEST_SKIP() << GetParam() << " is not available here";
  }
  void TearDown() override { simd::force_target(""); }
};

TEST_P(SimdSegmentBatch, EqualsTheScalarPathOnEveryForm) {
  ASSERT_EQ(simd::active_target(), GetParam());
  const std::vector<Vec3> points = form_covering_points();
  const std::vector<Segment> segments = vector_segments();
  ASSERT_GE(segments.size(), 8u);  // src/simd/segment_kernels.hpp
  for (const Segment& segment : segments) {
    simd::BatchCounts counts;
    const double worst = batch_against_scalar(segment, points, counts);
    EXPECT_LE(worst, batch_tolerance) << segment.generated_name();
    // The vector path ran, and lanes were set aside and re-run by form.
    EXPECT_GT(counts.group_runs, 0u) << segment.generated_name();
    EXPECT_GT(counts.set_aside, 0u) << segment.generated_name();
    std::printf("%s %s: worst %.1e, %zu group runs, %zu set aside, %zu scalar, %zu zero\n", GetParam().c_str(),
                segment.generated_name().c_str(), worst, counts.group_runs, counts.set_aside, counts.scalar_points,
                counts.zero_points);
    // Only the points on the inverse kernel's segment (A and B: +inf) are
    // left to the scalar path; every form, the Miller recurrences included,
    // runs vectorised.
    EXPECT_EQ(counts.scalar_points, segment.kernel().family == KernelFamily::inverse ? 2u : 0u)
        << segment.generated_name();
  }
}

// The vector targets. The portable SCALAR target hands every point to the
// scalar path (docs/simd.md): SimdScalarTarget below.
INSTANTIATE_TEST_SUITE_P(Targets, SimdSegmentBatch, testing::Values("AVX3", "AVX2"));

TEST_P(SimdSegmentBatch, ScalisSegmentsEqualTheScalarPathOnEveryForm) {
  const std::vector<Vec3> points = form_covering_points();
  int vectorised = 0;
  // The kernels of src/simd/scalis_kernels.hpp.
  for (const auto& [family, degree] : {std::pair{KernelFamily::inverse, 3}, std::pair{KernelFamily::cauchy, 4}}) {
    // A cone (radius 0 at B) and a tapered segment, σ = 1.5.
    for (const std::array<double, 2> radius : {std::array<double, 2>{0.2, 0.6}, std::array<double, 2>{0.5, 0.0}}) {
      const ScalisSegment segment(A, B, radius[0], radius[1], ScalisKernel{family, degree, 1.5}, 1.0);
      ASSERT_TRUE(simd::has_vector_kernel(segment));
      ++vectorised;
      simd::BatchCounts counts;
      const double worst = batch_against_scalar(segment, points, counts);
      EXPECT_LE(worst, batch_tolerance) << segment.evaluator_name();
      EXPECT_GT(counts.group_runs, 0u);
      EXPECT_LT(counts.scalar_points, points.size() / 10) << segment.evaluator_name();
      std::printf("%s SCALIS %s τ %.1f→%.1f: worst %.1e, %zu group runs, %zu set aside, %zu scalar\n",
                  GetParam().c_str(), segment.evaluator_name().c_str(), radius[0], radius[1], worst,
                  counts.group_runs, counts.set_aside, counts.scalar_points);
    }
  }
  EXPECT_EQ(vectorised, 4);
}

/// Points around a polygon in every form of its edge kernels (the edges'
/// far Gauss rule, beside, beyond an end near the line), above and below
/// the interior, near the plane, exactly in the plane (inside: the inverse
/// kernel's +inf; outside), exactly on an edge's line (h = 0: the scalar
/// path), and in the far field (≥ 5 radii: the scalar path). `scale`
/// multiplies everything (a power of two: the frame's restore is exact).
std::vector<Vec3> polygon_points(const std::vector<Vec3>& vertices, double scale) {
  std::mt19937_64 random(16);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> points;
  const Vec3 centre = (vertices[0] + vertices[2]) / 2;
  const Vec3 normal = (vertices[1] - vertices[0]).cross(vertices[2] - vertices[0]).normalized();
  for (int k = 0; k < 256; ++k) points.push_back(centre + 1.2 * Vec3(u(random), u(random), u(random)));
  for (int k = 0; k < 96; ++k)  // near the plane, in and out of the polygon
    points.push_back(centre + 0.8 * Vec3(u(random), u(random), u(random)) + 1e-3 * u(random) * normal);
  for (int k = 0; k < 64; ++k) {  // near the edges' lines, beyond and beside their ends
    const std::size_t m = std::size_t(k) % vertices.size();
    const Vec3 a = vertices[m], b = vertices[(m + 1) % vertices.size()];
    points.push_back(a + (0.5 + 0.9 * u(random)) * (b - a) + 0.02 * Vec3(u(random), u(random), u(random)));
  }
  for (int k = 0; k < 16; ++k) points.push_back(centre + 8.0 * Vec3(1 + u(random), u(random), u(random)));  // far
  points.push_back(centre);                                    // in the plane, inside
  points.push_back(vertices[0] + 2.0 * (vertices[0] - centre));  // in the plane, outside
  points.push_back(vertices[0] + 0.5 * (vertices[1] - vertices[0]) + 0.3 * normal);  // above an edge: h = 0 for it
  std::shuffle(points.begin(), points.end(), random);
  for (Vec3& p : points) p *= scale;
  return points;
}

TEST_P(SimdSegmentBatch, PolygonsEqualTheScalarPathOnEveryForm) {
  // A square in the plane z = 0.25 (in-plane points exact) and a tilted
  // pentagon; at unit scale and scaled by 2^40.
  const std::vector<std::vector<Vec3>> shapes = {
      {Vec3(0, 0, 0.25), Vec3(1, 0, 0.25), Vec3(1, 1, 0.25), Vec3(0, 1, 0.25)},
      {Vec3(0, 0, 0.1), Vec3(1, 0.1, 0.42), Vec3(1.3, 0.9, 0.67), Vec3(0.5, 1.4, 0.53), Vec3(-0.2, 0.8, 0.2)}};
  // (the pentagon in the plane z = 0.1 + 0.3 x + 0.2 y)
  int vectorised = 0;
  for (const auto& shape : shapes) {
    for (const double scale : {1.0, std::ldexp(1.0, 40)}) {
      std::vector<Vec3> vertices = shape;
      for (Vec3& v : vertices) v *= scale;
      for (const KernelSpec& kernel : {KernelSpec::inverse(3), KernelSpec::cauchy(4, 2.0 / (scale * scale))}) {
        const Polygon polygon(vertices, kernel);
        ASSERT_TRUE(simd::has_vector_kernel(polygon));
        ++vectorised;
        const std::vector<Vec3> points = polygon_points(shape, scale);
        simd::BatchCounts counts;
        const double worst = batch_against_scalar(polygon, points, counts);
        EXPECT_LE(worst, batch_tolerance);
        EXPECT_GT(counts.group_runs, 0u);
        EXPECT_GT(counts.set_aside, 0u);
        // The far field (16 points) and the in-plane and on-edge-line
        // points go to the scalar path, a few more on an edge's line
        // by chance; for the inverse kernel also every point near the
        // plane (8|z| < |P − V₀|∞: the exact height of
        // skelconv/detail/plane_height.hpp, which the lanes do not compute);
        // nothing else.
        std::size_t near_plane = 0;
        if (kernel.family == KernelFamily::inverse) {
          const Vec3 n = (vertices[1] - vertices[0]).cross(vertices[2] - vertices[0]).normalized();
          for (const Vec3& p : points) near_plane += 8 * std::abs(n.dot(p - vertices[0])) < (p - vertices[0]).cwiseAbs().maxCoeff();
          EXPECT_GT(near_plane, 90u);  // the 96 near-plane points, at least
        }
        EXPECT_GE(counts.scalar_points, 16u + near_plane - near_plane / 16);
        EXPECT_LT(counts.scalar_points, 32u + near_plane);
        std::printf("%s polygon %zu vertices, %s, scale %g: worst %.1e, %zu group runs, %zu set aside, %zu scalar\n",
                    GetParam().c_str(), shape.size(), kernel.family == KernelFamily::inverse ? "inverse 3" : "cauchy 4",
                    scale, worst, counts.group_runs, counts.set_aside, counts.scalar_points);
      }
    }
  }
  EXPECT_EQ(vectorised, 8);
}

// On the SCALAR target every primitive type runs point by point through the
// scalar path: no vector group, the scalar path's numbers exactly.
TEST(SimdScalarTarget, EveryPointGoesToTheScalarPath) {
  ASSERT_TRUE(simd::force_target("SCALAR"));
  const std::vector<Vec3> points = form_covering_points();
  const Segment segment(A, B, KernelSpec::cauchy(4, 2.0));
  const ScalisSegment scalis(A, B, 0.2, 0.6, ScalisKernel{KernelFamily::inverse, 3, 1.5}, 1.0);
  const Polygon polygon({Vec3(0, 0, 0.25), Vec3(1, 0, 0.25), Vec3(1, 1, 0.25), Vec3(0, 1, 0.25)}, KernelSpec::inverse(3));
  simd::BatchCounts counts[3];
  const double worst[3] = {batch_against_scalar(segment, points, counts[0]),
                           batch_against_scalar(scalis, points, counts[1]),
                           batch_against_scalar(polygon, points, counts[2])};
  simd::force_target("");
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(worst[k], 0.0) << k;
    EXPECT_EQ(counts[k].group_runs, 0u) << k;
    EXPECT_EQ(counts[k].scalar_points, points.size()) << k;
  }
}

TEST(SimdSegmentBatchFallback, KernelWithoutVectorInstantiationEqualsScalarPath) {
  const Segment segment(A, B, KernelSpec::inverse(16), {1.0, 0.5, 0.25, 0.125});
  ASSERT_FALSE(simd::has_vector_kernel(segment));
  simd::BatchCounts counts;
  const std::vector<Vec3> points = form_covering_points();
  EXPECT_EQ(batch_against_scalar(segment, points, counts), 0.0);
  EXPECT_EQ(counts.scalar_points, points.size());
}

TEST(SimdSegmentBatchErrors, NonFinitePointThrowsTheScalarPathsError) {
  const Segment segment(A, B, KernelSpec::cauchy(4, 1.0));
  const double x[3] = {0.0, NAN, 1.0}, y[3] = {0.0, 0.0, 0.0}, z[3] = {0.0, 0.0, 0.0};
  double f[3], gx[3], gy[3], gz[3];
  EXPECT_THROW(simd::value_and_gradient(segment, {x, y, z, 3}, {f, gx, gy, gz}), InputError);
}

}  // namespace
}  // namespace skelconv
