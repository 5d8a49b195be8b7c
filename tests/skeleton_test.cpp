// Skeleton: the field is the sum of the primitives' fields, and properties
// of the definition integral that hold whatever the closed forms are:
// mirror symmetry, reversal of a segment, splitting a segment, rigid motion.
#include "skelconv/skeleton/skeleton.hpp"

#include <cmath>
#include <limits>
#include <variant>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include "src/detail/infinity.hpp"  // skelconv::infinity

namespace skelconv {
namespace {

/// The three primitives of the schema example (docs/cli_skeleton.md).
Skeleton example_skeleton() {
  Skeleton skeleton;
  skeleton.add(Segment(Vec3(0, 0, 0), Vec3(1, 0, 0), KernelSpec::inverse(3), {1.0, 0.5}));
  skeleton.add(Segment(Vec3(0, 1, 0), Vec3(1, 1, 0), KernelSpec::cauchy(4, 2.0)));
  skeleton.add(Segment(Vec3(0, 2, 0), Vec3(1, 2, 1), KernelSpec::compact(6, 1.5)));
  return skeleton;
}

const std::vector<Vec3> sample_points{Vec3(0.5, 0.5, 0.3), Vec3(-0.7, 1.2, 0.9), Vec3(2.0, 2.5, -0.4),
                                      Vec3(0.25, 1.75, 0.5), Vec3(5.0, -3.0, 1.0)};

void expect_close(double actual, double expected, double relative) {
  EXPECT_NEAR(actual, expected, relative * std::max(1.0, std::abs(expected)));
}

void expect_close(const Vec3& actual, const Vec3& expected, double relative) {
  EXPECT_LE((actual - expected).norm(), relative * std::max(1.0, expected.norm()))
      << "actual (" << actual.transpose() << ") expected (" << expected.transpose() << ")";
}

TEST(Skeleton, FieldIsTheSumOfThePrimitiveFields) {
  const Skeleton skeleton = example_skeleton();
  for (const Vec3& p : sample_points) {
    double value = 0.0;
    Vec3 gradient = Vec3::Zero();
    for (const Primitive& primitive : skeleton.primitives()) {
      value += std::get<Segment>(primitive).value(p);
      gradient += std::get<Segment>(primitive).gradient(p);
    }
    expect_close(skeleton.value(p), value, 1e-15);
    expect_close(skeleton.gradient(p), gradient, 1e-15);
    const FieldSample both = skeleton.value_and_gradient(p);
    expect_close(both.value, value, 1e-14);
    expect_close(both.gradient, gradient, 1e-14);
  }
}

/// The left-to-right sums from +0 of the primitives' own value_and_gradient
/// (`both`), value and gradient (each may be a different generated function).
struct OrderedSums {
  FieldSample both;
  double value = 0.0;
  Vec3 gradient = Vec3::Zero();
};
OrderedSums ordered_sums(const Skeleton& skeleton, const Vec3& p) {
  OrderedSums sums;
  for (const Primitive& primitive : skeleton.primitives()) {
    std::visit(
        [&](const auto& q) {
          const FieldSample term = q.value_and_gradient(p);
          sums.both.value += term.value;
          sums.both.gradient += term.gradient;
          sums.value += q.value(p);
          sums.gradient += q.gradient(p);
        },
        primitive);
  }
  return sums;
}

// Skeleton sums a list of primitives of one type in one loop over them, and
// any other list child by child: either way the same additions in the same
// order as the primitives' own evaluations, so the same bits.
TEST(Skeleton, EveryListIsTheOrderedSumOfItsPrimitivesBitForBit) {
  const Segment cauchy(Vec3(0, 1, 0), Vec3(1, 1, 0), KernelSpec::cauchy(4, 2.0));
  const ScalisSegment scalis(Vec3(0, 0, 0.5), Vec3(1, 0.2, 0.4), 0.3, 0.2, ScalisKernel::cauchy(4, 1.0));
  const std::vector<Skeleton> skeletons{
      Skeleton({cauchy}),                                           // one primitive
      example_skeleton(),                                           // three segments, three kernels
      Skeleton({scalis, Segment(Vec3(0, 0, 0), Vec3(1, 0.3, 0), KernelSpec::compact(4, 2.0))}),
      Skeleton({scalis, scalis, scalis}),
  };
  for (const Skeleton& skeleton : skeletons) {
    for (const Vec3& p : sample_points) {
      const OrderedSums sums = ordered_sums(skeleton, p);
      const FieldSample& expected = sums.both;
      const FieldSample both = skeleton.value_and_gradient(p);
      EXPECT_EQ(both.value, expected.value) << p.transpose();
      EXPECT_EQ(both.gradient, expected.gradient) << p.transpose();
      EXPECT_EQ(skeleton.value(p), sums.value) << p.transpose();
      EXPECT_EQ(skeleton.gradient(p), sums.gradient) << p.transpose();
      const FieldSample plain = skeleton.value_and_gradient(p, Skeleton::Acceleration::plain);
      EXPECT_EQ(plain.value, expected.value) << p.transpose();
      EXPECT_EQ(plain.gradient, expected.gradient) << p.transpose();
    }
  }
}

TEST(Skeleton, EmptySkeletonIsZero) {
  const Skeleton empty;
  EXPECT_EQ(empty.value(Vec3(1, 2, 3)), 0.0);
  EXPECT_EQ(empty.gradient(Vec3(1, 2, 3)), Vec3::Zero());
}

TEST(Skeleton, OnAnInverseSegmentTheSumIsInfinite) {
  const Skeleton skeleton = example_skeleton();
  const FieldSample sample = skeleton.value_and_gradient(Vec3(0.5, 0, 0));
  EXPECT_EQ(sample.value, infinity);
  EXPECT_EQ(sample.gradient, Vec3::Constant(infinity));
}

TEST(Skeleton, BadQueryPointIsAnInputErrorOfThePoint) {
  try {
    example_skeleton().value(Vec3(std::nan(""), 0, 0));
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), "");
  }
}

/// Every family, with a cubic weight so that the weight's parameterisation
/// matters.
std::vector<KernelSpec> kernels_of_every_family() {
  return {KernelSpec::inverse(1), KernelSpec::inverse(3), KernelSpec::inverse(6), KernelSpec::cauchy(2, 0.8),
          KernelSpec::cauchy(5, 3.0), KernelSpec::compact(3, 1.2), KernelSpec::compact(8, 2.5)};
}
const std::vector<double> cubic_weight{1.0, 0.4, -0.2, 0.3};

/// w(1 − t) as coefficients: the weight seen from the other end.
std::vector<double> reversed_weight(const std::vector<double>& w) {
  // Σ w_k (1 − t)^k expanded with binomial coefficients.
  std::vector<double> r(w.size(), 0.0);
  for (std::size_t k = 0; k < w.size(); ++k) {
    double binomial = 1.0;  // C(k, j)
    for (std::size_t j = 0; j <= k; ++j) {
      r[j] += w[k] * binomial * ((j % 2) ? -1.0 : 1.0);
      binomial = binomial * double(k - j) / double(j + 1);
    }
  }
  return r;
}

/// w(t0 + (t1 − t0) u) as coefficients in u: the weight of the sub-segment
/// [Γ(t0), Γ(t1)] parameterised by its own u ∈ [0, 1].
std::vector<double> restricted_weight(const std::vector<double>& w, double t0, double t1) {
  // Horner in polynomials: result = (...(w_d) (t0 + h u) + w_{d-1}) ...
  const double h = t1 - t0;
  std::vector<double> result{w.back()};
  for (std::size_t k = w.size() - 1; k-- > 0;) {
    std::vector<double> next(result.size() + 1, 0.0);
    for (std::size_t j = 0; j < result.size(); ++j) {
      next[j] += result[j] * t0;
      next[j + 1] += result[j] * h;
    }
    next[0] += w[k];
    result = next;
  }
  return result;
}

TEST(SkeletonProperties, MirrorSymmetricSkeletonGivesASymmetricField) {
  // Two segments mirrored by x → −x: f(x, y, z) = f(−x, y, z) and ∂f/∂x is odd.
  for (const KernelSpec& kernel : kernels_of_every_family()) {
    Skeleton skeleton;
    skeleton.add(Segment(Vec3(-1.0, 0.0, 0.2), Vec3(-0.2, 0.5, -0.1), kernel, cubic_weight));
    skeleton.add(Segment(Vec3(1.0, 0.0, 0.2), Vec3(0.2, 0.5, -0.1), kernel, cubic_weight));
    for (const Vec3& p : {Vec3(0.3, 0.4, 0.5), Vec3(1.1, -0.3, 0.0), Vec3(0.6, 0.3, 0.05)}) {
      const Vec3 mirrored(-p.x(), p.y(), p.z());
      const FieldSample here = skeleton.value_and_gradient(p);
      const FieldSample there = skeleton.value_and_gradient(mirrored);
      SCOPED_TRACE(testing::Message() << family_name(kernel.family) << kernel.degree << " P = " << p.transpose());
      expect_close(there.value, here.value, 1e-13);
      expect_close(there.gradient, Vec3(-here.gradient.x(), here.gradient.y(), here.gradient.z()), 1e-13);
    }
  }
}

TEST(SkeletonProperties, ReversingASegmentWithItsWeightLeavesTheFieldUnchanged) {
  const Vec3 a(0.1, -0.4, 0.3), b(1.2, 0.6, -0.5);
  for (const KernelSpec& kernel : kernels_of_every_family()) {
    const Segment forward(a, b, kernel, cubic_weight);
    const Segment backward(b, a, kernel, reversed_weight(cubic_weight));
    for (const Vec3& p : {Vec3(0.5, 0.5, 0.5), Vec3(1.5, 0.0, -0.2), Vec3(-0.3, -0.6, 0.4)}) {
      SCOPED_TRACE(testing::Message() << family_name(kernel.family) << kernel.degree << " P = " << p.transpose());
      expect_close(backward.value(p), forward.value(p), 1e-12);
      expect_close(backward.gradient(p), forward.gradient(p), 1e-12);
    }
  }
}

TEST(SkeletonProperties, SplittingASegmentLeavesTheFieldUnchanged) {
  // ∫_0^1 = ∫_0^m + ∫_m^1: [A,B] equals [A,M] + [M,B] with M = Γ(m) and the
  // weight re-parameterised on each part (the |AB| factors agree).
  const Vec3 a(0.0, 0.0, 0.0), b(1.6, 0.4, 0.8);
  const double m = 0.375;  // exact in binary, so M = Γ(m) is computed exactly
  const Vec3 middle = a + m * (b - a);
  for (const KernelSpec& kernel : kernels_of_every_family()) {
    const Segment whole(a, b, kernel, cubic_weight);
    Skeleton halves;
    halves.add(Segment(a, middle, kernel, restricted_weight(cubic_weight, 0.0, m)));
    halves.add(Segment(middle, b, kernel, restricted_weight(cubic_weight, m, 1.0)));
    for (const Vec3& p : {Vec3(0.8, 0.6, 0.1), Vec3(0.2, -0.5, 0.4), Vec3(2.0, 0.3, 1.0)}) {
      SCOPED_TRACE(testing::Message() << family_name(kernel.family) << kernel.degree << " P = " << p.transpose());
      expect_close(halves.value(p), whole.value(p), 1e-12);
      expect_close(halves.gradient(p), whole.gradient(p), 1e-12);
    }
  }
}

TEST(SkeletonProperties, RigidMotionMovesTheField) {
  // f'(Q P + T) = f(P) and ∇f'(Q P + T) = Q ∇f(P) for a rotation Q.
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.7, Vec3(1, 2, -1).normalized()).toRotationMatrix();
  const Vec3 translation(0.3, -1.1, 2.0);
  const auto move = [&](const Vec3& p) -> Vec3 { return rotation * p + translation; };
  const Vec3 a(0.1, -0.4, 0.3), b(1.2, 0.6, -0.5);
  for (const KernelSpec& kernel : kernels_of_every_family()) {
    const Segment original(a, b, kernel, cubic_weight);
    const Segment moved(move(a), move(b), kernel, cubic_weight);
    for (const Vec3& p : {Vec3(0.5, 0.5, 0.5), Vec3(1.5, 0.0, -0.2)}) {
      SCOPED_TRACE(testing::Message() << family_name(kernel.family) << kernel.degree << " P = " << p.transpose());
      const FieldSample before = original.value_and_gradient(p);
      const FieldSample after = moved.value_and_gradient(move(p));
      expect_close(after.value, before.value, 1e-12);
      expect_close(after.gradient, rotation * before.gradient, 1e-12);
    }
  }
}

}  // namespace
}  // namespace skelconv
