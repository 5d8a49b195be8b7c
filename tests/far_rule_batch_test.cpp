// FarRuleBatch (far_rule_batch.hpp): Skeleton's tolerance mode on a list of
// Cauchy segments of one kind and degree chooses and sums the far rules many
// segments at a time, and must give what the per-segment path gives, bit for
// bit: the rules FarSegmentRule::nodes and ball_nodes choose, the terms
// FarSegmentRule::evaluate_nodes computes (the exact function where it
// declines), added in the tolerance mode's order (grouped by node count
// within chunks of 64 segments, the exact ones first). The reference below
// is that per-segment path written out with FarSegmentRule's public calls;
// the tolerance itself is far_segment_rule_test.cpp's.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <random>
#include <utility>
#include <vector>

#include "src/detail/far_rule_batch.hpp"
#include "skelconv/primitives/scalis_segment.hpp"
#include "skelconv/primitives/segment.hpp"
#include "skelconv/skeleton/skeleton.hpp"
#include "walk_skeleton.hpp"

namespace skelconv {
namespace far_rule_batch_test {  // named: the test files share a unity build
namespace {

using detail::FarRuleBatch;

const FarSegmentRule& rule_of(const Primitive& primitive) {
  if (const Segment* segment = std::get_if<Segment>(&primitive)) return *segment->far_rule();
  return *std::get<ScalisSegment>(primitive).far_rule();
}

std::vector<FarSegmentRule> rules_of(const Skeleton& skeleton) {
  std::vector<FarSegmentRule> rules;
  for (const Primitive& primitive : skeleton.primitives()) rules.push_back(rule_of(primitive));
  return rules;
}

FieldSample exact_of(const Primitive& primitive, const Vec3& p, bool gradient) {
  if (const Segment* segment = std::get_if<Segment>(&primitive)) {
    return gradient ? segment->value_and_gradient(p) : FieldSample{segment->value(p), Vec3::Zero()};
  }
  const ScalisSegment& segment = std::get<ScalisSegment>(primitive);
  return gradient ? segment.value_and_gradient(p) : FieldSample{segment.value(p), Vec3::Zero()};
}

/// A segment's ends, classical or SCALIS.
std::pair<Vec3, Vec3> ends_of(const Primitive& primitive) {
  if (const Segment* segment = std::get_if<Segment>(&primitive)) return {segment->a(), segment->b()};
  const ScalisSegment& segment = std::get<ScalisSegment>(primitive);
  return {segment.a(), segment.b()};
}

/// The n of every segment at P (ball radius < 0) or over the ball of
/// `radius` around P, one segment at a time.
std::vector<std::uint8_t> nodes_one_at_a_time(const std::vector<FarSegmentRule>& rules, const Vec3& p, double radius,
                                              double tolerance) {
  double lower = 0;
  for (const FarSegmentRule& rule : rules) {
    lower += radius < 0 ? rule.lower_bound(rule.mean_square(p)) : rule.lower_bound(rule.ball_mean_square(p, radius));
  }
  const double budget = tolerance * lower / double(rules.size());
  std::vector<std::uint8_t> nodes;
  for (const FarSegmentRule& rule : rules) {
    int n = 0;
    if (budget > 0.0) {
      n = radius < 0 ? rule.nodes(rule.end_squares(p), budget)
                     : rule.ball_nodes(rule.end_roots(rule.end_squares(p)), radius, budget);
    }
    nodes.push_back(std::uint8_t(n));
  }
  return nodes;
}

/// The tolerance mode's sum with these rules, one segment at a time.
FieldSample sum_one_at_a_time(const Skeleton& skeleton, const std::vector<FarSegmentRule>& rules,
                              const std::vector<std::uint8_t>& nodes, const Vec3& p, bool gradient) {
  FieldSample total;
  constexpr std::size_t chunk = 64;
  for (std::size_t first = 0; first < rules.size(); first += chunk) {
    const std::size_t size = std::min(chunk, rules.size() - first);
    for (int n = 0; n <= FarSegmentRule::max_nodes; n += 2) {  // the exact ones (0) first, then by n
      for (std::size_t k = first; k < first + size; ++k) {
        if (nodes[k] != n) continue;
        FieldSample term;
        if (n == 0 || !rules[k].evaluate_nodes(p, n, gradient, term)) {
          term = exact_of(skeleton.primitives()[k], p, gradient);
        }
        total.value += term.value;
        if (gradient) total.gradient += term.gradient;
      }
    }
  }
  return total;
}

/// Points on the skeleton's segments (where the exact function takes
/// over), near them and across its box and beyond.
std::vector<Vec3> probe_points(const Skeleton& skeleton, int count, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Vec3> points;
  for (int k = 0; k < count; ++k) {
    const Primitive& primitive = skeleton.primitives()[std::size_t(k * 7) % skeleton.size()];
    const auto [a, b] = ends_of(primitive);
    const Vec3 offset(unit(random), unit(random), unit(random));
    switch (k % 4) {
      case 0: points.push_back(a + (b - a) * (0.5 + 0.5 * unit(random))); break;  // on the segment
      case 1: points.push_back(a + 0.3 * offset); break;
      case 2: points.push_back(a + 2.0 * offset); break;
      default: points.push_back(a + 30.0 * offset); break;  // far beyond the walk
    }
  }
  return points;
}

bool same_bits(double x, double y) { return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y); }

/// Skeleton's values, values and gradients, and values and gradients near
/// a ball's centre, against the per-segment path, bit for bit.
void expect_same_as_one_at_a_time(const Skeleton& skeleton, const char* name) {
  const std::vector<FarSegmentRule> rules = rules_of(skeleton);
  ASSERT_TRUE(FarRuleBatch::make(rules).has_value()) << name;
  int compared = 0, approximated = 0, differing = 0;
  for (double tolerance : {1e-12, 1e-6}) {
    for (const Vec3& p : probe_points(skeleton, 120, 7)) {
      const std::vector<std::uint8_t> nodes = nodes_one_at_a_time(rules, p, -1, tolerance);
      const FieldSample both = sum_one_at_a_time(skeleton, rules, nodes, p, true);
      const FieldSample value = sum_one_at_a_time(skeleton, rules, nodes, p, false);
      const FieldSample batched = skeleton.value_and_gradient(p, tolerance);
      const double batched_value = skeleton.value(p, tolerance);
      bool same = same_bits(batched.value, both.value) && same_bits(batched_value, value.value);
      for (int i = 0; i < 3; ++i) same = same && same_bits(batched.gradient[i], both.gradient[i]);
      // Near a point: the rules of a ball of radius 0.1 around P, at a
      // point of it.
      const Vec3 q = p + Vec3(0.03, -0.05, 0.04);
      const Skeleton::NearbyRules near = skeleton.rules_near(p, 0.1, tolerance);
      const std::vector<std::uint8_t> ball_nodes = nodes_one_at_a_time(rules, p, 0.1, tolerance);
      const FieldSample near_both = sum_one_at_a_time(skeleton, rules, ball_nodes, q, true);
      const FieldSample near_batched = skeleton.value_and_gradient(q, near);
      same = same && same_bits(near_batched.value, near_both.value) &&
             same_bits(skeleton.value(q, near), sum_one_at_a_time(skeleton, rules, ball_nodes, q, false).value);
      for (int i = 0; i < 3; ++i) same = same && same_bits(near_batched.gradient[i], near_both.gradient[i]);
      differing += !same;
      ++compared;
      approximated += both.value != skeleton.value_and_gradient(p).value;
    }
  }
  std::printf("%s: %d points, %d differ from the per-segment path, %d not the exact sum\n", name, compared, differing,
              approximated);
  EXPECT_EQ(differing, 0) << name;
  EXPECT_GT(approximated, compared / 2) << name;  // the rules are in use
}

TEST(FarRuleBatch, SameBitsAsOneSegmentAtATimeOnClassicalWalks) {
  // 201 segments: three full chunks and a partial one of odd size.
  expect_same_as_one_at_a_time(walk_skeleton({201, 4, 4.0, {1.0}}, bench_walk_seed), "degree 4, s 4");
  expect_same_as_one_at_a_time(walk_skeleton({67, 3, 2.0, {1.0, 0.5}}, 11), "degree 3, linear weight");
  expect_same_as_one_at_a_time(walk_skeleton({40, 8, 1.0, {0.5, 0.0, 0.25, 1.0}}, 12), "degree 8, cubic weight");
}

TEST(FarRuleBatch, SameBitsAsOneSegmentAtATimeOnScalisWalks) {
  expect_same_as_one_at_a_time(scalis_walk_skeleton({97, 4, 1.0, 0.1, 0.6}, 13), "SCALIS degree 4");
  expect_same_as_one_at_a_time(scalis_walk_skeleton({33, 7, 2.0, 0.3, 2.0}, 14), "SCALIS degree 7");
}

/// The batch's own passes on `lanes` lanes (SSE2's 2, AVX's 4) against the
/// per-segment calls: the rules at points and over balls of radius 0.1, and
/// every chunk's terms (FarSegmentRule::evaluate_nodes, or the exact
/// function where it declines), bit for bit. Returns the (point, pass)
/// pairs that differ.
int lanes_differing(const Skeleton& skeleton, int lanes, const char* name) {
  const std::vector<FarSegmentRule> rules = rules_of(skeleton);
  const FarRuleBatch batch = *FarRuleBatch::make(rules);
  std::vector<std::uint8_t> nodes(rules.size()), ball_nodes(rules.size());
  int differing = 0, by_rules = 0;
  for (double tolerance : {1e-12, 1e-6}) {
    for (const Vec3& p : probe_points(skeleton, 120, 9)) {
      batch.choose(p, tolerance, nodes.data(), lanes);
      batch.choose_near(p, 0.1, tolerance, ball_nodes.data(), lanes);
      differing += nodes != nodes_one_at_a_time(rules, p, -1, tolerance);
      differing += ball_nodes != nodes_one_at_a_time(rules, p, 0.1, tolerance);
      for (bool gradient : {false, true}) {
        for (std::size_t first = 0; first < rules.size(); first += FarRuleBatch::chunk) {
          FarRuleBatch::Terms terms;
          batch.terms(p, first, nodes.data(), gradient, terms, lanes);
          bool same = terms.size == std::min(FarRuleBatch::chunk, rules.size() - first);
          for (std::size_t j = 0; j < terms.size; ++j) {
            const std::size_t k = first + terms.order[j];
            FieldSample term;
            const bool by_rule = nodes[k] != 0 && rules[k].evaluate_nodes(p, nodes[k], gradient, term);
            same = same && terms.exact[j] == !by_rule;
            if (!by_rule) continue;
            ++by_rules;
            same = same && same_bits(terms.value[j], term.value);
            if (gradient) {
              same = same && same_bits(terms.gradient_x[j], term.gradient.x()) &&
                     same_bits(terms.gradient_y[j], term.gradient.y()) &&
                     same_bits(terms.gradient_z[j], term.gradient.z());
            }
          }
          differing += !same;
        }
      }
    }
  }
  EXPECT_GT(by_rules, 0) << name;  // the rules are in use
  return differing;
}

TEST(FarRuleBatch, SameBitsOnSse2AndAvxLanes) {
  const Skeleton classical = walk_skeleton({201, 4, 4.0, {1.0}}, bench_walk_seed);
  const Skeleton cubic = walk_skeleton({40, 8, 1.0, {0.5, 0.0, 0.25, 1.0}}, 12);
  const Skeleton scalis = scalis_walk_skeleton({97, 4, 1.0, 0.1, 0.6}, 13);
  const Skeleton scalis_odd = scalis_walk_skeleton({33, 7, 2.0, 0.3, 2.0}, 14);
  std::vector<int> lanes = {2};
  if (FarRuleBatch::widest_lanes() == 4) lanes.push_back(4);
  else std::printf("no AVX on this processor: SSE2's lanes only\n");
  for (int width : lanes) {
    EXPECT_EQ(lanes_differing(classical, width, "degree 4"), 0) << width << " lanes";
    EXPECT_EQ(lanes_differing(cubic, width, "degree 8, cubic weight"), 0) << width << " lanes";
    EXPECT_EQ(lanes_differing(scalis, width, "SCALIS degree 4"), 0) << width << " lanes";
    EXPECT_EQ(lanes_differing(scalis_odd, width, "SCALIS degree 7"), 0) << width << " lanes";
  }
}

TEST(FarRuleBatch, OnlyListsOfOneKindAndDegree) {
  const std::vector<FarSegmentRule> degree_4 = rules_of(walk_skeleton({20, 4, 4.0, {1.0}}, 1));
  const std::vector<FarSegmentRule> degree_3 = rules_of(walk_skeleton({20, 3, 4.0, {1.0}}, 1));
  const std::vector<FarSegmentRule> linear = rules_of(walk_skeleton({20, 4, 4.0, {1.0, 1.0}}, 1));
  const std::vector<FarSegmentRule> scalis = rules_of(scalis_walk_skeleton({20, 4, 1.0, 0.2, 0.5}, 1));
  EXPECT_TRUE(FarRuleBatch::make(degree_4).has_value());
  for (const std::vector<FarSegmentRule>* other : {&degree_3, &linear, &scalis}) {
    std::vector<FarSegmentRule> mixed = degree_4;
    mixed.push_back(other->front());
    EXPECT_FALSE(FarRuleBatch::make(mixed).has_value());
  }
  EXPECT_FALSE(FarRuleBatch::make({}).has_value());
}

}  // namespace
}  // namespace far_rule_batch_test
}  // namespace skelconv
