// Soundness sweep of the enclosures (include/skelconv/interval/enclosure.hpp):
// random skeletons of every primitive type and kernel family, and every
// blend, random boxes from 1e-4 to a few units across, random points in
// each box (and its corners): no field value may fall outside the box's
// enclosure. Also prints the median width ratio (enclosure width ÷ the
// range of the sampled values) per primitive type, the tightness figure of
// docs/bound.md.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "skelconv/interval/enclosure.hpp"

namespace skelconv::interval {
namespace {

/// Points per family: 250 × 400 = 10⁵, the count docs/bound.md reports.
constexpr int boxes_per_family = 250;
constexpr int points_per_box = 400;

/// The enclosures hold the EXACT field; the values compared with them are
/// computed in double, with the runtime's own rounding error. A sample may
/// exceed the enclosure by that error and no more: a few ulps for points
/// and blends of points (closed forms of 10–20 operations), the verified
/// accuracy of the generated kernels for segments, polygons and SCALIS
/// segments (1e-13 relative, docs/verify.md), and the certified tolerance of
/// the SCALIS triangle quadrature (ScalisTriangle::certified_tolerance).
constexpr double point_evaluation_error = 1e-15;
constexpr double generated_evaluation_error = 1e-13;

using Rng = std::mt19937_64;

double uniform(Rng& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
Vec3 random_point(Rng& rng, double spread) {
  return Vec3(uniform(rng, -spread, spread), uniform(rng, -spread, spread), uniform(rng, -spread, spread));
}

/// A box of size 10^[−4, 0.6] around a point near the skeleton.
Box random_box(Rng& rng) {
  const Vec3 centre = random_point(rng, 2.0);
  const double size = std::pow(10.0, uniform(rng, -4.0, 0.6));
  Vec3 half(uniform(rng, 0.2, 1.0), uniform(rng, 0.2, 1.0), uniform(rng, 0.2, 1.0));
  half *= size / 2;
  return {centre - half, centre + half};
}

/// Every sample inside `box` within [lo, hi]; returns the width ratio, or
/// NaN when the sampled range is 0 or infinite.
double check_box(const std::function<double(const Vec3&)>& f, const Interval& enclosure, const Box& box, Rng& rng,
                 const std::string& what, double evaluation_error) {
  double lo = INFINITY, hi = -INFINITY;
  for (int k = 0; k < points_per_box; ++k) {
    Vec3 p;
    for (int i = 0; i < 3; ++i) p[i] = k < 8 ? ((k >> i) & 1 ? box.hi[i] : box.lo[i]) : uniform(rng, box.lo[i], box.hi[i]);
    const double value = f(p);
    lo = std::min(lo, value);
    hi = std::max(hi, value);
    const double slack = std::isfinite(value) ? evaluation_error * std::abs(value) : 0.0;
    if (!(value >= enclosure.lower() - slack && value <= enclosure.upper() + slack)) {
      ADD_FAILURE() << what << ": f = " << value << " outside [" << enclosure.lower() << ", " << enclosure.upper()
                    << "] at (" << p.transpose() << ")";
      return NAN;
    }
  }
  const double range = hi - lo;
  if (!(range > 0.0) || !std::isfinite(range) || !std::isfinite(enclosure.upper() - enclosure.lower())) return NAN;
  return (enclosure.upper() - enclosure.lower()) / range;
}

double median(std::vector<double> v) {
  std::erase_if(v, [](double x) { return std::isnan(x); });
  if (v.empty()) return NAN;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

/// Runs the sweep for skeletons made by `make` (a new one every 25 boxes).
void sweep(const std::string& name, const std::function<Skeleton(Rng&)>& make, std::uint64_t seed,
           double evaluation_error) {
  Rng rng(seed);
  std::vector<double> ratios;
  Skeleton skeleton;
  for (int b = 0; b < boxes_per_family; ++b) {
    if (b % 10 == 0) skeleton = make(rng);
    const Box box = random_box(rng);
    const Interval enclosure = enclose(skeleton, box);
    ratios.push_back(check_box([&](const Vec3& p) { return skeleton.value(p); }, enclosure, box, rng, name, evaluation_error));
  }
  std::printf("[ ratio    ] %-28s median enclosure width / sampled range = %.3g\n", name.c_str(), median(ratios));
}

KernelSpec random_classical(Rng& rng, bool point) {
  switch (std::uniform_int_distribution<int>(0, 2)(rng)) {
    case 0: return KernelSpec::inverse(point ? 3 : std::uniform_int_distribution<int>(3, 6)(rng));
    case 1: return KernelSpec::cauchy(std::uniform_int_distribution<int>(3, 8)(rng), uniform(rng, 0.5, 4.0));
    default: return KernelSpec::compact(2 * std::uniform_int_distribution<int>(2, 4)(rng), uniform(rng, 0.5, 2.5));
  }
}

TEST(IntervalSoundness, Points) {
  const std::vector<std::function<KernelSpec(Rng&)>> families{
      [](Rng& r) { return random_classical(r, true); },
      [](Rng& r) { return KernelSpec::soft(uniform(r, 0.5, 3)); },
      [](Rng& r) { return KernelSpec::wyvill(uniform(r, 0.5, 3)); },
      [](Rng& r) { const double e = uniform(r, 0.1, 1); return KernelSpec::ferley(e, e + uniform(r, 0.2, 2)); },
      [](Rng& r) { return KernelSpec::gaussian(uniform(r, 0.3, 4), uniform(r, 0.5, 2)); }};
  const char* names[] = {"point (inverse/cauchy/compact)", "point soft", "point wyvill", "point ferley", "point gaussian"};
  for (std::size_t f = 0; f < families.size(); ++f) {
    sweep(names[f], [&](Rng& rng) {
      std::vector<Primitive> p;
      for (int k = 0; k < 3; ++k) p.emplace_back(PointPrimitive(random_point(rng, 1.5), families[f](rng), uniform(rng, 0.5, 2)));
      return Skeleton(std::move(p));
    }, 100 + f, point_evaluation_error);
  }
}

/// ∇f of point primitives within enclose_gradient, every family: 10⁵
/// points per family, gradients compared with a few ulps' allowance.
TEST(IntervalSoundness, PointGradients) {
  Rng rng(700);
  for (const KernelSpec& spec : {KernelSpec::inverse(3), KernelSpec::cauchy(4, 2.0), KernelSpec::compact(2, 1.2),
                                 KernelSpec::compact(6, 1.7), KernelSpec::soft(1.5), KernelSpec::wyvill(2.0),
                                 KernelSpec::ferley(0.5, 1.6), KernelSpec::gaussian(1.3, 2.0)}) {
    int bounded = 0;
    for (int b = 0; b < boxes_per_family; ++b) {
      const PointPrimitive point(random_point(rng, 0.5), spec, uniform(rng, -2, 2));
      const Box box = random_box(rng);
      const IntervalPoint g = *enclose_gradient(Primitive(point), box);
      bounded += std::isfinite(g[0].upper() - g[0].lower());
      for (int k = 0; k < points_per_box; ++k) {
        Vec3 p;
        for (int i = 0; i < 3; ++i) p[i] = uniform(rng, box.lo[i], box.hi[i]);
        const Vec3 gradient = point.gradient(p);
        for (int i = 0; i < 3; ++i) {
          const double slack = point_evaluation_error * std::abs(gradient[i]);
          ASSERT_TRUE(gradient[i] >= g[i].lower() - slack && gradient[i] <= g[i].upper() + slack)
              << family_name(spec.family) << " axis " << i << ": " << gradient[i] << " outside [" << g[i].lower()
              << ", " << g[i].upper() << "]";
        }
      }
    }
    EXPECT_GT(bounded, boxes_per_family / 2) << family_name(spec.family);  // most boxes miss the centre
  }
  EXPECT_FALSE(enclose_gradient(Primitive(Segment(Vec3::Zero(), Vec3::UnitX(), KernelSpec::inverse(3))),
                                Box{Vec3::Zero(), Vec3::Ones()}));
}

TEST(IntervalSoundness, Segments) {
  sweep("segment", [](Rng& rng) {
    std::vector<Primitive> p;
    for (int k = 0; k < 2; ++k) {
      const Vec3 a = random_point(rng, 1.5);
      const std::vector<double> w{uniform(rng, 0.2, 2), uniform(rng, -0.5, 0.5)};
      p.emplace_back(Segment(a, a + random_point(rng, 1.5), random_classical(rng, false), w));
    }
    return Skeleton(std::move(p));
  }, 200, generated_evaluation_error);
}

/// A star-shaped (possibly non-convex) polygon in an axis plane (exactly
/// planar: its vertices share one coordinate).
Polygon random_polygon(Rng& rng) {
  const int n = std::uniform_int_distribution<int>(3, 7)(rng);
  const int axis = std::uniform_int_distribution<int>(0, 2)(rng);
  const Vec3 centre = random_point(rng, 1.0);
  std::vector<Vec3> vertices;
  for (int k = 0; k < n; ++k) {
    const double angle = 2 * M_PI * (k + uniform(rng, 0.1, 0.9)) / n, radius = uniform(rng, 0.3, 1.5);
    Vec3 v = centre;
    v[(axis + 1) % 3] += radius * std::cos(angle);
    v[(axis + 2) % 3] += radius * std::sin(angle);
    vertices.push_back(v);
  }
  KernelSpec kernel = random_classical(rng, false);
  if (kernel.family != KernelFamily::compact) kernel.degree = std::max(kernel.degree, 4);
  return Polygon(vertices, kernel);
}

TEST(IntervalSoundness, Polygons) {
  sweep("polygon", [](Rng& rng) { return Skeleton({Primitive(random_polygon(rng))}); }, 300,
        generated_evaluation_error);
}

/// The soft-object families where they have a segment (and, for soft and
/// Wyvill, a polygon) field.
KernelSpec random_soft_family(Rng& rng, bool polygon) {
  switch (std::uniform_int_distribution<int>(0, polygon ? 1 : 2)(rng)) {
    case 0: return KernelSpec::soft(uniform(rng, 0.5, 2.5));
    case 1: return KernelSpec::wyvill(uniform(rng, 0.5, 2.5));
    default: return KernelSpec::gaussian(uniform(rng, 0.3, 30), uniform(rng, 0.5, 2));
  }
}

TEST(IntervalSoundness, SoftFamiliesOnSegmentsAndPolygons) {
  sweep("segment soft/wyvill/gaussian", [](Rng& rng) {
    const Vec3 a = random_point(rng, 1.5);
    const std::vector<double> w{uniform(rng, 0.2, 2), uniform(rng, -0.5, 0.5)};
    return Skeleton({Primitive(Segment(a, a + random_point(rng, 1.5), random_soft_family(rng, false), w))});
  }, 210, generated_evaluation_error);
  sweep("polygon soft/wyvill", [](Rng& rng) {
    const Polygon shape = random_polygon(rng);
    return Skeleton({Primitive(Polygon(shape.vertices(), random_soft_family(rng, true)))});
  }, 310, generated_evaluation_error);
}

ScalisKernel random_scalis(Rng& rng) {
  switch (std::uniform_int_distribution<int>(0, 2)(rng)) {
    case 0: return ScalisKernel::inverse(std::uniform_int_distribution<int>(3, 6)(rng), uniform(rng, 0.5, 2));
    case 1: return ScalisKernel::cauchy(std::uniform_int_distribution<int>(3, 6)(rng), uniform(rng, 0.5, 2));
    default: return ScalisKernel::compact(2 * std::uniform_int_distribution<int>(2, 4)(rng), uniform(rng, 1.5, 3));
  }
}

TEST(IntervalSoundness, ScalisSegments) {
  sweep("scalis_segment", [](Rng& rng) {
    const Vec3 a = random_point(rng, 1.5);
    // One segment in four has a tip of radius 0 (1/τ unbounded there).
    const double tau0 = std::uniform_int_distribution<int>(0, 3)(rng) == 0 ? 0.0 : uniform(rng, 0.1, 0.8);
    return Skeleton({Primitive(ScalisSegment(a, a + random_point(rng, 1.5), tau0, uniform(rng, 0.1, 0.8),
                                             random_scalis(rng), 1.0))});
  }, 400, generated_evaluation_error);
}

TEST(IntervalSoundness, ScalisTriangles) {
  sweep("scalis_triangle", [](Rng& rng) {
    const Vec3 a = random_point(rng, 1.0);
    // Equal radii (the closed-form path) most of the time: the varying-radius
    // quadrature costs ~1 ms a point.
    const double tau = uniform(rng, 0.2, 0.8);
    const bool vary = std::uniform_int_distribution<int>(0, 4)(rng) == 0;
    const std::array<double, 3> radii{tau, vary ? tau * 1.3 : tau, vary ? tau * 0.8 : tau};
    ScalisKernel kernel = random_scalis(rng);
    return Skeleton({Primitive(ScalisTriangle({a, a + random_point(rng, 1.0), a + random_point(rng, 1.0)}, radii,
                                              kernel, 1.0))});
  }, 500, ScalisTriangle::certified_tolerance);
}

TEST(IntervalSoundness, Blends) {
  const auto two_points = [](Rng& rng) {
    return std::vector<Primitive>{PointPrimitive(random_point(rng, 1.0), KernelSpec::soft(uniform(rng, 1, 2))),
                                  PointPrimitive(random_point(rng, 1.0), KernelSpec::gaussian(uniform(rng, 0.5, 2), 1))};
  };
  const std::vector<std::pair<const char*, std::function<Blend()>>> blends{
      {"blend sum (weights)", [] { return Blend::sum({0.7, -0.4}); }},
      {"blend union", [] { return Blend::union_max(); }},
      {"blend super_elliptic", [] { return Blend::super_elliptic(2.5, {0.6}, 0.5); }},
      {"blend super_elliptic angle", [] { return Blend::super_elliptic(2.0, {0.5, 0.4}, 0.5, true); }}};
  std::uint64_t seed = 600;
  for (const auto& [name, make_blend] : blends) {
    sweep(name, [&](Rng& rng) {
      Skeleton skeleton;
      const Skeleton::NodeId node = skeleton.add_blend(make_blend());
      for (Primitive& p : two_points(rng)) skeleton.add(std::move(p), node);
      return skeleton;
    }, seed++, point_evaluation_error);
  }
}

}  // namespace
}  // namespace skelconv::interval
