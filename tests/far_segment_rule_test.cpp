// Skeleton's tolerance mode (docs/field.md, "Tolerance"; far_segment_rule.hpp)
// against the exact field: on random walks of classical Cauchy segments of
// several degrees, sharpnesses and weights, of SCALIS Cauchy segments of
// several degrees, scales and radii (a small one among them), and of both
// mixed, at points on and around them, every f must be within tolerance · f
// of the exact sum and every component of ∇f within tolerance · f times the
// mean over the segments of (i/2) g (g = √s, or 1/(σ min τ) for SCALIS).
// The reference is the exact evaluation (the generated functions, which
// verify/ checks against float128 quadrature), summed directly; and each
// SCALIS rule alone against its own budget, where the bound is tightest.
// The mesh
// half (mesh vertices of a walk and of Zanni's ant) is
// far_segment_rule_mesh_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>
#include <vector>

#include "skelconv/errors.hpp"
#include "skelconv/field/batch.hpp"
#include "skelconv/primitives/scalis_segment.hpp"
#include "skelconv/primitives/segment.hpp"
#include "skelconv/skeleton/skeleton.hpp"
#include "walk_skeleton.hpp"

namespace skelconv {
namespace {

/// A segment's end A, classical or SCALIS.
Vec3 start_of(const Primitive& primitive) {
  if (const Segment* segment = std::get_if<Segment>(&primitive)) return segment->a();
  return std::get<ScalisSegment>(primitive).a();
}

/// Points near the skeleton (within 1.5 of a segment's end: where a mesh's
/// surface lies) and across the whole box and beyond.
std::vector<Vec3> probe_points(const Skeleton& skeleton, int count, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Eigen::AlignedBox3d box;
  for (const Primitive& primitive : skeleton.primitives()) box.extend(start_of(primitive));
  std::vector<Vec3> points;
  for (int k = 0; k < count; ++k) {
    const Vec3 a = start_of(skeleton.primitives()[std::size_t(k) % skeleton.size()]);
    const Vec3 offset(unit(random), unit(random), unit(random));
    if (k % 3 != 2) {
      points.push_back(a + 1.5 * offset);
    } else {
      points.push_back(box.center() + 1.5 * offset.cwiseProduct(box.sizes()));  // to a box's width outside
    }
  }
  return points;
}

/// ∇f's tolerance scale (docs/field.md, "Tolerance"): the mean over the
/// segments of (i/2) g, the bound of |∇f|/f of each one's kernel: g = √s
/// (classical), 1/(σ min(τ0, τ1)) (SCALIS).
double gradient_scale(const Skeleton& skeleton) {
  double sum = 0;
  for (const Primitive& primitive : skeleton.primitives()) {
    if (const Segment* segment = std::get_if<Segment>(&primitive)) {
      sum += segment->kernel().degree / 2.0 * std::sqrt(segment->kernel().s);
    } else {
      const ScalisSegment& scalis = std::get<ScalisSegment>(primitive);
      sum += scalis.kernel().degree / 2.0 / (scalis.kernel().sigma * std::min(scalis.tau0(), scalis.tau1()));
    }
  }
  return sum / double(skeleton.size());
}

struct Worst {
  double f = 0, gradient = 0;  ///< largest error over its allowance
  int approximated = 0;        ///< points whose f differs from the exact one
};

Worst check_walk(const Skeleton& skeleton, const std::vector<Vec3>& points, double tolerance) {
  Worst worst;
  const double scale = gradient_scale(skeleton);
  for (const Vec3& p : points) {
    const FieldSample exact = skeleton.value_and_gradient(p);
    const FieldSample within = skeleton.value_and_gradient(p, tolerance);
    worst.f = std::max(worst.f, std::abs(within.value - exact.value) / (tolerance * exact.value));
    worst.gradient = std::max(worst.gradient,
                              (within.gradient - exact.gradient).cwiseAbs().maxCoeff() / (tolerance * scale * exact.value));
    worst.approximated += within.value != exact.value;
    // value() alone, as the mesher asks for it.
    worst.f = std::max(worst.f, std::abs(skeleton.value(p, tolerance) - exact.value) / (tolerance * exact.value));
  }
  return worst;
}

/// printf into a string, for the names of the walks.
template <class... Args>
std::string fmt_walk(const char* format, Args... args) {
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, format, args...);
  return buffer;
}

/// check_walk at 1e-12 … 1e-3, expecting every error within its allowance
/// and the mode in use.
void expect_within(const Skeleton& skeleton, const std::vector<Vec3>& points, const std::string& name) {
  for (double tolerance : {1e-12, 1e-9, 1e-6, 1e-3}) {
    const Worst worst = check_walk(skeleton, points, tolerance);
    SCOPED_TRACE(testing::Message() << name << ", tolerance " << tolerance);
    EXPECT_LE(worst.f, 1.0);
    EXPECT_LE(worst.gradient, 1.0);
    // The mode is used: at 1e-6 and above nearly every point takes a rule somewhere.
    if (tolerance >= 1e-6) {
      EXPECT_GT(worst.approximated, int(points.size()) / 2);
    }
    std::printf("%s, tolerance %.0e: worst error / allowance %.2e (f), %.2e (grad f); %d of %zu points "
                "approximated\n",
                name.c_str(), tolerance, worst.f, worst.gradient, worst.approximated, points.size());
  }
}

/// expect_within on each walk's skeleton (`build(walk, seed)`, seeds from
/// `seed` on), at 300 points around it.
template <class W, class Build>
void expect_walks_within(const std::vector<W>& walks, unsigned seed, Build build, const char* kind) {
  for (const W& walk : walks) {
    const Skeleton skeleton = build(walk, seed);
    expect_within(skeleton, probe_points(skeleton, 300, seed + 100),
                  fmt_walk("%d %s, i = %d", walk.count, kind, walk.degree));
    ++seed;
  }
}

TEST(FarSegmentRule, WithinTheToleranceOnRandomWalks) {
  const std::vector<Walk> walks = {
      {200, 4, 4.0, {1.0}},             // the benchmark's kernel
      {120, 2, 1.0, {1.0}},             // slow decay: far segments matter most
      {120, 3, 2.0, {0.5}},             // half-integer power
      {80, 8, 9.0, {1.0, 2.0}},         // steep, linear weight
      {80, 6, 0.5, {0.2, 0.0, 0.0, 1.5}},  // cubic weight
      {60, 16, 3.0, {1.0}},             // the highest degree
  };
  expect_walks_within(walks, 1, walk_skeleton, "segments");
}

TEST(FarSegmentRule, WithinTheToleranceOnScalisWalks) {
  const std::vector<ScalisWalk> walks = {
      {24, 4, 1.0, 0.25, 1.3},  // the ant's kernel, sizes and count
      {40, 2, 1.0, 0.2, 1.0},   // the lowest degree: slow decay
      {30, 3, 0.5, 0.3, 2.0},   // half-integer power, σ < 1
      {30, 7, 2.0, 0.1, 0.6},   // σ > 1, thin
      {20, 10, 1.0, 0.2, 1.2},  // the highest degree
  };
  expect_walks_within(walks, 11, scalis_walk_skeleton, "SCALIS segments");
}

TEST(FarSegmentRule, WithinTheToleranceWithASmallRadius) {
  // A cone almost to a point: radius 0.01 at one end of one segment, probed
  // around that end (the integrand's zeros come near [0, 1] there).
  const Skeleton walk = scalis_walk_skeleton({24, 4, 1.0, 0.3, 1.0}, 21);
  std::vector<Primitive> segments = walk.primitives();
  const ScalisSegment tip = std::get<ScalisSegment>(segments[5]);
  segments[5] = ScalisSegment(tip.a(), tip.b(), tip.tau0(), 0.01, tip.kernel());
  const Skeleton skeleton(std::move(segments));
  std::vector<Vec3> points = probe_points(skeleton, 150, 22);
  std::mt19937_64 random(23);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int k = 0; k < 150; ++k) {
    points.push_back(tip.b() + 0.05 * Vec3(unit(random), unit(random), unit(random)));
  }
  expect_within(skeleton, points, "24 SCALIS segments, a radius 0.01");
}

TEST(FarSegmentRule, WithinTheToleranceOnMixedLists) {
  // Classical and SCALIS segments alternating along one walk.
  const std::vector<Vec3> points = walk_points(40, 31);
  KernelSpec cauchy;
  cauchy.family = KernelFamily::cauchy;
  cauchy.degree = 4;
  cauchy.s = 4.0;
  std::vector<Primitive> segments;
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    if (k % 2 == 0) {
      segments.emplace_back(Segment(points[k], points[k + 1], cauchy, {1.0, 0.5}));
    } else {
      segments.emplace_back(ScalisSegment(points[k], points[k + 1], 0.4, 0.7, ScalisKernel::cauchy(3, 1.0)));
    }
  }
  const Skeleton skeleton(std::move(segments));
  expect_within(skeleton, probe_points(skeleton, 300, 32), "40 classical and SCALIS segments");
}

/// Rules chosen near a centre (Skeleton::rules_near) against the exact
/// field at points up to `radius` from it, and the plain mode beyond.
Worst check_near(const Skeleton& skeleton, const std::vector<Vec3>& centres, double radius, double tolerance,
                 unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Worst worst;
  const double scale = gradient_scale(skeleton);
  for (const Vec3& centre : centres) {
    const Skeleton::NearbyRules rules = skeleton.rules_near(centre, radius, tolerance);
    for (int k = 0; k < 8; ++k) {
      Vec3 direction(unit(random), unit(random), unit(random));
      direction.normalize();
      // Half of them on the ball's sphere (just inside), where the rules
      // chosen at the centre would be furthest from their bound.
      const Vec3 p = centre + (k % 2 == 0 ? 0.999 : std::abs(unit(random))) * radius * direction;
      const FieldSample exact = skeleton.value_and_gradient(p);
      const FieldSample near = skeleton.value_and_gradient(p, rules);
      worst.f = std::max(worst.f, std::abs(near.value - exact.value) / (tolerance * exact.value));
      worst.gradient = std::max(
          worst.gradient, (near.gradient - exact.gradient).cwiseAbs().maxCoeff() / (tolerance * scale * exact.value));
      worst.approximated += near.value != exact.value;
    }
    const Vec3 beyond = centre + 1.5 * radius * Vec3::UnitX();  // outside: the plain mode, bit for bit
    const FieldSample plain = skeleton.value_and_gradient(beyond, tolerance);
    const FieldSample near = skeleton.value_and_gradient(beyond, rules);
    EXPECT_EQ(near.value, plain.value);
    EXPECT_EQ(near.gradient, plain.gradient);
  }
  return worst;
}

TEST(FarSegmentRule, RulesChosenNearAPointHoldOverItsBall) {
  // Balls from a mesher's (a sixteenth of a facet) to two segment lengths:
  // rules chosen for the centre alone would be far too short at the
  // larger balls' edges, where P comes near segments.
  const Skeleton classical = walk_skeleton({60, 4, 4.0, {1.0, 0.5}}, 41);
  const Skeleton scalis = scalis_walk_skeleton({24, 4, 1.0, 0.25, 1.3}, 42);
  const Skeleton scalis_thin = scalis_walk_skeleton({30, 7, 2.0, 0.1, 0.6}, 43);
  int case_index = 0;
  for (const Skeleton* skeleton : {&classical, &scalis, &scalis_thin}) {
    const std::vector<Vec3> centres = probe_points(*skeleton, 60, 44 + unsigned(case_index));
    for (double radius : {0.0025, 0.1, 0.5, 2.0}) {
      for (double tolerance : {1e-12, 1e-6}) {
        const Worst worst = check_near(*skeleton, centres, radius, tolerance, 45 + unsigned(case_index));
        SCOPED_TRACE(testing::Message() << "skeleton " << case_index << ", radius " << radius << ", tolerance "
                                        << tolerance);
        EXPECT_LE(worst.f, 1.0);
        EXPECT_LE(worst.gradient, 1.0);
        if (tolerance >= 1e-6) {
          EXPECT_GT(worst.approximated, int(centres.size()) * 8 / 2);
        }
        std::printf("near rules, skeleton %d, radius %g, tolerance %.0e: worst error / allowance %.2e (f), "
                    "%.2e (grad f); %d approximated\n",
                    case_index, radius, tolerance, worst.f, worst.gradient, worst.approximated);
      }
    }
    ++case_index;
  }
  // A skeleton the mode does not cover (too few segments): the plain, exact field.
  const Skeleton short_walk = walk_skeleton({5, 4, 4.0, {1.0}}, 46);
  const Vec3 centre = probe_points(short_walk, 1, 47).front();
  const Skeleton::NearbyRules rules = short_walk.rules_near(centre, 0.1, 1e-12);
  EXPECT_EQ(short_walk.value_and_gradient(centre, rules).value, short_walk.value_and_gradient(centre).value);
}

TEST(FarSegmentRule, ZeroIsTheExactField) {
  const Skeleton skeleton = walk_skeleton({50, 4, 4.0, {1.0}}, 7);
  for (const Vec3& p : probe_points(skeleton, 100, 8)) {
    const FieldSample exact = skeleton.value_and_gradient(p);
    const FieldSample zero = skeleton.value_and_gradient(p, 0.0);
    EXPECT_EQ(zero.value, exact.value);
    EXPECT_EQ(zero.gradient, exact.gradient);
  }
}

TEST(FarSegmentRule, OnlyListsOfCauchySegmentsWithoutNegativeWeightsOrZeroRadii) {
  KernelSpec cauchy;
  cauchy.family = KernelFamily::cauchy;
  cauchy.degree = 4;
  cauchy.s = 4;
  KernelSpec inverse;
  inverse.family = KernelFamily::inverse;
  inverse.degree = 3;
  EXPECT_NE(Segment(Vec3(0, 0, 0), Vec3(1, 0, 0), cauchy).far_rule(), nullptr);
  EXPECT_EQ(Segment(Vec3(0, 0, 0), Vec3(1, 0, 0), cauchy, {1.0, -0.5}).far_rule(), nullptr);
  EXPECT_EQ(Segment(Vec3(0, 0, 0), Vec3(1, 0, 0), inverse).far_rule(), nullptr);
  // A negative weight anywhere leaves the whole list exact (f̲ would not bound f).
  std::vector<Primitive> segments;
  for (int k = 0; k < 20; ++k) segments.emplace_back(Segment(Vec3(k, 0, 0), Vec3(k + 1, 0, 0), cauchy));
  segments.emplace_back(Segment(Vec3(0, 1, 0), Vec3(1, 1, 0), cauchy, {1.0, -0.5}));
  const Skeleton mixed(std::move(segments));
  const Vec3 p(3, 5, 1);
  EXPECT_EQ(mixed.value_and_gradient(p, 1e-3).value, mixed.value_and_gradient(p).value);
  // SCALIS: Cauchy with both radii positive; a radius 0 (a cone's tip,
  // where the field diverges) leaves the whole list exact.
  const ScalisKernel scalis = ScalisKernel::cauchy(4, 1.0);
  EXPECT_NE(ScalisSegment(Vec3(0, 0, 0), Vec3(1, 0, 0), 0.5, 0.2, scalis).far_rule(), nullptr);
  EXPECT_EQ(ScalisSegment(Vec3(0, 0, 0), Vec3(1, 0, 0), 0.5, 0.0, scalis).far_rule(), nullptr);
  EXPECT_EQ(ScalisSegment(Vec3(0, 0, 0), Vec3(1, 0, 0), 0.5, 0.2, ScalisKernel::inverse(3, 1.0)).far_rule(), nullptr);
  std::vector<Primitive> cone = scalis_walk_skeleton({20, 4, 1.0, 0.3, 1.0}, 41).primitives();
  const ScalisSegment& last = std::get<ScalisSegment>(cone.back());
  cone.back() = ScalisSegment(last.a(), last.b(), last.tau0(), 0.0, scalis);
  const Skeleton with_tip(std::move(cone));
  EXPECT_EQ(with_tip.value_and_gradient(p, 1e-3).value, with_tip.value_and_gradient(p).value);
}

TEST(FarSegmentRule, BadToleranceIsAnInputError) {
  const Skeleton skeleton = walk_skeleton({10, 4, 4.0, {1.0}}, 3);
  for (double bad : {-1e-12, 1.0, std::nan(""), double(INFINITY)}) {
    try {
      (void)skeleton.value_and_gradient(Vec3(0, 0, 0), bad);
      ADD_FAILURE() << bad;
    } catch (const InputError& error) {
      EXPECT_EQ(error.where(), "tolerance") << error.what();
    }
    BatchOptions options;
    options.tolerance = bad;
    const std::vector<Vec3> points{Vec3(0, 0, 0)};
    EXPECT_THROW(evaluate_batch(skeleton, points, options), InputError);
  }
}

TEST(FarSegmentRule, BatchesGiveTheSameBytesOnAnyThreadCount) {
  const Skeleton skeleton = walk_skeleton({100, 4, 4.0, {1.0}}, 5);
  const std::vector<Vec3> points = probe_points(skeleton, 500, 6);
  BatchOptions one;
  one.threads = 1;
  one.tolerance = 1e-12;
  BatchOptions three = one;
  three.threads = 3;
  const BatchResult a = evaluate_batch(skeleton, points, one), b = evaluate_batch(skeleton, points, three);
  for (std::size_t k = 0; k < points.size(); ++k) {
    EXPECT_EQ(a.samples[k].value, b.samples[k].value);
    EXPECT_EQ(a.samples[k].gradient, b.samples[k].gradient);
    EXPECT_EQ(a.samples[k].value, skeleton.value_and_gradient(points[k], 1e-12).value);
  }
}

}  // namespace
}  // namespace skelconv

namespace skelconv {
namespace {

/// The largest |error| / budget of one segment's rule (f, and ∇f over
/// (i/2) g), over points around it and budgets just at each rule's
/// threshold: what the test below holds to 1, and how near the bound is.
struct RuleWorst {
  double f = 0, gradient = 0;
};

RuleWorst worst_rule_error(const ScalisSegment& segment, unsigned seed) {
  const FarSegmentRule& rule = *segment.far_rule();
  const double g = segment.kernel().degree / 2.0 / (segment.kernel().sigma * std::min(segment.tau0(), segment.tau1()));
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  RuleWorst worst;
  const Vec3 middle = 0.5 * (segment.a() + segment.b());
  for (int k = 0; k < 400; ++k) {
    const double reach = std::pow(10.0, unit(random) + 1);  // 1 … 100 from the middle
    const Vec3 p = middle + reach * Vec3(unit(random), unit(random), unit(random));
    const FieldSample exact = segment.value_and_gradient(p);
    int previous = -1;
    // Budgets from 1e-2 f down to 1e-13 f (1e3 times the rounding of either
    // sum) by factors 1.05: each rule's
    // largest budget (the bound just at it) comes within 1.05 of its edge.
    for (double budget = 1e-2 * exact.value; budget > 1e-13 * exact.value; budget /= 1.05) {
      const int n = rule.nodes(p, budget);
      if (n == 0 || n == previous) continue;
      previous = n;
      FieldSample within;
      if (!rule.evaluate_nodes(p, n, true, within)) continue;
      worst.f = std::max(worst.f, std::abs(within.value - exact.value) / budget);
      worst.gradient = std::max(worst.gradient, (within.gradient - exact.gradient).cwiseAbs().maxCoeff() / (g * budget));
    }
  }
  return worst;
}

TEST(FarSegmentRule, EachScalisRuleWithinItsBudget) {
  // Degrees 2 … 10, radii near equal, ten times apart, small at one end.
  const std::vector<std::array<double, 4>> cases = {  // degree, σ, τ0, τ1
      {2, 1.0, 0.5, 0.6}, {4, 1.0, 0.6, 1.3}, {4, 1.0, 1.0, 0.1}, {3, 0.5, 0.3, 0.9},
      {7, 2.0, 0.2, 0.4}, {10, 1.0, 0.8, 0.08}, {4, 1.0, 0.01, 0.5}};
  unsigned seed = 51;
  for (const auto& [degree, sigma, tau0, tau1] : cases) {
    const ScalisSegment segment(Vec3(0.1, -0.2, 0.3), Vec3(1.2, 0.4, -0.1), tau0, tau1,
                                ScalisKernel::cauchy(int(degree), sigma));
    const RuleWorst worst = worst_rule_error(segment, seed++);
    std::printf("SCALIS i = %d, sigma %.1f, radii %.2f, %.2f: worst rule error / budget %.2e (f), %.2e (grad f)\n",
                int(degree), sigma, tau0, tau1, worst.f, worst.gradient);
    EXPECT_LE(worst.f, 1.0);
    EXPECT_LE(worst.gradient, 1.0);
  }
}

/// The lower bound from Q's mean (Jensen's inequality, far_segment_rule.hpp)
/// at 400 points 0.01–100 segment lengths from the middle: at most the exact
/// f, and at least the bound from Q's larger end, which it tightens; over
/// balls, the bound of ball_mean_square at most f anywhere in the ball.
/// Returns the largest ratio of the bound to f seen (< 1).
template <class S>
double expect_lower_bound_below_f(const S& segment, unsigned seed) {
  const FarSegmentRule& rule = *segment.far_rule();
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const Vec3 middle = 0.5 * (segment.a() + segment.b());
  const double length = (segment.b() - segment.a()).norm();
  double closest = 0;
  for (int k = 0; k < 400; ++k) {
    const double reach = length * std::pow(10.0, 2 * unit(random));  // 0.01 … 100 lengths from the middle
    const Vec3 p = middle + reach * Vec3(unit(random), unit(random), unit(random));
    const double f = segment.value(p);
    const double lower = rule.lower_bound(p);
    const FarSegmentRule::EndSquares ends = rule.end_squares(p);
    EXPECT_LE(lower, f * (1 + 1e-14)) << "at " << p.transpose();
    EXPECT_GE(lower, rule.lower_bound(std::max(ends.a, ends.b)) * (1 - 1e-14)) << "at " << p.transpose();
    closest = std::max(closest, lower / f);
    const double radius = reach * 0.5 * (1 + unit(random));
    const double ball_lower = rule.lower_bound(rule.ball_mean_square(p, radius));
    for (int j = 0; j < 8; ++j) {
      Vec3 offset(unit(random), unit(random), unit(random));
      if (offset.norm() > 1) offset /= offset.norm();
      const Vec3 q = p + radius * offset;
      EXPECT_LE(ball_lower, segment.value(q) * (1 + 1e-14)) << "ball at " << p.transpose() << ", radius " << radius;
    }
  }
  return closest;
}

TEST(FarSegmentRule, LowerBoundFromTheMeanOfQ) {
  unsigned seed = 61;
  for (const auto& [degree, s, weight] : std::vector<std::tuple<int, double, std::vector<double>>>{
           {4, 4.0, {1.0}}, {3, 1.0, {1.0, 0.5}}, {8, 9.0, {0.2, 0.0, 1.0, 0.3}}, {16, 0.5, {1.0, 2.0}}}) {
    const Segment segment(Vec3(0.1, -0.2, 0.3), Vec3(1.2, 0.4, -0.1), KernelSpec::cauchy(degree, s), weight);
    ASSERT_NE(segment.far_rule(), nullptr);
    const double closest = expect_lower_bound_below_f(segment, seed++);
    std::printf("classical i = %d, s %.1f: largest lower bound / f %.3f\n", degree, s, closest);
  }
  for (const auto& [degree, sigma, tau0, tau1] : std::vector<std::array<double, 4>>{
           {2, 1.0, 0.5, 0.6}, {4, 1.0, 0.6, 1.3}, {4, 1.0, 1.0, 0.1}, {7, 2.0, 0.2, 0.4}, {10, 1.0, 0.8, 0.08}}) {
    const ScalisSegment segment(Vec3(0.1, -0.2, 0.3), Vec3(1.2, 0.4, -0.1), tau0, tau1,
                                ScalisKernel::cauchy(int(degree), sigma));
    ASSERT_NE(segment.far_rule(), nullptr);
    const double closest = expect_lower_bound_below_f(segment, seed++);
    std::printf("SCALIS i = %d, radii %.2f, %.2f: largest lower bound / f %.3f\n", int(degree), tau0, tau1, closest);
  }
}

}  // namespace
}  // namespace skelconv

