// Unit tests of the reconstruction steps added for the accuracy targets and
// the junctions (docs/reconstruction.md): Bézier triangles, their placement,
// the periodic B-spline, parallel-path removal, cap trimming and the fit of
// radii and ends to a known surface. Expected values are derived by hand in
// the comments.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "skelconv/reconstruct/bezier_triangle.hpp"
#include "skelconv/reconstruct/bspline.hpp"
#include "skelconv/reconstruct/reconstruct.hpp"
#include "skelconv/reconstruct/surface_fit.hpp"
#include "skelconv/skeleton/skeleton_file.hpp"

namespace skelconv::reconstruct {
namespace {

BezierNet arbitrary_net() {
  BezierNet net;
  for (int k = 0; k < 10; ++k) net[k] = Vec4(k, k * k, 1.0 / (k + 1), 0.1 * k);
  return net;
}

// r = 1 kills every term but r³P0 (every other weight has a factor s or t).
TEST(BezierTriangle, CornersAreThePrimaryPoints) {
  const BezierNet net = arbitrary_net();
  EXPECT_EQ(bezier_triangle_point(net, 1, 0, 0), net[0]);
  EXPECT_EQ(bezier_triangle_point(net, 0, 1, 0), net[1]);
  EXPECT_EQ(bezier_triangle_point(net, 0, 0, 1), net[2]);
}

// The linear net P_ijk = (iA + jB + kC)/3 (P3 ↔ r²s ↔ (2A + B)/3, …,
// P9 ↔ rst ↔ (A + B + C)/3) gives the flat triangle rA + sB + tC: the
// Bernstein polynomials reproduce linear functions.
TEST(BezierTriangle, LinearNetIsTheFlatTriangle) {
  const Vec4 a(0, 0, 0, 1), b(3, 0, 0, 2), c(0, 6, 3, 4);
  const BezierNet net = {a, b, c, (2 * a + b) / 3, (a + 2 * b) / 3, (2 * b + c) / 3, (b + 2 * c) / 3,
                         (a + 2 * c) / 3, (2 * a + c) / 3, (a + b + c) / 3};
  for (const auto& [r, s, t] : {std::array{0.2, 0.3, 0.5}, std::array{0.6, 0.4, 0.0}, std::array{1.0 / 3, 1.0 / 3, 1.0 / 3}}) {
    const Vec4 expected = r * a + s * b + t * c;
    EXPECT_LT((bezier_triangle_point(net, r, s, t) - expected).norm(), 1e-14) << r << " " << s << " " << t;
  }
}

// At the centre r = s = t = 1/3 the weights are 1/27 (primary), 3/27
// (secondary) and 6/27 (central): with P9 = 27 and the rest 0, P = 6.
TEST(BezierTriangle, CentralWeightIsSixRst) {
  BezierNet net;
  net.fill(Vec4::Zero());
  net[9] = Vec4(27, 0, 0, 0);
  EXPECT_DOUBLE_EQ(bezier_triangle_point(net, 1.0 / 3, 1.0 / 3, 1.0 / 3).x(), 6.0);
  net.fill(Vec4::Zero());
  net[3] = Vec4(27, 0, 0, 0);  // 3r²s at (1/3, 1/3, 1/3) = 1/9
  EXPECT_DOUBLE_EQ(bezier_triangle_point(net, 1.0 / 3, 1.0 / 3, 1.0 / 3).x(), 3.0);
}

// The junction net: P9 at the centre, both secondaries of a corner at 1/3
// of the way to it; tessellating the linear net at n = 2 gives 4 facets
// whose areas add up to the flat triangle's.
TEST(BezierTriangle, JunctionNetAndTessellation) {
  const Vec4 centre(0, 0, 0, 0.5), c0(3, 0, 0, 0.2), c1(0, 3, 0, 0.2), c2(0, 0, 3, 0.2);
  const BezierNet net = junction_net(centre, c0, c1, c2);
  EXPECT_EQ(net[9], centre);
  EXPECT_EQ(net[3], Vec4(2, 0, 0, 0.3));
  EXPECT_EQ(net[8], Vec4(2, 0, 0, 0.3));
  EXPECT_EQ(net[4], Vec4(0, 2, 0, 0.3));
  EXPECT_EQ(net[7], Vec4(0, 0, 2, 0.3));
  const Vec4 a(0, 0, 0, 1), b(2, 0, 0, 1), c(0, 2, 0, 1);
  const BezierNet flat = {a, b, c, (2 * a + b) / 3, (a + 2 * b) / 3, (2 * b + c) / 3, (b + 2 * c) / 3,
                          (a + 2 * c) / 3, (2 * a + c) / 3, (a + b + c) / 3};
  const std::vector<Facet> facets = tessellate(flat, 2);
  ASSERT_EQ(facets.size(), 4u);
  double area = 0.0;
  for (const Facet& f : facets) area += (f[1] - f[0]).head<3>().cross((f[2] - f[0]).head<3>()).norm() / 2;
  EXPECT_NEAR(area, 2.0, 1e-14);  // the triangle (0,0), (2,0), (0,2)
}

// A Y of three straight arms, points every 0.25 out to 2, junction radius
// 0.5: with k = 1.4 the corners are the first points at distance ≥ 0.7,
// the points at 0.75; with cuts the arms then start there.
TEST(BezierTriangle, PlacementOnAY) {
  std::vector<Branch> arms;
  for (int a = 0; a < 3; ++a) {
    const double angle = 2 * std::numbers::pi * a / 3;
    Branch b;
    b.first_node = 0, b.last_node = a + 1;
    for (int k = 0; k <= 8; ++k) b.points.push_back(Vec4(0.25 * k * std::cos(angle), 0.25 * k * std::sin(angle), 0, 0.5));
    arms.push_back(b);
  }
  std::vector<Branch> kept = arms;
  EXPECT_EQ(place_junction_triangles(kept, 1.4, 2, false).size(), 4u);
  EXPECT_EQ(kept[0].points.size(), 9u);  // fillet: the arms are untouched
  const std::vector<Facet> facets = place_junction_triangles(arms, 1.4, 2, true);
  ASSERT_EQ(facets.size(), 4u);
  for (const Branch& b : arms) {
    ASSERT_EQ(b.points.size(), 6u);
    EXPECT_NEAR(b.points.front().head<3>().norm(), 0.75, 1e-15);
  }
  // Facet 0 starts at domain point (0, 0) = corner P0 = arm 0's corner.
  EXPECT_LT((facets[0][0] - Vec4(0.75, 0, 0, 0.5)).norm(), 1e-15);
}

// The periodic B-spline of the unit square starts at (V3 + 4V0 + V1)/6 =
// (1/6, 1/6) and is closed; span 1 (V0…V3) at u = 1/2 has the weights 1/48,
// 23/48, 23/48, 1/48: x = 46/48, y = 24/48. No kink where the cycle was
// cut: the square's symmetry about x = y maps the points just after the
// seam onto those just before it.
TEST(BSpline, ClosedSquare) {
  const std::vector<Vec4> square = {Vec4(0, 0, 0, 1), Vec4(1, 0, 0, 1), Vec4(1, 1, 0, 1), Vec4(0, 1, 0, 1),
                                    Vec4(0, 0, 0, 1)};
  const std::vector<Vec4> curve = smooth_closed_bspline(square, 4);
  ASSERT_EQ(curve.size(), 17u);  // 4 spans × 4 + the closing point
  EXPECT_LT((curve.front() - Vec4(1.0 / 6, 1.0 / 6, 0, 1)).norm(), 1e-15);
  EXPECT_EQ(curve.front(), curve.back());
  EXPECT_LT((curve[6] - Vec4(46.0 / 48, 24.0 / 48, 0, 1)).norm(), 1e-15);
  EXPECT_NEAR(curve[1].x(), curve[15].y(), 1e-15);
  EXPECT_NEAR(curve[1].y(), curve[15].x(), 1e-15);
}

/// A curve skeleton in the plane z = 0: nodes at `xy`, all of radius
/// `radius`, joined by `edges` (indices into `xy`).
CurveSkeleton planar_skeleton(const std::vector<std::pair<double, double>>& xy, double radius,
                              std::vector<std::pair<std::int32_t, std::int32_t>> edges) {
  CurveSkeleton s;
  for (const auto& [x, y] : xy) s.nodes.push_back(Vec4(x, y, 0, radius));
  s.edges = std::move(edges);
  return s;
}

// Two junctions J1 = (0,0,0), J2 = (1,0,0) joined by a direct edge and by a
// path through (0.5, 0.1, 0): the cycle's centroid (0.5, 0.02, 0) is inside
// the balls (radius 0.5), so the path through the extra node goes. With
// the middle node at (0.5, 1, 0) and radius 0.1 the cycle encloses a hole
// (its centroid (0.5, 0.2, 0) is 0.2 or more from every point) and stays.
TEST(Branches, ParallelPathsWithoutHoleAreRemoved) {
  const auto make = [](double middle_y, double radius) {
    return planar_skeleton({{0.0, 0.0}, {1.0, 0.0}, {0.5, middle_y}, {-2.0, 0.0}, {0.0, -2.0}, {3.0, 0.0}, {1.0, -2.0}},
                           radius, {{0, 1}, {0, 2}, {1, 2}, {0, 3}, {0, 4}, {1, 5}, {1, 6}});
  };
  CurveSkeleton bubble = make(0.1, 0.5);
  EXPECT_EQ(remove_spurs(bubble, 0.0), 1u);  // factor 0: no contraction, no spur
  const BranchGraph g = extract_branches(bubble);
  EXPECT_EQ(g.branches.size(), 5u);
  EXPECT_EQ(g.ends, 4u);
  EXPECT_EQ(g.junctions, 2u);
  CurveSkeleton handle = make(1.0, 0.1);
  EXPECT_EQ(remove_spurs(handle, 0.0), 0u);
  EXPECT_EQ(extract_branches(handle).branches.size(), 6u);
}

// A branch split in two paths that meet only at its tip: a loop at junction
// J = (0,0,0) through (1, 0.1), tip (2, 0), (1, -0.1) (two other branches
// leave J towards (-2, 0) and (0, -2)). Radius 0.5: each half runs inside
// the other's tube, so one half goes and the tip (2, 0) becomes an end,
// as the tree's outermost branches need (experiment_ferley1996_tree). With radius 0.1
// and the halves 1 apart (through (1, ±1): a ring on a stick) the loop
// encloses a hole and stays.
TEST(Branches, BranchSplitIntoALoopBecomesOneBranch) {
  const auto make = [](double half_width, double radius) {
    return planar_skeleton({{0.0, 0.0}, {1.0, half_width}, {2.0, 0.0}, {1.0, -half_width}, {-2.0, 0.0}, {0.0, -2.0}},
                           radius, {{0, 1}, {1, 2}, {2, 3}, {0, 3}, {0, 4}, {0, 5}});
  };
  CurveSkeleton split = make(0.1, 0.5);
  EXPECT_EQ(remove_spurs(split, 0.0), 1u);  // factor 0: no contraction, no spur
  const BranchGraph g = extract_branches(split);
  EXPECT_EQ(g.branches.size(), 3u);
  EXPECT_EQ(g.ends, 3u);
  EXPECT_EQ(g.junctions, 1u);
  EXPECT_TRUE(std::find(split.nodes.begin(), split.nodes.end(), Vec4(2, 0, 0, 0.5)) != split.nodes.end());
  CurveSkeleton ring = make(1.0, 0.1);
  EXPECT_EQ(remove_spurs(ring, 0.0), 0u);
  EXPECT_EQ(extract_branches(ring).branches.size(), 3u);  // the loop and the two others
  EXPECT_EQ(extract_branches(ring).ends, 2u);
}

// Radii falling faster than 0.5 per unit length at a free end are cap
// balls: 0.5 → 0.3 over 0.2 (slope 1) and 0.3 → 0.1 over 0.1 (2) go at the
// back; 0.45 → 0.1 over 0.5 (0.7) goes at the front, 0.5 → 0.45 over 0.5
// (0.1) stays.
TEST(Ends, CapTrimming) {
  Branch b;
  b.first_node = 0, b.last_node = 1;
  for (const auto& [x, r] : {std::pair{0.0, 0.1}, {0.5, 0.45}, {1.0, 0.5}, {2.0, 0.5}, {3.0, 0.5}, {3.2, 0.3}, {3.3, 0.1}})
    b.points.push_back(Vec4(x, 0, 0, r));
  const std::vector<Branch> trimmed = trim_caps({b}, 0.5);
  ASSERT_EQ(trimmed[0].points.size(), 4u);
  EXPECT_EQ(trimmed[0].points.front().x(), 0.5);
  EXPECT_EQ(trimmed[0].points.back().x(), 3.0);
}

// A hook at a free end (the noisy tripod's arm, in small): the branch runs
// along x to (2, 0, 0), then steps to (2.3, 0.4, 0) (ahead: kept) and back
// to (2.1, 0.1, 0) (against the step before it: dropped); at the front,
// (0.5, 0, 0) → (0, 0, 0) → (0.2, 0.3, 0) turns back too: dropped. Radii
// constant, so the slope rule alone would keep every point.
TEST(Ends, HookTrimming) {
  Branch b;
  b.first_node = 0, b.last_node = 1;
  for (const Vec3& p : {Vec3(0.2, 0.3, 0), Vec3(0, 0, 0), Vec3(0.5, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0),
                        Vec3(2.3, 0.4, 0), Vec3(2.1, 0.1, 0)})
    b.points.push_back(Vec4(p.x(), p.y(), p.z(), 0.4));
  const std::vector<Branch> trimmed = trim_caps({b}, 0.5);
  ASSERT_EQ(trimmed[0].points.size(), 5u);
  EXPECT_EQ(trimmed[0].points.front().head<3>(), Vec3(0, 0, 0));
  EXPECT_EQ(trimmed[0].points.back().head<3>(), Vec3(2.3, 0.4, 0));
}

/// A closed cylinder of radius 0.5 (64-gon, inradius 0.5 cos(π/64)) from
/// x = −2 to 2, with fan caps.
TriangleMesh cylinder() {
  constexpr int sides = 64;
  TriangleMesh m;
  for (int end = 0; end < 2; ++end) {
    for (int k = 0; k < sides; ++k) {
      const double a = 2 * std::numbers::pi * k / sides;
      m.vertices.push_back(Vec3(end == 0 ? -2 : 2, 0.5 * std::cos(a), 0.5 * std::sin(a)));
    }
  }
  m.vertices.push_back(Vec3(-2, 0, 0));
  m.vertices.push_back(Vec3(2, 0, 0));
  const int c0 = 2 * sides, c1 = c0 + 1;
  for (int k = 0; k < sides; ++k) {
    const int n = (k + 1) % sides;
    m.triangles.push_back({k, n, sides + n});
    m.triangles.push_back({k, sides + n, sides + k});
    m.triangles.push_back({c0, n, k});
    m.triangles.push_back({c1, sides + k, sides + n});
  }
  return m;
}

// Two points of a branch a rounding apart (1 and the next double, 2.2e-16:
// the curve path's fit of an open box closed by --repair left such a pair)
// make a piece that skeleton files refuse (shorter than 1e-8 of its
// coordinates): it is left out of the written skeleton, which reads back
// with the segment from the second point to (2, 0, 0) and the two end
// extensions (extend_free_ends): 3 segments, not 4.
TEST(SkeletonFile, APieceARoundingLongIsLeftOut) {
  Branch b;
  b.first_node = 0, b.last_node = 1;
  b.points = {Vec4(1, 0, 0, 0.3), Vec4(std::nextafter(1.0, 2.0), 0, 0, 0.3), Vec4(2, 0, 0, 0.3)};
  Stage s;
  s.branches = {b};
  const ReconstructOptions o;
  EXPECT_EQ(primitive_counts(s, o).segments, 3u);
  const Skeleton skeleton = parse_skeleton_json(skeleton_file_text(s, o));
  EXPECT_GT(skeleton.value(Vec3(1.5, 0, 0)), 0.0);
}

// A branch on the cylinder's axis from −1.5 to 1.5 at radius 0.3 (far too
// thin): after the fit, the reconstructed surface is at the cylinder's
// radius 0.5 in the middle and reaches the caps at x = ±2 on the axis.
TEST(Fit, RadiiAndEndsOnACylinder) {
  Branch b;
  b.first_node = 0, b.last_node = 1;
  for (int k = 0; k <= 12; ++k) b.points.push_back(Vec4(-1.5 + 0.25 * k, 0, 0, 0.3));
  const ReconstructOptions o;
  const BranchField field_of = [&o](const std::vector<Branch>& branches) {
    Stage s;
    s.branches = branches;
    return parse_skeleton_json(skeleton_file_text(s, o));
  };
  const SurfaceQuery input(cylinder());
  FitOptions fit;
  FitReport report;
  const std::vector<Branch> fitted = fit_to_surface(extend_free_ends({b}, 1.0), input, field_of, fit, &report);
  const Skeleton skeleton = field_of(fitted);
  const auto f = [&](const Vec3& p) { return skeleton.value(p); };
  // The surface crosses y = 0.5 + 3% between 0.49 and 0.515 (measured:
  // 0.510 after the 4 default rounds; a convolution surface cannot make
  // the flat cap's corner, which pulls the middle a little), and the axis
  // within ±0.01 of the caps (measured: 1.9997).
  EXPECT_GT(f(Vec3(0, 0.49, 0)), 1.0);
  EXPECT_LT(f(Vec3(0, 0.515, 0)), 1.0);
  for (double side : {-1.0, 1.0}) {
    EXPECT_GT(f(Vec3(side * 1.99, 0, 0)), 1.0);
    EXPECT_LT(f(Vec3(side * 2.01, 0, 0)), 1.0);
  }
  EXPECT_LT(report.largest_tip_change, 0.01);
}

// The same branch 0.08 off the axis (y = 0.064, z = −0.048) at radius 0.4:
// the fit moves the tube sections onto the axis (the first harmonic of the
// ray distances; a circle seen from c* + e is R − e·u along u). 0.08 keeps
// the sections tube-like (ray distances 0.42 to 0.58, within the ratio
// 1.5). The middle point ends within 0.01 of the axis, and the surface is
// on all four sides within 3% of the radius.
TEST(Fit, CentresMoveOntoTheAxis) {
  Branch b;
  b.first_node = 0, b.last_node = 1;
  for (int k = 0; k <= 12; ++k) b.points.push_back(Vec4(-1.5 + 0.25 * k, 0.064, -0.048, 0.4));
  const ReconstructOptions o;
  const BranchField field_of = [&o](const std::vector<Branch>& branches) {
    Stage s;
    s.branches = branches;
    return parse_skeleton_json(skeleton_file_text(s, o));
  };
  const std::vector<Branch> fitted =
      fit_to_surface(extend_free_ends({b}, 1.0), SurfaceQuery(cylinder()), field_of, FitOptions{});
  const Vec4& middle = fitted[0].points[7];  // x = 0 (index 6 + the extension point)
  EXPECT_NEAR(middle.x(), 0.0, 1e-3);  // rays are normal to the branch: (almost) no move along it
  EXPECT_LT(middle.head<3>().tail<2>().norm(), 0.01) << middle.transpose();
  const Skeleton skeleton = field_of(fitted);
  for (const Vec3& u : {Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)}) {
    EXPECT_GT(skeleton.value(0.485 * u), 1.0) << u.transpose();
    EXPECT_LT(skeleton.value(0.515 * u), 1.0) << u.transpose();
  }
}

}  // namespace
}  // namespace skelconv::reconstruct
