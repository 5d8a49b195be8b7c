// The bounding-volume index (skelconv/field/support_grid.hpp) and the batch
// entry point (skelconv/field/batch.hpp): the indexed sum equals the plain
// sum bit for bit, on every compact primitive type, at random points and at
// points placed on and just beyond support boundaries; batches give the
// same bytes for any thread count, and report the lowest failing point.
#include <algorithm>
#include <cstring>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "skelconv/field/batch.hpp"
#include "skelconv/field/support_box.hpp"
#include "skelconv/field/support_grid.hpp"
#include "skelconv/skeleton/skeleton.hpp"

namespace skelconv {
namespace {

/// Bitwise equality of two samples (EXPECT_EQ on doubles would call −0 = +0
/// and miss a changed sign).
bool same_bits(const FieldSample& a, const FieldSample& b) {
  return std::memcmp(&a.value, &b.value, sizeof(double)) == 0 &&
         std::memcmp(a.gradient.data(), b.gradient.data(), 3 * sizeof(double)) == 0;
}

/// Where mixed_skeleton puts its primitives: in the root sum, in a sum
/// node under a union, or directly in a union or super-elliptic node (all
/// four are indexed).
enum class Parent { root, sum_under_union, union_node, super_elliptic_node };

/// `count` primitives scattered in [0, 4]³: every compact type (segments,
/// polygons, points, SCALIS segments and triangles) and, every 10th, an
/// infinite-support Cauchy segment or point, as children of `parent_kind`.
Skeleton mixed_skeleton(int count, Parent parent_kind = Parent::root) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 4.0), small(-0.3, 0.3), radius(0.2, 0.5);
  Skeleton skeleton;
  Skeleton::NodeId parent = Skeleton::root;
  if (parent_kind == Parent::sum_under_union) {
    // A union over a point and a sum node holding everything: the sum is
    // indexed inside the tree too.
    const Skeleton::NodeId node = skeleton.add_blend(Blend::union_max());
    skeleton.add(PointPrimitive(Vec3(2, 2, 2), KernelSpec::cauchy(4, 0.5)), node);
    parent = skeleton.add_blend(Blend::sum(), node);
  } else if (parent_kind == Parent::union_node) {
    parent = skeleton.add_blend(Blend::union_max());
  } else if (parent_kind == Parent::super_elliptic_node) {
    // r < c: a child at 0 adds nothing; r > c: it adds a constant (both kept
    // exact by writing skipped children as zeros).
    std::vector<double> r;
    for (int k = 0; k < count; ++k) r.push_back(k % 3 == 0 ? 0.7 : 0.3);
    parent = skeleton.add_blend(Blend::super_elliptic(1.5, r, 0.5));
  }
  for (int k = 0; k < count; ++k) {
    const Vec3 c(u(rng), u(rng), u(rng));
    const Vec3 d(small(rng), small(rng), small(rng));
    const double R = radius(rng);
    switch (k % 10 == 9 ? 5 + (k / 10) % 2 : k % 5) {
      case 0: skeleton.add(Segment(c, c + d, KernelSpec::compact(4, R)), parent); break;
      case 1:
        skeleton.add(Polygon({c, c + Vec3(0.3, 0, 0), c + Vec3(0.1, 0.25, 0.05)}, KernelSpec::compact(6, R)),
                     parent);
        break;
      case 2: skeleton.add(PointPrimitive(c, KernelSpec::compact(3, R), 0.7), parent); break;
      case 3:
        skeleton.add(ScalisSegment(c, c + d, 0.5 * R, 0.3 * R, ScalisKernel::compact(4, 1.5)), parent);
        break;
      case 4:
        skeleton.add(ScalisTriangle({c, c + Vec3(0.3, 0, 0), c + Vec3(0, 0.3, 0.1)}, {0.1, 0.1, 0.1},
                                    ScalisKernel::compact(4, 2.0)),
                     parent);
        break;
      case 5: skeleton.add(Segment(c, c + d, KernelSpec::cauchy(4, 8.0)), parent); break;
      default: skeleton.add(PointPrimitive(c, KernelSpec::cauchy(3, 8.0), 0.1), parent); break;
    }
  }
  return skeleton;
}

/// Random points in and around the skeleton, plus points on and just
/// beyond the support sphere of every compact point primitive (where the
/// box test and the primitive's own test are closest).
std::vector<Vec3> probe_points(const Skeleton& skeleton, int random_count) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-0.5, 4.5);
  std::vector<Vec3> points;
  for (int k = 0; k < random_count; ++k) points.emplace_back(u(rng), u(rng), u(rng));
  for (const Primitive& primitive : skeleton.primitives()) {
    if (const auto* point = std::get_if<PointPrimitive>(&primitive)) {
      const double R = point->support_radius();
      if (!std::isfinite(R)) continue;
      for (double scale : {1.0 - 1e-12, 1.0, 1.0 + 1e-12, 1.0 + 1e-6}) {
        points.push_back(point->center() + Vec3(R * scale, 0, 0));
        points.push_back(point->center() - Vec3(0, 0, R * scale));
      }
    }
  }
  return points;
}

TEST(SkeletonIndex, IndexedEqualsPlainBitForBit) {
  for (Parent parent : {Parent::root, Parent::sum_under_union, Parent::union_node, Parent::super_elliptic_node}) {
    SCOPED_TRACE(int(parent));
    const Skeleton skeleton = mixed_skeleton(150, parent);
    int nonzero = 0;
    for (const Vec3& p : probe_points(skeleton, 400)) {
      const FieldSample indexed = skeleton.value_and_gradient(p, Skeleton::Acceleration::indexed);
      const FieldSample plain = skeleton.value_and_gradient(p, Skeleton::Acceleration::plain);
      EXPECT_TRUE(same_bits(indexed, plain)) << p.transpose() << ": " << indexed.value << " vs " << plain.value;
      nonzero += indexed.value != 0.0;
    }
    EXPECT_GT(nonzero, 200);  // the points do meet the primitives
  }
}

/// SCALIS segments and triangles and points of positive weight, scattered
/// in [0, 4]³ as mixed_skeleton's: every term ≥ 0. With `nested`, every
/// third primitive goes into a sum node under the root sum instead (where
/// Skeleton::reaches stops inside the inner sum).
Skeleton nonnegative_skeleton(int count, bool nested) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 4.0), small(-0.6, 0.6), radius(0.3, 0.8);
  Skeleton skeleton;
  const Skeleton::NodeId inner = nested ? skeleton.add_blend(Blend::sum()) : Skeleton::root;
  for (int k = 0; k < count; ++k) {
    const Skeleton::NodeId parent = k % 3 == 0 ? inner : Skeleton::root;
    const Vec3 c(u(rng), u(rng), u(rng));
    const Vec3 d(small(rng), small(rng), small(rng));
    const double R = radius(rng);
    switch (k % 3) {
      case 0: skeleton.add(ScalisSegment(c, c + d, 0.5 * R, 0.3 * R, ScalisKernel::compact(4, 1.5)), parent); break;
      case 1:
        skeleton.add(ScalisTriangle({c, c + Vec3(0.6, 0, 0), c + Vec3(0, 0.6, 0.2)}, {0.3 * R, 0.3 * R, 0.3 * R},
                                    ScalisKernel::compact(4, 1.5)),
                     parent);
        break;
      default: skeleton.add(PointPrimitive(c, KernelSpec::compact(4, R), 0.7), parent); break;
    }
  }
  return skeleton;
}

TEST(SkeletonReaches, DecidesAsTheValueDoes) {
  // reaches(p, level) stops adding a sum of terms ≥ 0 once it is twice the
  // level: its answer must be value(p) >= level at every level, those just
  // below and above f(p) included (where nothing may stop early), and on
  // skeletons it does not cover (negative weights, unions: the value).
  std::vector<Skeleton> skeletons;
  skeletons.push_back(nonnegative_skeleton(300, false));
  skeletons.push_back(nonnegative_skeleton(300, true));
  skeletons.push_back(mixed_skeleton(150));
  skeletons.push_back(mixed_skeleton(150, Parent::sum_under_union));
  for (std::size_t s = 0; s < skeletons.size(); ++s) {
    SCOPED_TRACE(s);
    const Skeleton& skeleton = skeletons[s];
    int inside = 0, far_inside = 0;
    for (const Vec3& p : probe_points(skeleton, 1500)) {
      const double f = skeleton.value(p);
      std::vector<double> levels{0.05, 0.3, 1.0, 3.0, f, std::nextafter(f, 0.0), std::nextafter(f, 1e300),
                                 0.5 * f, std::nextafter(0.5 * f, 0.0), std::nextafter(0.5 * f, 1e300), 0.2 * f};
      for (const double level : levels) {
        if (!(level > 0.0)) continue;
        EXPECT_EQ(skeleton.reaches(p, level), f >= level) << p.transpose() << " f " << f << " level " << level;
      }
      inside += f >= 1.0;
      far_inside += f >= 2.0;
    }
    if (s < 2) {
      EXPECT_GT(inside, 50);      // the probes meet the primitives...
      EXPECT_GT(far_inside, 20);  // ...and points where the sum may stop early
    }
  }
}

TEST(SkeletonIndex, GridVisitsExactlyTheBoxesHoldingThePoint) {
  // Against brute force over the boxes, on random boxes of varied sizes
  // (a few far larger than the rest: visited everywhere).
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0.0, 10.0), size(0.05, 0.6);
  std::vector<std::optional<SupportBox>> boxes;
  for (int k = 0; k < 500; ++k) {
    if (k % 50 == 7) {
      boxes.push_back(std::nullopt);
      continue;
    }
    const Vec3 lo(u(rng), u(rng), u(rng));
    const double s = k % 97 == 3 ? 8.0 : size(rng);
    boxes.push_back(SupportBox{lo, lo + Vec3(s, 0.7 * s, 1.3 * s)});
  }
  const SupportGrid grid(boxes);
  EXPECT_LT(grid.gridded_count(), boxes.size());  // the nullopt and large ones
  std::uniform_real_distribution<double> q(-1.0, 12.0);
  for (int n = 0; n < 2000; ++n) {
    const Vec3 p(q(rng), q(rng), q(rng));
    std::vector<std::size_t> visited, expected;
    grid.for_each_active(p, [&](std::size_t k) { visited.push_back(k); });
    for (std::size_t k = 0; k < boxes.size(); ++k)
      if (!boxes[k] || boxes[k]->contains(p)) expected.push_back(k);
    // The grid may visit an always-visited large box that misses p, never
    // skip one that holds it, and keeps ascending order.
    std::vector<std::size_t> visited_holding;
    for (std::size_t k : visited)
      if (!boxes[k] || boxes[k]->contains(p)) visited_holding.push_back(k);
    EXPECT_EQ(visited_holding, expected);
    EXPECT_TRUE(std::is_sorted(visited.begin(), visited.end()));
  }
}

/// Every point of `points` is outside `box` and there the primitive is
/// exactly 0 with a zero gradient: the kernel vanishes beyond its support
/// radius R (K(r) = 0 for r ≥ R, docs/mathematics.md §1), and the box holds the support.
template <class P>
void expect_zero_outside(const P& primitive, const SupportBox& box, std::initializer_list<Vec3> points) {
  for (const Vec3& p : points) {
    EXPECT_FALSE(box.contains(p)) << p.transpose();
    const FieldSample f = primitive.value_and_gradient(p);
    EXPECT_EQ(f.value, 0.0) << p.transpose();
    EXPECT_EQ(f.gradient, Vec3::Zero()) << p.transpose();
  }
}

TEST(SupportBox, EveryFiniteSupportFamilyOnSegmentsAndPolygons) {
  // soft and wyvill vanish beyond R like compact does, on segments and
  // polygons too (their closed forms are compact levels): they must be boxed
  // (indexed), the Gaussian (infinite support) must not.
  const double R = 0.7;
  for (const KernelSpec& kernel : {KernelSpec::compact(4, R), KernelSpec::soft(R), KernelSpec::wyvill(R)}) {
    SCOPED_TRACE(std::string(family_name(kernel.family)));
    const Segment segment(Vec3(0, 0, 0), Vec3(1, 0.5, 0), kernel);
    const std::optional<SupportBox> segment_box = support_box(Primitive(segment));
    ASSERT_TRUE(segment_box.has_value());
    // Points at 0.99 R from the segment's ends lie in the support: inside.
    EXPECT_TRUE(segment_box->contains(Vec3(-0.99 * R, 0, 0)));
    EXPECT_TRUE(segment_box->contains(Vec3(1 + 0.99 * R, 0.5, 0)));
    EXPECT_TRUE(segment_box->contains(Vec3(0.5, 0.25, 0.99 * R)));
    expect_zero_outside(segment, *segment_box,
                        {Vec3(-1.01 * R, 0, 0), Vec3(1 + 1.01 * R, 0.5, 0), Vec3(0.5, 0.25, 1.01 * R)});

    const Polygon polygon({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, kernel);
    const std::optional<SupportBox> polygon_box = support_box(Primitive(polygon));
    ASSERT_TRUE(polygon_box.has_value());
    EXPECT_TRUE(polygon_box->contains(Vec3(0.2, 0.2, 0.99 * R)));
    EXPECT_TRUE(polygon_box->contains(Vec3(-0.99 * R, 0, 0)));
    expect_zero_outside(polygon, *polygon_box, {Vec3(0.2, 0.2, 1.01 * R), Vec3(-1.01 * R, 0, 0), Vec3(0, 1 + 1.01 * R, 0)});
  }
  const Segment gaussian(Vec3(0, 0, 0), Vec3(1, 0, 0), KernelSpec::gaussian(2.0, 1.0));
  EXPECT_FALSE(support_box(Primitive(gaussian)).has_value());
}

// The box's corners lie up to √3 ρ from the skeleton: the ball about the
// centroid cuts them off, and wherever the primitive is not exactly 0 the
// ball holds the point (random points over the box, on a compact SCALIS
// triangle, segment and point, the medial path's primitives).
TEST(SupportBox, BallCutsOffTheBoxCornersNeverTheSupport) {
  const ScalisKernel kernel = ScalisKernel::compact(4, 1.5);
  const double tau = 0.2, rho = 1.5 * tau;  // ρ = σ τ
  const ScalisTriangle triangle({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, {tau, tau, tau}, kernel);
  const ScalisSegment segment(Vec3(0, 0, 0), Vec3(1, 0.5, 0), tau, 0.5 * tau, kernel);
  const PointPrimitive point(Vec3(0.5, 0.5, 0.5), KernelSpec::compact(4, rho), 0.7);
  const std::optional<SupportBox> triangle_box = support_box(Primitive(triangle));
  ASSERT_TRUE(triangle_box.has_value());
  // A corner of the box, 1.1 from the triangle's hypotenuse: f = 0 there,
  // and the ball leaves it out (the box alone holds it).
  const Vec3 corner(1 + 0.99 * rho, 1 + 0.99 * rho, 0.99 * rho);
  EXPECT_TRUE(corner.x() <= triangle_box->hi.x() && corner.y() <= triangle_box->hi.y() &&
              corner.z() <= triangle_box->hi.z());
  expect_zero_outside(triangle, *triangle_box, {corner});
  // Points 0.99 ρ beyond a vertex, an edge and the face are inside.
  EXPECT_TRUE(triangle_box->contains(Vec3(1 + 0.99 * rho, 0, 0)));
  EXPECT_TRUE(triangle_box->contains(Vec3(0.5, 0.5, 0) + 0.99 * rho * Vec3(1, 1, 0).normalized()));
  EXPECT_TRUE(triangle_box->contains(Vec3(0.2, 0.2, 0.99 * rho)));
  const auto check = [](const auto& primitive) {
    const std::optional<SupportBox> box = support_box(Primitive(primitive));
    ASSERT_TRUE(box.has_value());
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int cut = 0, nonzero = 0;
    for (int n = 0; n < 4000; ++n) {
      const Vec3 p = box->lo + (box->hi - box->lo).cwiseProduct(Vec3(u(rng), u(rng), u(rng)));
      const FieldSample f = primitive.value_and_gradient(p);
      const bool vanishes = f.value == 0.0 && f.gradient == Vec3::Zero();
      if (!vanishes) {
        ++nonzero;
        EXPECT_TRUE(box->contains(p)) << p.transpose();
      }
      cut += !box->contains(p);
    }
    EXPECT_GT(nonzero, 100);
    EXPECT_GT(cut, 100);  // the corners the ball cuts off
  };
  check(triangle);
  check(segment);
  check(point);
}

TEST(SkeletonBatch, SameBytesWhateverTheThreadCount) {
  const Skeleton skeleton = mixed_skeleton(60);
  const std::vector<Vec3> points = probe_points(skeleton, 700);
  BatchOptions options;
  options.block_size = 16;  // many blocks, so that threads interleave
  options.threads = 1;
  const BatchResult serial = evaluate_batch(skeleton, points, options);
  ASSERT_FALSE(serial.failure);
  for (std::size_t k = 0; k < points.size(); ++k) {
    ASSERT_TRUE(same_bits(serial.samples[k], skeleton.value_and_gradient(points[k])));
  }
  for (unsigned threads : {2u, 3u, 8u}) {
    options.threads = threads;
    const BatchResult parallel = evaluate_batch(skeleton, points, options);
    ASSERT_FALSE(parallel.failure);
    ASSERT_EQ(std::memcmp(parallel.samples.data(), serial.samples.data(),
                          serial.samples.size() * sizeof(FieldSample)),
              0)
        << threads << " threads";
  }
}

// BatchOptions::progress: with no interval every block but the last is
// reported, with the points evaluated so far (one thread: in order), and the
// samples are those of a batch without it; from several threads the counts
// grow and stay below the total.
TEST(SkeletonBatch, ReportsProgressBetweenBlocks) {
  const Skeleton skeleton = mixed_skeleton(20);
  const std::vector<Vec3> points = probe_points(skeleton, 100);
  BatchOptions options;
  options.threads = 1;
  options.block_size = 16;
  const BatchResult quiet = evaluate_batch(skeleton, points, options);
  std::vector<std::size_t> reported;
  options.progress = [&](std::size_t evaluated) { reported.push_back(evaluated); };
  options.progress_interval = 0.0;
  const BatchResult reporting = evaluate_batch(skeleton, points, options);
  std::vector<std::size_t> every_block;
  for (std::size_t end = 16; end < points.size(); end += 16) every_block.push_back(end);
  EXPECT_EQ(reported, every_block);
  ASSERT_FALSE(reporting.failure);
  ASSERT_EQ(std::memcmp(reporting.samples.data(), quiet.samples.data(), quiet.samples.size() * sizeof(FieldSample)),
            0);
  reported.clear();
  options.threads = 3;
  evaluate_batch(skeleton, points, options);
  EXPECT_FALSE(reported.empty());
  EXPECT_TRUE(std::is_sorted(reported.begin(), reported.end()));
  for (std::size_t evaluated : reported) EXPECT_LT(evaluated, points.size());
}

TEST(SkeletonBatch, ReportsTheLowestFailingPoint) {
  const Skeleton skeleton = mixed_skeleton(20);
  std::vector<Vec3> points(1000, Vec3(1, 1, 1));
  points[613] = Vec3(std::nan(""), 0, 0);
  points[37] = Vec3(0, std::numeric_limits<double>::infinity(), 0);
  points[38] = Vec3(std::nan(""), 0, 0);
  for (unsigned threads : {1u, 2u, 5u}) {
    BatchOptions options;
    options.threads = threads;
    options.block_size = 8;
    const BatchResult result = evaluate_batch(skeleton, points, options);
    ASSERT_TRUE(result.failure);
    EXPECT_EQ(result.failure->index, 37u) << threads << " threads";
    EXPECT_THROW(std::rethrow_exception(result.failure->error), InputError);
    // One sample per point whatever failed, and those before the failure
    // are the points' own (one thread constructs them in order).
    ASSERT_EQ(result.samples.size(), points.size()) << threads << " threads";
    for (std::size_t k = 0; k < result.failure->index; ++k) {
      ASSERT_TRUE(same_bits(result.samples[k], skeleton.value_and_gradient(points[k]))) << k;
    }
  }
}

}  // namespace
}  // namespace skelconv
