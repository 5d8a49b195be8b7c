// The medial-mesh path (reconstruct/medial_quadric.hpp, medial_fit.hpp,
// docs/reconstruction_medial.md) on complexes built by hand whose answer is
// known without running the code: a sheet between two planes stays between
// them, a tube's spheres stay on its axis, a hole wider than the balls stays
// and one inside them is closed. Then the whole path on a cube (the budget)
// and a plate, where the fit may only lower its RMS distance.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <limits>
#include <numbers>
#include <set>
#include <utility>

#include <gtest/gtest.h>

#include "skelconv/mesh/mesh_reader.hpp"
#include "skelconv/mesh/mesh_topology.hpp"
#include "skelconv/reconstruct/medial_derivatives.hpp"
#include "skelconv/reconstruct/medial_fit.hpp"
#include "skelconv/reconstruct/medial_mesh.hpp"
#include "skelconv/reconstruct/medial_quadric.hpp"
#include "skelconv/reconstruct/medial_slope.hpp"
#include "skelconv/reconstruct/reconstruct.hpp"
#include "skelconv/skeleton/skeleton_file.hpp"
#include "src/reconstruct/fill_cavities.hpp"
#include "src/reconstruct/plug_tunnels.hpp"
#include "src/reconstruct/medial_step.hpp"
#include "src/reconstruct/tube_ends.hpp"
#include "src/reconstruct/unreached_tips.hpp"

namespace skelconv::reconstruct {
namespace {

void add_edge(MedialGraph& g, std::int32_t a, std::int32_t b) { g.edges.push_back(MedialEdge{a, b, {0, 0, 0}}); }

// --- The quadric simplification (medial_quadric.hpp) on complexes built by
// hand, with contact samples whose tangent planes say where the spheres
// must be: a sheet between the planes z = ±r, a tube inside y² + z² = r².

/// An n × n grid sheet of spacing h in z = 0, radius r, each vertex
/// touching the planes z = ±r; its cells are faces, except those with
/// both indices in [hole_from, hole_to) (a square hole: an annulus), whose
/// inner vertices are left out.
MedialGraph quadric_sheet(int n, double h, double r, int hole_from = 0, int hole_to = 0) {
  MedialGraph g;
  const auto in_hole = [&](int i, int j) { return i >= hole_from && i < hole_to && j >= hole_from && j < hole_to; };
  std::vector<std::int32_t> index(std::size_t(n * n), -1);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      // A vertex all four of whose cells are in the hole has no face.
      if (in_hole(i - 1, j - 1) && in_hole(i, j - 1) && in_hole(i - 1, j) && in_hole(i, j)) continue;
      const std::int32_t above = std::int32_t(g.samples.size());
      g.samples.push_back(Vec3(i * h, j * h, r));
      g.samples.push_back(Vec3(i * h, j * h, -r));
      index[std::size_t(i * n + j)] = std::int32_t(g.vertices.size());
      g.vertices.push_back(MedialVertex{Vec3(i * h, j * h, 0), r, {above, above + 1, above, above + 1}});
    }
  const auto at = [&](int i, int j) { return index[std::size_t(i * n + j)]; };
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j)
      if (!in_hole(i, j)) g.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
  return g;
}

/// V − E + T of a medial mesh (E: the triangles' sides and the tube edges).
long long euler_characteristic(const MedialMesh& m) {
  std::set<std::array<std::int32_t, 2>> edges(m.edges.begin(), m.edges.end());
  for (const auto& t : m.triangles) edges.insert({t[0], t[1]}), edges.insert({t[1], t[2]}), edges.insert({t[0], t[2]});
  return (long long)m.spheres.size() - (long long)edges.size() + (long long)m.triangles.size();
}

std::size_t primitives(const MedialMesh& m) { return m.triangles.size() + m.edges.size() + m.isolated.size(); }

TEST(QuadricMedialMesh, SheetStaysBetweenItsPlanesWithinTheBudget) {
  const MedialGraph g = quadric_sheet(21, 0.05, 0.3);
  QuadricOptions o;
  o.budget = 20;
  QuadricReport report;
  const MedialMesh m = quadric_medial_mesh(g, o, &report);
  EXPECT_LE(primitives(m), 20u);
  EXPECT_GE(m.triangles.size(), 10u) << "a sheet stays triangles";
  EXPECT_EQ(report.euler_before, 1);
  EXPECT_EQ(euler_characteristic(m), 1) << "a disc stays a disc";
  // The sphere touching both planes is the only one with zero error: every
  // merged sphere is centred on z = 0 with radius 0.3.
  for (const Vec4& s : m.spheres) {
    EXPECT_NEAR(s.z(), 0.0, 1e-9);
    EXPECT_NEAR(s.w(), 0.3, 1e-9);
  }
}

TEST(QuadricMedialMesh, HoleWiderThanTheBallsIsNeverClosed) {
  // An annulus (χ 0) of radius 0.1 around a 0.3 × 0.3 hole, asked down to
  // one primitive: the link condition stops the collapses while its hole
  // is still there.
  const MedialGraph g = quadric_sheet(21, 0.05, 0.1, 7, 13);
  QuadricOptions o;
  o.budget = 1;
  QuadricReport report;
  const MedialMesh m = quadric_medial_mesh(g, o, &report);
  EXPECT_EQ(report.euler_before, 0);
  EXPECT_EQ(euler_characteristic(m), 0);
  EXPECT_GT(report.refused_by_link, 0u);
  EXPECT_GE(primitives(m), 3u) << "a loop needs at least three edges";
}

TEST(QuadricMedialMesh, HoleInsideTheBallsIsClosed) {
  // One missing cell (0.05 wide) in a sheet of radius 0.3: the balls cover
  // it, the shape has no tunnel there; the simplified sheet is a disc.
  const MedialGraph g = quadric_sheet(21, 0.05, 0.3, 10, 11);
  QuadricOptions o;
  o.budget = 20;
  QuadricReport report;
  const MedialMesh m = quadric_medial_mesh(g, o, &report);
  EXPECT_EQ(report.euler_before, 0);
  EXPECT_EQ(euler_characteristic(m), 1);
  EXPECT_GE(report.loops_closed, 1u);
}

/// The depth (positive inside) of a plate 1 × 1 × 2t, z = 0 its middle,
/// with a square tunnel [a, b]² through it where `tunnel` (else solid).
std::function<double(const Vec3&)> plate_depth(double t, bool tunnel, double a, double b) {
  return [=](const Vec3& p) {
    double d = std::min({t - std::abs(p.z()), p.x() + 0.025, 1.025 - p.x(), p.y() + 0.025, 1.025 - p.y()});
    if (tunnel) d = std::min(d, std::max({a - p.x(), p.x() - b, a - p.y(), p.y() - b}));
    return d;
  };
}

/// The sheet of a thin wall (balls of radius 0.02 round a 0.3 × 0.3 hole)
/// simplified to `budget` against the depth of a plate 0.04 thick, solid
/// across the hole or with a tunnel through it, 4 inside samples per test.
MedialMesh thin_plate_sheet(std::size_t budget, bool tunnel, QuadricReport& report) {
  QuadricOptions o;
  o.budget = budget;
  o.depth = plate_depth(0.02, tunnel, 0.36, 0.64);
  o.inside_samples = 4;
  return quadric_medial_mesh(quadric_sheet(21, 0.05, 0.02, 7, 13), o, &report);
}

TEST(QuadricMedialMesh, HoleWiderThanTheBallsIsClosedWhereTheInputHoldsIt) {
  // The annulus of HoleWiderThanTheBallsIsNeverClosed, of a thin wall (balls
  // of radius 0.02 round a 0.3 × 0.3 hole): a sheet whose Voronoi faces
  // were dropped there. With the input's depth and inside_samples, the
  // loops the hole shrinks to are closed where the plate is solid, never
  // where it has a tunnel.
  for (const bool tunnel : {false, true}) {
    QuadricReport report;
    const MedialMesh m = thin_plate_sheet(1, tunnel, report);
    EXPECT_EQ(euler_characteristic(m), tunnel ? 0 : 1) << (tunnel ? "the tunnel stays" : "a solid plate is a disc");
    if (!tunnel) {
      EXPECT_GT(report.loops_closed_inside, 0u);
    }
  }
}

TEST(QuadricMedialMesh, HoleTheCollapsesLeftIsClosedWhereTheInputHoldsIt) {
  // The same thin wall's sheet with its hole (a rim of 24 edges, none
  // bridged), not simplified: the budget stopped the collapses before any
  // met the hole's rim (CGAL's rotor_small: three such holes through its
  // shell's sheet, each a loop of three edges no collapse touched). The
  // input holds the disc across it when the plate is solid (closed: the
  // sheet a disc, χ 1), not when the hole is a tunnel of the plate (χ 0);
  // the sheet's outer rim is never closed over the sheet (χ 2).
  for (const bool tunnel : {false, true}) {
    QuadricReport report;
    const MedialMesh m = thin_plate_sheet(100000, tunnel, report);
    EXPECT_EQ(report.collapses, 0u);
    EXPECT_EQ(report.holes_closed, tunnel ? 0u : 1u);
    EXPECT_EQ(euler_characteristic(m), tunnel ? 0 : 1) << m.triangles.size() << " triangles";
  }
}

TEST(QuadricMedialMesh, TubeEdgeAcrossASheetsHoleIsClosedWhereTheInputHoldsIt) {
  // The same thin wall's sheet with a tube edge across its hole (a Voronoi
  // edge whose faces were dropped with the hole's), not simplified: two
  // loops (χ −1). The input holds both sides of the edge when the plate is
  // solid (each side closed by a fan: a disc, χ 1), neither when the hole is
  // a tunnel of the plate.
  MedialGraph g = quadric_sheet(21, 0.05, 0.02, 7, 13);
  const auto vertex_at = [&g](double x, double y) {
    for (std::size_t k = 0; k < g.vertices.size(); ++k)
      if ((g.vertices[k].centre - Vec3(x, y, 0)).norm() < 1e-9) return std::int32_t(k);
    return std::int32_t(-1);
  };
  add_edge(g, vertex_at(0.35, 0.5), vertex_at(0.65, 0.5));
  for (const bool tunnel : {false, true}) {
    QuadricOptions o;
    o.budget = 100000;
    o.depth = plate_depth(0.02, tunnel, 0.36, 0.64);
    o.inside_samples = 4;
    QuadricReport report;
    const MedialMesh m = quadric_medial_mesh(g, o, &report);
    EXPECT_EQ(report.collapses, 0u);
    EXPECT_EQ(report.bridges_closed, tunnel ? 0u : 2u);
    EXPECT_EQ(euler_characteristic(m), tunnel ? -1 : 1) << m.triangles.size() << " triangles, " << m.edges.size()
                                                        << " tube edges";
  }
  // Without inside_samples (the default) nothing is closed.
  QuadricOptions o;
  o.budget = 100000;
  o.depth = plate_depth(0.02, false, 0, 0);
  EXPECT_EQ(euler_characteristic(quadric_medial_mesh(g, o)), -1);
}

// The bisector sheet of a right-angled edge along y: the solid between the
// planes z = ±x (x > 0), its sheet z = 0, each ball (x, y, 0) of radius
// x sin 45° touching both planes, where the outward normals are
// (−1, 0, ±1)/√2. Every such ball has zero quadric error, so without the
// radius term the collapses spread the spheres by the length term alone,
// alike along x and y; a one-radius SCALIS triangle spanning radii r_min to
// r_max then steps by about their difference. The radius term makes a
// collapse across x (Δr = Δx sin 45°) dearer than one along y (Δr = 0).
MedialGraph quadric_wedge_sheet(int n, double x0, double h) {
  MedialGraph g;
  const double s = std::sqrt(0.5);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Vec3 c(x0 + i * h, j * h, 0.0);
      const double r = c.x() * s;
      const std::int32_t above = std::int32_t(g.samples.size());
      g.samples.push_back(c + r * Vec3(-s, 0, s));
      g.samples.push_back(c + r * Vec3(-s, 0, -s));
      g.vertices.push_back(MedialVertex{c, r, {above, above + 1, above, above + 1}});
    }
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j)
      g.faces.push_back({i * n + j, (i + 1) * n + j, (i + 1) * n + j + 1, i * n + j + 1});
  return g;
}

/// The largest difference of radii within one triangle or tube edge of `m`.
double largest_radius_spread(const MedialMesh& m) {
  double spread = 0.0;
  for (const auto& e : m.edges)
    spread = std::max(spread, std::abs(m.spheres[std::size_t(e[0])].w() - m.spheres[std::size_t(e[1])].w()));
  for (const auto& t : m.triangles) {
    const double a = m.spheres[std::size_t(t[0])].w(), b = m.spheres[std::size_t(t[1])].w(),
                 c = m.spheres[std::size_t(t[2])].w();
    spread = std::max(spread, std::max({a, b, c}) - std::min({a, b, c}));
  }
  return spread;
}

TEST(QuadricMedialMesh, TheRadiusTermKeepsASheetsTrianglesNarrowWhereItsRadiusVaries) {
  // 21 × 21 balls 0.05 apart from x = 0.02 (radius 0.014) to 1.02 (0.72).
  const MedialGraph g = quadric_wedge_sheet(21, 0.02, 0.05);
  QuadricOptions o;
  o.budget = 60;
  o.radius_weight = 0.0;
  const MedialMesh plain = quadric_medial_mesh(g, o);
  o.radius_weight = 0.03;  // the weight measured on CGAL's CAD parts
  const MedialMesh weighted = quadric_medial_mesh(g, o);
  for (const MedialMesh* m : {&plain, &weighted}) {
    EXPECT_LE(primitives(*m), 60u);
    EXPECT_GE(m->triangles.size(), 30u) << "a sheet stays triangles";
  }
  // Each sphere still touches both planes (zero error): r = x sin 45°.
  for (const Vec4& sphere : weighted.spheres) {
    EXPECT_NEAR(sphere.z(), 0.0, 1e-9);
    EXPECT_NEAR(sphere.w(), sphere.x() * std::sqrt(0.5), 1e-9);
  }
  // The sheet spans radii 0.014 to 0.72; 60 triangles about equal in x and y
  // (about 5 × 6 cells) span about a fifth of that each, or more.
  const double before = largest_radius_spread(plain), after = largest_radius_spread(weighted);
  EXPECT_GT(before, 0.12);
  EXPECT_LT(after, 0.6 * before) << "before " << before << ", after " << after;
}

TEST(QuadricMedialMesh, TubeBecomesAChainOnItsAxis) {
  // A line of balls of radius 0.2 along x, each touching the cylinder
  // y² + z² = 0.2² at four points.
  MedialGraph g;
  for (int k = 0; k <= 100; ++k) {
    const double x = 0.02 * k;
    const std::int32_t first = std::int32_t(g.samples.size());
    for (const Vec3& d : {Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)}) g.samples.push_back(Vec3(x, 0, 0) + 0.2 * d);
    g.vertices.push_back(MedialVertex{Vec3(x, 0, 0), 0.2, {first, first + 1, first + 2, first + 3}});
    if (k > 0) add_edge(g, k - 1, k);
  }
  QuadricOptions o;
  o.budget = 4;
  const MedialMesh m = quadric_medial_mesh(g, o);
  EXPECT_TRUE(m.triangles.empty());
  EXPECT_EQ(m.edges.size(), 4u);
  EXPECT_EQ(m.spheres.size(), 5u);
  double low = 1.0, high = 0.0;
  for (const Vec4& s : m.spheres) {
    EXPECT_NEAR(s.y(), 0.0, 1e-9);
    EXPECT_NEAR(s.z(), 0.0, 1e-9);
    EXPECT_NEAR(s.w(), 0.2, 1e-9);
    low = std::min(low, s.x()), high = std::max(high, s.x());
  }
  // Shortest edges first: the five spheres spread over the 2 long axis.
  EXPECT_LT(low, 0.4);
  EXPECT_GT(high, 1.6);
}

// A horn on a sheet: the 6 × 6 sheet of quadric_sheet (spacing 0.1,
// between the planes z = ±0.1), and from its corner (0.5, 0.5, 0) a chain
// of balls along x on the axis of a cone of half-angle 15° whose apex is
// at x = 0.5 + 0.1 / sin 15° = 0.886: t = 0.1, 0.12, …, 0.38 from the
// apex, each of radius t sin 15° touching the cone at four points. Every
// ball on the axis touches every one of the cone's tangent planes, so the
// collapses may merge the chain's end ball into a deeper one at no error
// from them. The apex is a sample that no ball reaches: the first ball
// falls 0.1 (1 − sin 15°) = 0.074 short of it, 2.9 times its radius
// (0.026), as a horn's tip falls short of the balls pruning leaves. Held
// (unreached_tips.hpp), that ball keeps its place through the collapses.
TEST(QuadricMedialMesh, AHornsEndBallKeepsItsPlaceThroughTheCollapses) {
  const double angle = 15.0 * std::numbers::pi / 180.0;
  MedialGraph g = quadric_sheet(6, 0.1, 0.1);
  const Vec3 apex(0.5 + 0.1 / std::sin(angle), 0.5, 0);
  const std::int32_t corner = std::int32_t(g.vertices.size() - 1);  // (0.5, 0.5, 0)
  ASSERT_LT((g.vertices[std::size_t(corner)].centre - Vec3(0.5, 0.5, 0)).norm(), 1e-12);
  const std::int32_t apex_sample = std::int32_t(g.samples.size());
  g.samples.push_back(apex);
  std::int32_t previous = corner;
  for (int k = 14; k >= 0; --k) {
    const double t = 0.1 + 0.02 * k;
    const std::int32_t first = std::int32_t(g.samples.size());
    for (const Vec3& e : {Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)})
      g.samples.push_back(apex + t * std::cos(angle) * (std::cos(angle) * Vec3(-1, 0, 0) + std::sin(angle) * e));
    g.vertices.push_back(MedialVertex{apex - Vec3(t, 0, 0), t * std::sin(angle), {first, first + 1, first + 2, first + 3}});
    add_edge(g, previous, std::int32_t(g.vertices.size() - 1));
    previous = std::int32_t(g.vertices.size() - 1);
  }
  const std::int32_t tip = previous;
  const double first_gap = 0.1 * (1 - std::sin(angle));  // 0.0741
  // How far the spheres fall short of the apex at best.
  const auto shortfall = [&apex](const MedialMesh& m) {
    double least = std::numeric_limits<double>::infinity();
    for (const Vec4& s : m.spheres) least = std::min(least, (apex - s.head<3>()).norm() - s.w());
    return least;
  };
  QuadricOptions o;
  o.budget = 4;
  // Alone, the collapses merge the whole horn into the sheet's corner
  // ball, 0.386 − 0.1 = 0.286 short of the apex.
  ASSERT_GT(shortfall(quadric_medial_mesh(g, o)), first_gap + 0.1)
      << "the case must be one the collapses alone shorten";
  // Reach 0.05: the apex's gap is above it and above the first ball's
  // radius; every other sample is on a ball.
  o.reach_points = detail::unreached_tips(g, 0.05, 1.0, 0.1);
  ASSERT_EQ(o.reach_points.size(), 1u);
  EXPECT_EQ(o.reach_points[0].vertex, tip);
  EXPECT_EQ(o.reach_points[0].point, g.samples[std::size_t(apex_sample)]);
  const MedialMesh held = quadric_medial_mesh(g, o);
  EXPECT_NEAR(shortfall(held), first_gap, 1e-12);
  EXPECT_LE(held.triangles.size() + held.edges.size() + held.isolated.size(), 4u);
  // The held ball is a tube's end, not a sphere apart.
  EXPECT_TRUE(held.isolated.empty());
  // Thicker than it is long beyond the ball (thinness 3 > 2.9): not a tip.
  EXPECT_TRUE(detail::unreached_tips(g, 0.05, 3.0, 0.1).empty());
}

// Inside the unit ball (depth 1 − |x|), three tube ends off a sphere B at
// the centre. A (radius 0.6 at x = −0.3, depth 0.7) is a tube's: its
// sphere beyond, one radius on, is at (−0.9, 0, 0), depth 0.1, and is
// added. C (radius 0.2 at y = 0.92, depth 0.08, less than half its radius)
// is a spike: its ball reaches out of the input, as the medial axis's
// spikes towards the creases of a tessellation do; its sphere beyond would
// be at (0, 1.12, 0), 0.12 outside, and goes back to the surface, (0, 1,
// 0). D (radius 0.1 at 0.905 along the diagonal y = −x, depth 0.095) is a
// tube's end with its cap a radius ahead: its sphere beyond, 0.005
// outside, stays where it is.
TEST(TubeEnds, ASpikesSphereBeyondGoesBackToTheInputsSurface) {
  reconstruct::MedialMesh m;
  const double s = std::sqrt(0.5);
  m.spheres = {Vec4(-0.3, 0, 0, 0.6), Vec4(0, 0, 0, 0.6), Vec4(0, 0.92, 0, 0.2), Vec4(0.905 * s, -0.905 * s, 0, 0.1)};
  m.edges = {{0, 1}, {1, 2}, {1, 3}};
  const auto depth = [](const Vec3& x) { return 1.0 - x.norm(); };
  EXPECT_EQ(detail::extend_tube_ends(m, 1.0, 0.5, 0.0, 0.5, depth), 1u);
  ASSERT_EQ(m.spheres.size(), 7u);
  ASSERT_EQ(m.edges.size(), 6u);
  EXPECT_EQ(m.edges[3], (std::array<std::int32_t, 2>{0, 4}));
  EXPECT_EQ(m.edges[4], (std::array<std::int32_t, 2>{2, 5}));
  EXPECT_EQ(m.edges[5], (std::array<std::int32_t, 2>{3, 6}));
  EXPECT_NEAR((m.spheres[4] - Vec4(-0.9, 0, 0, 0.6)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((m.spheres[5] - Vec4(0, 1, 0, 0.2)).norm(), 0.0, 1e-9);
  EXPECT_GE(depth(m.spheres[5].head<3>()), 0.0);
  EXPECT_NEAR((m.spheres[6] - Vec4(1.005 * s, -1.005 * s, 0, 0.1)).norm(), 0.0, 1e-15);
}

// A tube of one edge from sphere a to sphere b.
reconstruct::MedialMesh one_tube(const Vec4& a, const Vec4& b) {
  reconstruct::MedialMesh m;
  m.spheres = {a, b};
  m.edges = {{0, 1}};
  return m;
}

// A ball on a neck: the unit ball at the origin and a tube of radius 0.2
// along −x into it (the input's depth the larger of the two's). The
// medial mesh: the ball's sphere B at the end of a tube edge from the
// neck's sphere N (radius 0.2 at x = −1.2). B's radius is 1.02, a little
// more than its centre's depth 1, as a merged sphere's may be (the elk's:
// 24.0 at 23.7 deep), so it is shallower than its radius, as a tapering
// tip is, and must still be found a bulb. B is wider than N by 0.82, more
// than half their distance 1.2, and one radius beyond it (x = 1.02) the
// input ends: a bulb. It gets no sphere beyond (which would stand on the
// ball's surface with the ball's radius, a capsule a radius longer than
// the input) but a copy of its sphere, isolated. N's end, a tube's, is
// extended one radius on as before. With the rule off (bulb slope 0) B's
// sphere beyond is (1.02, 0, 0), radius 1.02.
TEST(TubeEnds, ABulbsBallIsAnIsolatedSphereNotACapsule) {
  const auto depth = [](const Vec3& p) {
    const double neck = std::min(0.2 - std::hypot(p.y(), p.z()), p.x() + 3.0);
    return std::max(1.0 - p.norm(), neck);
  };
  reconstruct::MedialMesh m = one_tube(Vec4(-1.2, 0, 0, 0.2), Vec4(0, 0, 0, 1.02));
  std::size_t bulbs = 0;
  EXPECT_EQ(detail::extend_tube_ends(m, 1.0, 0.5, 2.0, 0.5, depth, &bulbs), 0u);
  EXPECT_EQ(bulbs, 1u);
  ASSERT_EQ(m.spheres.size(), 4u);
  ASSERT_EQ(m.edges.size(), 2u);
  EXPECT_EQ(m.edges[1], (std::array<std::int32_t, 2>{0, 2}));
  EXPECT_NEAR((m.spheres[2] - Vec4(-1.4, 0, 0, 0.2)).norm(), 0.0, 1e-15);
  ASSERT_EQ(m.isolated, std::vector<std::int32_t>{3});
  EXPECT_EQ(m.spheres[3], Vec4(0, 0, 0, 1.02));
  // Off: a sphere beyond on the ball's surface.
  reconstruct::MedialMesh off = one_tube(Vec4(-1.2, 0, 0, 0.2), Vec4(0, 0, 0, 1.02));
  detail::extend_tube_ends(off, 1.0, 0.5, 2.0, 0.0, depth, &bulbs);
  EXPECT_EQ(bulbs, 0u);
  EXPECT_TRUE(off.isolated.empty());
  ASSERT_EQ(off.spheres.size(), 4u);
  EXPECT_NEAR((off.spheres[3] - Vec4(1.02, 0, 0, 1.02)).norm(), 0.0, 1e-15);
  // A tube that widens into a body (the input goes on, 2.5 deep, one
  // radius beyond its end): no bulb, extended as before.
  const auto body = [](const Vec3& p) { return 3.0 - (p - Vec3(1, 0, 0)).norm(); };
  reconstruct::MedialMesh w = one_tube(Vec4(-0.5, 0, 0, 0.2), Vec4(0, 0, 0, 0.5));
  detail::extend_tube_ends(w, 1.0, 0.5, 2.0, 0.5, body, &bulbs);
  EXPECT_EQ(bulbs, 0u);
  EXPECT_TRUE(w.isolated.empty());
  EXPECT_NEAR((w.spheres[3] - Vec4(0.5, 0, 0, 0.5)).norm(), 0.0, 1e-15);
}

// A horn: a cone along x, apex at x = 1, half-angle asin 0.12 (signed
// distance (1 − x)·0.12 − |y, z|·cos, cut at x = −1). An edge from the
// origin (0.12 deep, deeper than its radius 0.1: a body's end) to the tip
// A at x = 0.5 (0.06 deep, shallower than its radius, not a spike's). One
// radius beyond A the horn goes on to x = 1, five times as far: A's
// sphere beyond goes to the apex; the origin's stays one radius on.
TEST(TubeEnds, ATaperingTipsSphereBeyondGoesToWhereTheInputEnds) {
  const double sin_a = 0.12, cos_a = std::sqrt(1 - sin_a * sin_a);
  const auto horn = [&](const Vec3& p) {
    return std::min((1.0 - p.x()) * sin_a - std::hypot(p.y(), p.z()) * cos_a, p.x() + 1.0);
  };
  reconstruct::MedialMesh m;
  m.spheres = {Vec4(0, 0, 0, 0.1), Vec4(0.5, 0, 0, 0.1)};
  m.edges = {{0, 1}};
  // The edge's other end, the origin, is 0.12 deep: deeper than its
  // radius, so it is a body's end and keeps one radius on (x = −0.1).
  EXPECT_EQ(detail::extend_tube_ends(m, 1.0, 0.5, 2.0, 0.5, horn), 0u);
  ASSERT_EQ(m.spheres.size(), 4u);
  EXPECT_NEAR((m.spheres[2] - Vec4(-0.1, 0, 0, 0.1)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((m.spheres[3] - Vec4(1.0, 0, 0, 0.1)).norm(), 0.0, 1e-9);
  EXPECT_GE(horn(m.spheres[3].head<3>()), 0.0);
  // Off: one radius on.
  reconstruct::MedialMesh off;
  off.spheres = {Vec4(0, 0, 0, 0.1), Vec4(0.5, 0, 0, 0.1)};
  off.edges = {{0, 1}};
  detail::extend_tube_ends(off, 1.0, 0.5, 0.0, 0.5, horn);
  EXPECT_NEAR((off.spheres[3] - Vec4(0.6, 0, 0, 0.1)).norm(), 0.0, 1e-15);
  // A body beyond: the cone turned round (apex at x = −1, widening past
  // the tip). The tip at 0.5, radius 0.2, is 0.18 deep, but the input is
  // deeper than 0.2 a quarter radius past its sphere beyond: one radius on.
  const auto body = [&](const Vec3& p) { return (p.x() + 1.0) * sin_a - std::hypot(p.y(), p.z()) * cos_a; };
  reconstruct::MedialMesh b;
  b.spheres = {Vec4(0, 0, 0, 0.2), Vec4(0.5, 0, 0, 0.2)};
  b.edges = {{0, 1}};
  detail::extend_tube_ends(b, 1.0, 0.5, 2.0, 0.5, body);
  EXPECT_NEAR((b.spheres[3] - Vec4(0.7, 0, 0, 0.2)).norm(), 0.0, 1e-15);
  // A tube going on at its depth to a round cap (a capsule of radius 0.1
  // from x = −1 to 1): the tip 0.02 off its axis at x = 0 is 0.08 deep,
  // shallower than its radius 0.1, and the input goes on to x ≈ 1.1, but
  // loses its depth over the cap's 0.1: one radius on.
  const auto capsule = [](const Vec3& p) {
    return 0.1 - std::hypot(std::max(std::abs(p.x()) - 1.0, 0.0), std::hypot(p.y(), p.z()));
  };
  reconstruct::MedialMesh c;
  c.spheres = {Vec4(-0.5, 0.02, 0, 0.1), Vec4(0, 0.02, 0, 0.1)};
  c.edges = {{0, 1}};
  detail::extend_tube_ends(c, 1.0, 0.5, 2.0, 0.5, capsule);
  EXPECT_NEAR((c.spheres[3] - Vec4(0.1, 0.02, 0, 0.1)).norm(), 0.0, 1e-15);
}

// A drop's tip: a cone of half-angle asin 0.17 (about 10°) along the x
// axis, apex at x = 1. Its medial axis runs to the apex, the radius falling
// to 0, but the samples' spacing stops it short: the simplified mesh ends
// at a sheet's corner, a ball of radius 0.06 at (0.7, 0.03, 0) whose centre
// is 0.021 deep (as CGAL's drop's, 0.0085 deep with radius 0.037: the
// Voronoi balls near a tip thinner than the spacing are barely inside).
// The apex is 0.3015 − 0.06 = 0.2415 beyond it: more than the reach (0.05)
// and the ball's radius. The corner gets a tube edge towards the apex,
// ending one floor radius (0.02) short of it, with a sphere of that radius.
TEST(TubeEnds, ASharpTipTheMeshFallsShortOfGetsATubeOutToIt) {
  const double sin_a = 0.17, cos_a = std::sqrt(1 - sin_a * sin_a);
  const auto cone = [&](const Vec3& p) {
    return std::min((1.0 - p.x()) * sin_a - std::hypot(p.y(), p.z()) * cos_a, p.x() + 1.0);
  };
  const Vec3 apex(1, 0, 0), corner(0.7, 0.03, 0);
  ASSERT_NEAR(cone(corner), 0.3 * sin_a - 0.03 * cos_a, 1e-15);
  ASSERT_LT(cone(corner), 0.06) << "the corner's ball must reach out of the cone, as a tip's do";
  const auto sheet = [&corner](double radius) {
    reconstruct::MedialMesh m;
    m.spheres = {Vec4(corner.x(), corner.y(), corner.z(), radius), Vec4(0.3, 0.05, 0, 0.1), Vec4(0.3, -0.05, 0, 0.1)};
    m.triangles = {{0, 1, 2}};
    return m;
  };
  const std::vector<reconstruct::ReachPoint> tips{{0, apex}};
  reconstruct::MedialMesh m = sheet(0.06);
  EXPECT_EQ(detail::reach_unreached_tips(m, tips, 0.05, 1.0, 0.02, cone), 1u);
  ASSERT_EQ(m.spheres.size(), 4u);
  ASSERT_EQ(m.edges.size(), 1u);
  EXPECT_EQ(m.edges[0], (std::array<std::int32_t, 2>{0, 3}));
  EXPECT_EQ(m.triangles.size(), 1u);
  const Vec3 end = m.spheres[3].head<3>();
  EXPECT_EQ(m.spheres[3].w(), 0.02);
  // On the line from the corner to the apex, 0.02 short of the apex.
  EXPECT_NEAR((apex - end).norm(), 0.02, 1e-15);
  EXPECT_NEAR((apex - end).cross(apex - corner).norm(), 0.0, 1e-15);
  EXPECT_GT((apex - end).dot(apex - corner), 0.0);
  EXPECT_GE(cone(end), 0.0);
  // A ball reaching within the reach of the apex (0.04 − 0.005 short):
  // nothing added.
  reconstruct::MedialMesh reached = sheet(0.06);
  reached.spheres.push_back(Vec4(0.96, 0, 0, 0.005));
  reached.edges.push_back({0, 3});
  EXPECT_EQ(detail::reach_unreached_tips(reached, tips, 0.05, 1.0, 0.02, cone), 0u);
  EXPECT_EQ(reached.spheres.size(), 4u);
  // Thicker than it is long beyond its ball (a ball of radius 0.3 at
  // x = 0.6, 0.1 short of the apex: under thinness 1 × its radius):
  // nothing added.
  reconstruct::MedialMesh thick = sheet(0.3);
  thick.spheres[0] = Vec4(0.6, 0, 0, 0.3);
  EXPECT_EQ(detail::reach_unreached_tips(thick, tips, 0.05, 1.0, 0.02, cone), 0u);
  EXPECT_EQ(thick.spheres.size(), 3u);
  // A round end: a capsule of radius 0.1 along the x axis to x = 0.9, its
  // tip (1, 0, 0) 0.22 beyond a ball of radius 0.06 at (0.72, 0, 0) (a
  // ball the collapses left short of it), is 0.02 deep 0.02 short of the
  // tip, not under half of 0.02: nothing added.
  const auto capsule = [](const Vec3& p) {
    return 0.1 - std::hypot(std::max(std::abs(p.x()) - 0.9, 0.0), std::hypot(p.y(), p.z()));
  };
  reconstruct::MedialMesh round = sheet(0.06);
  round.spheres[0] = Vec4(0.72, 0, 0, 0.06);
  EXPECT_EQ(detail::reach_unreached_tips(round, tips, 0.05, 1.0, 0.02, capsule), 0u);
  EXPECT_EQ(round.spheres.size(), 3u);
  // The way to the apex crosses a gap in the input (0.83 < x < 0.87): no
  // tube out of it.
  const auto notched = [&cone](const Vec3& p) { return std::min(cone(p), std::abs(p.x() - 0.85) - 0.02); };
  reconstruct::MedialMesh gap = sheet(0.06);
  EXPECT_EQ(detail::reach_unreached_tips(gap, tips, 0.05, 1.0, 0.02, notched), 0u);
  EXPECT_EQ(gap.spheres.size(), 3u);
  EXPECT_TRUE(gap.edges.empty());
}

// The tube is on by default, but only for a tip the mesh falls short of by
// half a sample spacing or more: a tip within that is within the goal as
// it is (half a spacing is 1.25% of the diagonal at 40 divisions). The
// same cone (apex (1, 0, 0), half-angle asin 0.17), a spacing of 0.2: the
// stage's reach is `tip_tube_reach` spacings. A ball inscribed on the axis
// 0.0723 from the apex (radius 0.0723 × 0.17 ≈ 0.0123) falls 0.06 short
// of it: 0.3 spacings (the cow's horn was 0.29), more than its radius and
// than the quarter spacing that holds it through the collapses, and the
// tip is sharp (0.0034 deep one floor radius short of the apex): no tube.
// The sheet's corner of the test above, 1.2 spacings short, gets one.
TEST(TubeEnds, ASharpTipShortByLessThanHalfASpacingGetsNoTube) {
  const MedialOptions defaults;
  EXPECT_TRUE(defaults.tip_end_tube);
  const double sin_a = 0.17, cos_a = std::sqrt(1 - sin_a * sin_a), spacing = 0.2;
  const double reach = defaults.tip_tube_reach * spacing, floor_radius = 0.02;
  const auto cone = [&](const Vec3& p) {
    return std::min((1.0 - p.x()) * sin_a - std::hypot(p.y(), p.z()) * cos_a, p.x() + 1.0);
  };
  const std::vector<ReachPoint> tips{{0, Vec3(1, 0, 0)}};
  const double near_length = 0.06 / (1.0 - sin_a);
  MedialMesh near;
  near.spheres = {Vec4(1.0 - near_length, 0, 0, near_length * sin_a), Vec4(0.3, 0, 0, 0.1)};
  near.edges = {{0, 1}};
  ASSERT_NEAR(1.0 - (near.spheres[0].x() + near.spheres[0].w()), 0.3 * spacing, 1e-12);
  ASSERT_GT(0.3 * spacing, defaults.tip_end_reach * spacing) << "held through the collapses: a tip pruning left short";
  ASSERT_GT(0.3 * spacing, defaults.tip_end_thinness * near.spheres[0].w());
  ASSERT_LT(cone(Vec3(1.0 - floor_radius, 0, 0)), 0.5 * floor_radius) << "a sharp tip";
  EXPECT_EQ(detail::reach_unreached_tips(near, tips, reach, defaults.tip_end_thinness, floor_radius, cone), 0u);
  EXPECT_EQ(near.spheres.size(), 2u);
  EXPECT_EQ(near.edges.size(), 1u);
  MedialMesh far;
  far.spheres = {Vec4(0.7, 0.03, 0, 0.06), Vec4(0.3, 0.05, 0, 0.1), Vec4(0.3, -0.05, 0, 0.1)};
  far.triangles = {{0, 1, 2}};
  EXPECT_EQ(detail::reach_unreached_tips(far, tips, reach, defaults.tip_end_thinness, floor_radius, cone), 1u);
  EXPECT_EQ(far.spheres.size(), 4u);
}

/// A ring of n balls of radius rho around the z axis at distance R: the
/// medial axis of a torus (a wall around a bore, cut across), each ball
/// touching the torus on its outer and inner side and above and below.
MedialGraph quadric_ring(int n, double R, double rho) {
  MedialGraph g;
  for (int k = 0; k < n; ++k) {
    const double angle = 2 * std::acos(-1.0) * k / n;
    const Vec3 radial(std::cos(angle), std::sin(angle), 0), c = R * radial;
    const std::int32_t first = std::int32_t(g.samples.size());
    for (const Vec3& d : {radial, Vec3(-radial), Vec3(0, 0, 1), Vec3(0, 0, -1)}) g.samples.push_back(c + rho * d);
    g.vertices.push_back(MedialVertex{c, rho, {first, first + 1, first + 2, first + 3}});
    add_edge(g, k, (k + 1) % n);
  }
  return g;
}

TEST(QuadricMedialMesh, MergedBallsStayInsideTheShapeWhenItsDepthIsKnown) {
  // A ring collapsed to its last loop: each remaining sphere sums the
  // planes of a third of the ring, and a sphere tangent to them all lies
  // in the bore. With the torus's signed distance, every merged ball
  // stays inside it.
  const double R = 0.25, rho = 0.05;
  const MedialGraph g = quadric_ring(120, R, rho);
  const auto depth = [&](const Vec3& p) { return rho - std::hypot(std::hypot(p.x(), p.y()) - R, p.z()); };
  QuadricOptions o;
  o.budget = 3;
  const MedialMesh free = quadric_medial_mesh(g, o);
  ASSERT_EQ(free.spheres.size(), 3u) << "a loop needs three spheres";
  double worst = 0.0;
  for (const Vec4& s : free.spheres) worst = std::max(worst, s.w() - depth(s.head<3>()));
  EXPECT_GT(worst, rho) << "without the depth, a merged ball leaves the torus (else this test shows nothing)";
  o.depth = depth;
  const MedialMesh kept = quadric_medial_mesh(g, o);
  ASSERT_EQ(kept.spheres.size(), 3u);
  EXPECT_EQ(kept.edges.size(), 3u) << "the loop stays";
  for (const Vec4& s : kept.spheres) {
    EXPECT_GT(depth(s.head<3>()), 0.0) << s.transpose();
    EXPECT_LE(s.w(), depth(s.head<3>()) + 1e-12) << s.transpose();
  }
}

/// The sheet of quadric_sheet (no hole) whose radius grows by `step` from
/// one column of vertices (one x) to the next, its contact planes z = ±r
/// of its own column.
MedialGraph graded_sheet(int n, double h, double r, double step) {
  MedialGraph g = quadric_sheet(n, h, r);
  for (MedialVertex& v : g.vertices) {
    v.radius = r + step * std::round(v.centre.x() / h);
    g.samples[std::size_t(v.samples[0])].z() = v.radius;
    g.samples[std::size_t(v.samples[1])].z() = -v.radius;
  }
  return g;
}

TEST(QuadricMedialMesh, WithinTheBudgetCollapsesGoOnWhileWithinTheErrorTarget) {
  // A sheet of 21 columns whose radius steps by Δ from one column to the
  // next: a collapse within a column makes a sphere of no error, one that
  // joins two columns a sphere at least Δ / 2 from the planes of one of
  // them (its radius within Δ / 2 of at most one column's). Its 800
  // triangles are within a budget of 1000.
  const double step = 0.005;
  const MedialGraph g = graded_sheet(21, 0.05, 0.2, step);
  QuadricOptions o;
  o.budget = 1000;
  QuadricReport without;
  const MedialMesh all = quadric_medial_mesh(g, o, &without);
  EXPECT_EQ(primitives(all), 800u) << "without a target, nothing to collapse within the budget";
  EXPECT_EQ(without.collapses, 0u);
  EXPECT_EQ(without.stopped_at_budget, 1u);
  // Below the error of any first join of two columns: every column
  // collapses on itself to one sphere of its radius (a disc's collapses
  // end at a chain, a complex of its topology).
  o.error_target = 0.2 * step;
  QuadricReport within;
  const MedialMesh columns = quadric_medial_mesh(g, o, &within);
  EXPECT_EQ(within.stopped_at_error, 1u);
  EXPECT_EQ(within.collapses_under_budget, within.collapses);
  EXPECT_GT(within.over_error_target, 0u) << "collapses across the columns are left undone";
  EXPECT_EQ(columns.spheres.size(), 21u) << "each column one sphere";
  EXPECT_EQ(primitives(columns), 20u) << "a chain of 21 spheres";
  EXPECT_EQ(euler_characteristic(columns), 1) << "a disc stays a disc";
  std::set<long> radii;
  for (const Vec4& s : columns.spheres) {
    const double column = std::round((s.w() - 0.2) / step);
    EXPECT_NEAR(s.w(), 0.2 + step * column, 1e-9) << "a sphere of two columns";
    EXPECT_NEAR(s.x(), 0.05 * column, 1e-9);
    EXPECT_NEAR(s.z(), 0.0, 1e-9);
    radii.insert(long(column));
  }
  EXPECT_EQ(radii.size(), 21u) << "every column keeps a sphere";
  // Above the error of joining two whole columns (Δ / 2): columns join,
  // and fewer primitives are left.
  o.error_target = 1.5 * step;
  const MedialMesh joined = quadric_medial_mesh(g, o);
  EXPECT_LT(primitives(joined), primitives(columns));
}

TEST(QuadricMedialMesh, TheErrorTargetBoundsEveryPlaneNotTheirMean) {
  // A flat sheet of radius r whose middle vertex alone has radius r + D
  // (its 4 planes at z = ±(r + D)). Every other collapse costs no error;
  // joining the middle ball to any other leaves a sphere at least D / 2
  // from the planes of one of the two (its radius within D / 2 of r or
  // of r + D, the planes' normals ±z). A mean over the planes would let
  // it join a sphere of many planes (4 planes D off among 1,764 are a
  // root mean square of D √(4 / 1764) ≈ 0.05 D): the target bounds each
  // plane, and the middle ball keeps its radius.
  const double r = 0.2, D = 0.01;
  const int n = 21;
  MedialGraph g = quadric_sheet(n, 0.05, r);
  MedialVertex& middle = g.vertices[std::size_t((n / 2) * n + n / 2)];
  middle.radius = r + D;
  g.samples[std::size_t(middle.samples[0])].z() = r + D;
  g.samples[std::size_t(middle.samples[1])].z() = -(r + D);
  QuadricOptions o;
  o.budget = 1000;
  o.error_target = 0.2 * D;
  QuadricReport report;
  const MedialMesh m = quadric_medial_mesh(g, o, &report);
  EXPECT_EQ(report.stopped_at_error, 1u);
  EXPECT_GT(report.collapses, 0u) << "the flat sheet collapses";
  EXPECT_GT(report.over_error_target, 0u) << "joining the middle ball is left undone";
  std::size_t kept = 0;
  for (const Vec4& s : m.spheres) {
    if (std::abs(s.w() - (r + D)) < 1e-9) ++kept;
    else EXPECT_NEAR(s.w(), r, 0.2 * D) << "a sphere farther than the target from the sheet's planes";
  }
  EXPECT_EQ(kept, 1u) << "the middle ball stays apart";
}

TEST(QuadricMedialMesh, SameGraphSameMesh) {
  const MedialGraph g = quadric_sheet(15, 0.05, 0.3, 5, 9);
  QuadricOptions o;
  o.budget = 30;
  const MedialMesh a = quadric_medial_mesh(g, o), b = quadric_medial_mesh(g, o);
  EXPECT_EQ(a.spheres, b.spheres);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.triangles, b.triangles);
}

TEST(MedialMesh, BudgetIsRespected) {
  const TriangleMesh cube = read_mesh(std::filesystem::path(SKELCONV_TEST_DATA) / "reconstruct" / "cube.ply");
  // 40, not fewer: the link condition keeps the cube's medial complex at
  // about 30 primitives (loops whose triangles leave its balls).
  for (const std::size_t budget : {40u, 500u}) {
    ReconstructOptions o;
    o.method = SkeletonMethod::medial;
    o.medial.budget = budget;
    // The budget is the medial mesh's; the fit moves spheres, never adds
    // primitives: no round of either stage (and so no topology test).
    o.medial.fit.rounds = 0, o.medial.fit.worst_rounds = 0;
    const Reconstruction r = reconstruct(cube, o);
    ASSERT_EQ(r.stages.back().name, "medial");
    EXPECT_LE(primitive_counts(r.stages.back(), o).total(), budget);
    EXPECT_GT(primitive_counts(r.stages.back(), o).total(), 0u);
  }
}

/// The radii written for the one triangle of `spheres` (three spheres) by
/// the medial path's skeleton file, with `rule`.
std::array<double, 3> written_triangle_radii(const std::vector<Vec4>& spheres, const TriangleRadiusRule& rule) {
  ReconstructOptions o;
  o.method = SkeletonMethod::medial;
  o.medial.triangle_radius = rule;
  Stage s;
  s.name = "medial";
  s.medial.spheres = spheres;
  s.medial.triangles = {{0, 1, 2}};
  const Skeleton skeleton = parse_skeleton_json(skeleton_file_text(s, o));
  EXPECT_EQ(skeleton.primitives().size(), 1u);
  return std::get<ScalisTriangle>(skeleton.primitives().at(0)).radii();
}

TEST(MedialMesh, ATrianglesRadiusIsTheMeanOfItsSpheresOrTheirGeometricMean) {
  // A fan from a thick sphere (radius 0.8) to two thin ones (0.1), as a
  // body's sheet runs out to a thin part lying against it. The SCALIS
  // triangle's one radius: with the arithmetic rule (--medial-arithmetic-
  // triangle-radius) (0.8 + 0.1 + 0.1) / 3 = 1/3, 3.3 times the thin
  // corners'; with the geometric rule ∛(0.8 × 0.1 × 0.1) = ∛0.008 = 0.2,
  // twice theirs. Equal radii give that radius either way.
  const auto written_radii = [](const std::vector<Vec4>& spheres, bool geometric) {
    return written_triangle_radii(spheres,
                                  geometric ? TriangleRadiusRule::geometric() : TriangleRadiusRule::arithmetic());
  };
  const std::vector<Vec4> fan{Vec4(0, 0, 0, 0.8), Vec4(1, -0.1, 0, 0.1), Vec4(1, 0.1, 0, 0.1)};
  const std::vector<Vec4> even{Vec4(0, 0, 0, 0.3), Vec4(1, -0.1, 0, 0.3), Vec4(1, 0.1, 0, 0.3)};
  for (const double r : written_radii(fan, false)) EXPECT_NEAR(r, 1.0 / 3.0, 1e-15);
  for (const double r : written_radii(fan, true)) EXPECT_NEAR(r, 0.2, 1e-15);
  for (const bool geometric : {false, true})
    for (const double r : written_radii(even, geometric)) EXPECT_NEAR(r, 0.3, 1e-15);
}

TEST(MedialMesh, AFanBlendsTheMeansByHowUnequalItsRadiiAre) {
  // The rule with fan_from 1.3 and fan_to 1.6 on q = A / G (A the
  // arithmetic mean, G the geometric), τ = (1 − s) A + s G:
  const TriangleRadiusRule rule{1.3, 1.6};
  // - a fan 0.8, 0.1, 0.1: A = 1/3, G = 0.2, q = 5/3 ≥ 1.6, so s = 1 and
  //   τ = G; 3 ∂τ/∂r = G / r = 0.25, 2, 2;
  const TriangleRadius fan = triangle_radius(0.8, 0.1, 0.1, rule);
  EXPECT_NEAR(fan.tau, 0.2, 1e-15);
  EXPECT_NEAR(fan.thirds[0], 0.25, 1e-14);
  EXPECT_NEAR(fan.thirds[1], 2.0, 1e-14);
  EXPECT_NEAR(fan.thirds[2], 2.0, 1e-14);
  // - close radii 1, 1.2, 1.1: q = 1.1 / ∛1.32 ≈ 1.0028 ≤ 1.3, the
  //   arithmetic mean 1.1 and 3 ∂τ/∂r = 1;
  const TriangleRadius close = triangle_radius(1.0, 1.2, 1.1, rule);
  EXPECT_EQ(close.tau, (1.0 + 1.2 + 1.1) / 3);
  for (const double third : close.thirds) EXPECT_EQ(third, 1.0);
  // - between, 0.125, 1, 1: A = 17/24, G = 1/2, q = 17/12, t = (17/12 −
  //   1.3) / 0.3 = 7/18, s = t² (3 − 2t) = (49/324)(40/18) = 1960/5832,
  //   τ = A − s (A − G) = 17/24 − (1960/5832)(5/24).
  const TriangleRadius between = triangle_radius(0.125, 1.0, 1.0, rule);
  EXPECT_NEAR(between.tau, 17.0 / 24 - (1960.0 / 5832) * (5.0 / 24), 1e-15);
  // Its ∂τ/∂r (the fit's Jacobian) against central differences of τ, in
  // the blend, where s itself moves with the radii.
  const std::array<double, 3> radii{0.125, 1.0, 1.0};
  for (std::size_t v = 0; v < 3; ++v) {
    const double h = 1e-6;
    std::array<double, 3> up = radii, down = radii;
    up[v] += h, down[v] -= h;
    const double difference = (triangle_radius(up[0], up[1], up[2], rule).tau -
                               triangle_radius(down[0], down[1], down[2], rule).tau) /
                              (2 * h);
    EXPECT_NEAR(between.thirds[v] / 3, difference, 1e-8) << "sphere " << v;
  }
  // The written skeleton takes τ by the option's rule.
  for (const double r :
       written_triangle_radii({Vec4(0, 0, 0, 0.125), Vec4(1, -0.1, 0, 1.0), Vec4(1, 0.1, 0, 1.0)}, rule))
    EXPECT_NEAR(r, between.tau, 1e-15);
}

TEST(MedialMesh, ByDefaultOnlyTheSteepestFansTakeTheGeometricMean) {
  // The default rule blends from q = A / G = 2 to 2.5 (A the arithmetic
  // mean, G the geometric):
  // - 0.64, 0.01, 0.01: A = 0.66 / 3 = 0.22, G = ∛(6.4e−5) = 0.04,
  //   q = 5.5: the geometric mean, 0.04;
  // - 0.8, 0.1, 0.1: A = 1/3, G = 0.2, q = 5/3 < 2: the arithmetic, 1/3.
  const auto written_radius = [](const std::vector<Vec4>& spheres) {
    return written_triangle_radii(spheres, ReconstructOptions{}.medial.triangle_radius)[0];
  };
  EXPECT_NEAR(written_radius({Vec4(0, 0, 0, 0.64), Vec4(1, -0.1, 0, 0.01), Vec4(1, 0.1, 0, 0.01)}), 0.04, 1e-15);
  EXPECT_NEAR(written_radius({Vec4(0, 0, 0, 0.8), Vec4(1, -0.1, 0, 0.1), Vec4(1, 0.1, 0, 0.1)}), 1.0 / 3.0, 1e-15);
}

TEST(MedialMesh, SameInputSameBytesInOneProcess) {
  // The command runs the path once per process, the Python module many
  // times in one: the second run must not see anything the first left.
  const TriangleMesh tetrahedron =
      read_mesh(std::filesystem::path(SKELCONV_TEST_DATA) / "reconstruct" / "tetrahedron.off");
  ReconstructOptions o;
  o.method = SkeletonMethod::medial;
  o.medial.budget = 40;
  const std::string first = skeleton_file_text(reconstruct(tetrahedron, o).stages.back(), o);
  EXPECT_EQ(skeleton_file_text(reconstruct(tetrahedron, o).stages.back(), o), first);
}

TEST(MedialFit, PlateIsASheetAndTheFitNeverRaisesTheDistance) {
  // The unit cube flattened to 1 × 1 × 0.2: its medial axis is a sheet.
  TriangleMesh plate = read_mesh(std::filesystem::path(SKELCONV_TEST_DATA) / "reconstruct" / "cube.ply");
  for (Vec3& v : plate.vertices) v.z() *= 0.2;
  ReconstructOptions o;
  o.method = SkeletonMethod::medial;
  const Reconstruction r = reconstruct(plate, o);
  const MedialMesh& m = r.stages.back().medial;
  EXPECT_GT(m.triangles.size(), m.edges.size()) << "a plate is a sheet, not tubes";
  const std::vector<double>& rms = r.medial_path.fit.rms;
  ASSERT_GE(rms.size(), 1u);
  for (std::size_t k = 1; k < rms.size(); ++k) EXPECT_LT(rms[k], rms[k - 1]) << "round " << k;
  // The second stage, on the worst points, lowers their L^p mean round by
  // round from where the first left it.
  const std::vector<double>& worst = r.medial_path.fit.worst;
  ASSERT_GE(worst.size(), 2u) << "the second stage took no round";
  for (std::size_t k = 1; k < worst.size(); ++k) EXPECT_LT(worst[k], worst[k - 1]) << "round " << k;
}

/// The field of a medial mesh as the reconstruction writes it: the skeleton
/// file of a medial stage under options `o`, read back.
MedialField written_field(const ReconstructOptions& o) {
  return [o](const MedialMesh& medial) {
    Stage s;
    s.medial = medial;
    return parse_skeleton_json(skeleton_file_text(s, o));
  };
}

// The stall rule on hand-made objectives, 1% a round over 2 rounds: the
// bound is 0.99² = 0.9801 × the value two rounds before.
TEST(MedialFit, StalledMeansLessThanTheFallARoundOverTheLastRounds) {
  EXPECT_TRUE(fit_stalled({1.0, 0.99, 0.981}, 0.01, 2));
  EXPECT_FALSE(fit_stalled({1.0, 0.99, 0.98}, 0.01, 2));
  // A last round that barely moved after one that fell by half: the two
  // together fell far more than 2%.
  EXPECT_FALSE(fit_stalled({1.0, 0.5, 0.4999}, 0.01, 2));
  EXPECT_TRUE(fit_stalled({1.0, 0.5, 0.4999}, 0.01, 1));
  // Only the last stall_rounds rounds count.
  EXPECT_TRUE(fit_stalled({1.0, 0.2, 0.199, 0.198}, 0.01, 2));
  EXPECT_FALSE(fit_stalled({1.0, 0.9999}, 0.01, 2)) << "fewer rounds than stall_rounds";
  EXPECT_FALSE(fit_stalled({1.0, 1.0, 1.0}, 0.0, 2)) << "no stall rule";
}

// The fit of a sheet of two triangles (four spheres at (±0.4, ±0.4, 0),
// radius 0.07: every face of the plate within the primitives' support) to
// a plate 1 × 1 × 0.2, points on a grid of 1/20 on its faces, under the
// default options (one Newton step, started on first-order distances): a
// sum of two SCALIS triangles rounds the plate's edges and corners, so its
// distance has a floor, which the fit reaches within a few rounds and then
// barely lowers (RMS 0.069 before, 0.023 after five first-order rounds,
// about 0.018 after the Newton rounds; with no stall rule each phase goes on
// to its cap, lowering it by ~0.1% a round). Each phase of the first stage runs
// while its objective falls by its stall fall (the first-order start's, then
// the Newton phase's) a round or more over the stall rounds and stops at the
// first round where it does not, before its cap; the Newton phase starts
// where the first-order one stopped.
TEST(MedialFit, TheFirstStageRunsUntilItStalls) {
  MedialMesh sheet;
  for (const double y : {-0.4, 0.4})
    for (const double x : {-0.4, 0.4}) sheet.spheres.push_back(Vec4(x, y, 0.0, 0.07));
  sheet.triangles = {{0, 1, 3}, {0, 3, 2}};
  const Vec3 half(0.5, 0.5, 0.1);
  std::vector<WeightedPoint> points;
  const double h = 0.05;  // the grid's spacing, 1/20
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const int nu = int(std::lround(2.0 * half[u] / h)), nv = int(std::lround(2.0 * half[v] / h));
    for (const double side : {-1.0, 1.0})
      for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
          Vec3 p;
          p[axis] = side * half[axis];
          p[u] = -half[u] + (i + 0.5) * h, p[v] = -half[v] + (j + 0.5) * h;
          points.push_back({p, h * h});
        }
  }
  const ReconstructOptions o;
  const MedialFitOptions& fit = o.medial.fit;
  ASSERT_EQ(fit.newton_steps, 1);
  ASSERT_TRUE(fit.first_order_start);
  MedialFitReport report;
  fit_medial_mesh(sheet, points, {}, written_field(o), fit, &report);
  ASSERT_GE(report.first_order.size(), 3u) << "no first-order start, or one too short to stall";
  ASSERT_GE(report.rms.size(), 3u) << "no Newton phase, or one too short to stall";
  const struct {
    const std::vector<double>& values;
    int cap;
    double stall_fall;
  } phases[] = {{report.first_order, fit.first_order_rounds, fit.first_order_stall_fall},
                {report.rms, fit.rounds, fit.stall_fall}};
  for (const auto& [values, cap, stall_fall] : phases) {
    for (std::size_t k = 1; k < values.size(); ++k) {
      const std::vector<double> upto(values.begin(), values.begin() + std::ptrdiff_t(k));
      EXPECT_FALSE(fit_stalled(upto, stall_fall, fit.stall_rounds))
          << "went on after round " << k - 1 << " of a stalled stage";
    }
    EXPECT_LT(values.size() - 1, std::size_t(cap)) << "the stage ran to its cap";
    EXPECT_TRUE(fit_stalled(values, stall_fall, fit.stall_rounds)) << "the stage stopped before it stalled";
  }
}

// A ball of radius 1 (an isolated sphere: a compact point primitive,
// f = w (1 − r²/R²)², R = 1.5, w = (1 − 1/1.5²)⁻² = 3.24, f(1) = 1) and
// points 0.5 from its centre, 0.5 inside its surface. There f = 2.56 and
// |∇f| = 2.56: the first-order distance (f − 1)/|∇f| = 0.609 is 22% long.
// Two Newton steps along the gradient land within 10⁻³ of 0.5 (the first
// bounded step 1.56/√(2.56² + 1.56²) = 0.52, the second at r = 1.02 gives
// −0.020).
TEST(MedialFit, NewtonStepsFindTheDistanceInsideABall) {
  MedialMesh ball;
  ball.spheres = {Vec4(0.2, -0.1, 0.3, 1.0)};
  ball.isolated = {0};
  std::vector<WeightedPoint> points;
  for (const Vec3& d : {Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(0, 0.6, 0.8)})
    points.push_back({ball.spheres[0].head<3>() + 0.5 * d, 1.0});
  const ReconstructOptions o;
  const MedialField field_of = written_field(o);
  MedialFitOptions fit;
  fit.rounds = 0, fit.worst_rounds = 0;  // the distance before any round
  MedialFitReport report;
  fit.newton_steps = 0;
  fit_medial_mesh(ball, points, {}, field_of, fit, &report);
  ASSERT_EQ(report.rms.size(), 1u);
  EXPECT_NEAR(report.rms[0], 1.56 / std::hypot(2.56, 1.56), 2e-3) << "one bounded step";
  fit.newton_steps = 2;
  fit_medial_mesh(ball, points, {}, field_of, fit, &report);
  ASSERT_EQ(report.rms.size(), 1u);
  EXPECT_NEAR(report.rms[0], 0.5, 1e-3);
  // The second stage alone takes its own Newton steps: the first stage's
  // distances are first-order, the second's L⁴ mean (of three equal
  // distances: the distance) starts from the Newton distance.
  fit.newton_steps = 0, fit.worst_newton_steps = 2, fit.worst_rounds = 1;
  fit_medial_mesh(ball, points, {}, field_of, fit, &report);
  ASSERT_EQ(report.rms.size(), 1u);
  EXPECT_NEAR(report.rms[0], 1.56 / std::hypot(2.56, 1.56), 2e-3) << "one bounded step";
  ASSERT_GE(report.worst.size(), 1u);
  EXPECT_NEAR(report.worst[0], 0.5, 1e-3);
}

// A cube's sharp corners and edges, where a convolution surface falls
// short: the cube [−0.5, 0.5]³ against one ball of radius ρ = 0.6 at its
// centre (R = 0.9, w = 3.24, f(r) = w (1 − r²/R²)², |f′(r)| = 4 w r/R²
// (1 − r²/R²)), points at its 8 corners (r = 0.8660, true distance ρ − r =
// −0.2660), 12 edge midpoints (r = 0.7071, −0.1071) and 6 face centres
// (r = 0.5, +0.1000), weight 1: the true RMS distance is 0.1714. At a
// corner f = 0.0178 and |∇f| = 1.026: the bounded first-order step is
// −0.9822 / √(1.026² + (0.9822/0.6)²) = −0.5083, 91% long (edge
// midpoints −0.1189, face centres 0.0979; RMS 0.2970). One Newton step
// more, from r = 0.3577 (f = 2.297, |∇f| = 4.825, step +0.2456), lands at
// −0.2627 (edge midpoints −0.1072, face centres 0.1000; RMS 0.1698).
// The fit's first stage measures with that step by default: its distance
// before any round is within 0.003 of the true RMS, the corners' residual
// (0.0033 each, 8 of 26 points).
TEST(MedialFit, TheFirstStageMeasuresSharpCornersWithANewtonStep) {
  MedialMesh ball;
  ball.spheres = {Vec4(0.0, 0.0, 0.0, 0.6)};
  ball.isolated = {0};
  std::vector<WeightedPoint> points;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z)
        if (x != 0 || y != 0 || z != 0) points.push_back({0.5 * Vec3(x, y, z), 1.0});
  ASSERT_EQ(points.size(), 26u);
  const ReconstructOptions o;
  MedialFitOptions fit;
  fit.newton_steps = 1;                  // --medial-newton-steps 1
  fit.rounds = 0, fit.worst_rounds = 0;  // the distance before any round
  MedialFitReport report;
  fit_medial_mesh(ball, points, {}, written_field(o), fit, &report);
  ASSERT_EQ(report.rms.size(), 1u);
  EXPECT_NEAR(report.rms[0], 0.1714, 0.003);
}

// The same ball with three points on its surface (δ = 0) and one inside
// point: where the ball covers it (0.5 from the centre) it counts nothing;
// 1.2 from the centre, outside the ball (a cavity where the input is
// solid), it counts its bounded step: f = 3.24 (1 − 1.44/2.25)² = 0.4199,
// |∇f| = 4 × 3.24 × 0.36 × 1.2 / 2.25 = 2.488, δ = −0.5801 / √(2.488² +
// 0.5801²) = −0.2271, weighted as one surface point: the objective is
// |δ| / √4.
TEST(MedialFit, AnInsidePointCountsOnlyWhenLeftOutside) {
  MedialMesh ball;
  ball.spheres = {Vec4(0.2, -0.1, 0.3, 1.0)};
  ball.isolated = {0};
  const Vec3 centre = ball.spheres[0].head<3>();
  std::vector<WeightedPoint> points;
  for (const Vec3& d : {Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(0, 0.6, 0.8)}) points.push_back({centre + d, 2.0});
  const ReconstructOptions o;
  const MedialField field_of = written_field(o);
  MedialFitOptions fit;
  fit.rounds = 0, fit.worst_rounds = 0;  // the objective before any round
  fit.newton_steps = 0;                  // the bounded step alone, as derived above
  MedialFitReport report;
  fit_medial_mesh(ball, points, {centre + Vec3(0, 0, 0.5)}, field_of, fit, &report);
  ASSERT_EQ(report.rms.size(), 1u);
  EXPECT_NEAR(report.rms[0], 0.0, 1e-9);
  fit_medial_mesh(ball, points, {centre + Vec3(0, 0, 1.2)}, field_of, fit, &report);
  ASSERT_EQ(report.rms.size(), 1u);
  EXPECT_NEAR(report.rms[0], 0.2271 / 2.0, 2e-4);
}

// Points 1.3 from the ball's centre (inside its support, 1.5) pull its
// radius from 1 towards 1.3; a topology test that fails above radius 1.15 (standing in for a neck that
// pinches or a gap that closes) sends the fit back to the last round below
// it, and the fit resumes from there with each step tested: it ends
// between 1 and 1.15, and says from which round it resumed.
TEST(MedialFit, GoesBackToTheLastRoundThatKeepsTheTopology) {
  MedialMesh ball;
  ball.spheres = {Vec4(0.0, 0.0, 0.0, 1.0)};
  ball.isolated = {0};
  std::vector<WeightedPoint> points;
  for (const Vec3& d : {Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(0, 0.6, 0.8), Vec3(-0.8, 0, 0.6)})
    points.push_back({1.3 * d, 1.0});
  const ReconstructOptions o;
  const MedialField field_of = written_field(o);
  MedialFitOptions fit;
  fit.fit_centres = false;
  MedialFitReport report;
  const MedialMesh free = fit_medial_mesh(ball, points, {}, field_of, fit, &report);
  ASSERT_GT(free.spheres[0].w(), 1.15) << "the unconstrained fit must cross the test's limit";
  EXPECT_FALSE(report.rounds_kept.has_value());
  int tests = 0;
  const TopologyError above = [&tests](const MedialMesh& m) { return ++tests, m.spheres[0].w() > 1.15 ? 1LL : 0LL; };
  const MedialMesh kept = fit_medial_mesh(ball, points, {}, field_of, fit, &report, {}, above);
  EXPECT_LE(kept.spheres[0].w(), 1.15);
  EXPECT_GT(kept.spheres[0].w(), 1.0);
  ASSERT_TRUE(report.rounds_kept.has_value());
  EXPECT_LE(tests, 2 + 5 + fit.topology_checks) << "final, unfitted, bisection, tested steps";
}

// The same ball with a topology test that fails at radius 1 (the unfitted
// sphere, as the dino's claws come apart before the fit thickens them) and
// within 10⁻⁸ of the points' 1.3, which the fit's rounds approach far
// closer each time (1 − r/1.3 ≈ 2·10⁻², 4·10⁻⁴, 4·10⁻⁷, 4·10⁻¹⁰, …): the
// unfitted sphere is no closer than the end, so the guard tests the middle
// round (the third of seven), which passes, goes back to it and resumes.
TEST(MedialFit, GoesBackToTheMiddleRoundWhereTheUnfittedSpheresAreNoCloser) {
  MedialMesh ball;
  ball.spheres = {Vec4(0.0, 0.0, 0.0, 1.0)};
  ball.isolated = {0};
  std::vector<WeightedPoint> points;
  for (const Vec3& d : {Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(0, 0.6, 0.8), Vec3(-0.8, 0, 0.6)})
    points.push_back({1.3 * d, 1.0});
  const ReconstructOptions o;
  const MedialField field_of = written_field(o);
  MedialFitOptions fit;
  fit.fit_centres = false;
  fit.newton_steps = 0;  // the first stage's rounds as derived above, on first-order distances
  MedialFitReport report;
  const TopologyError outside = [](const MedialMesh& m) {
    const double r = m.spheres[0].w();
    return r <= 1.0 || r > 1.3 - 1e-8 ? 1LL : 0LL;
  };
  const MedialMesh kept = fit_medial_mesh(ball, points, {}, field_of, fit, &report, {}, outside);
  EXPECT_LE(kept.spheres[0].w(), 1.3 - 1e-8);
  EXPECT_GT(kept.spheres[0].w(), 1.29);
  ASSERT_TRUE(report.rounds_kept.has_value());
  EXPECT_EQ(*report.rounds_kept, 3u);
}

// A flat sheet of spheres 1 apart (a grid of 8 × 4 in z = 0, two triangles
// per square) with one inner square left without its triangles: a hole in
// the medial mesh, as pruning leaves in a thin wall (CGAL's lion's ear).
// At the starting radius 0.6 the four sides' fields cover it (its middle is
// 0.5 from each side); the fit's points, a plate 0.3 thick on either side
// (none over the hole), pull every radius towards 0.3, where the middle is
// beyond every support (1.5 r = 0.45): the fit left alone opens a tunnel.
// The topology error is the meshed surface's against one component of
// genus 0 (the sheet without its hole). Refusing every step that opens the
// hole keeps the sheet near its unfitted radii; holding the spheres about
// the hole lets the far end of the sheet (x ≥ 5, three squares away) reach
// the points as the fit left alone does, the topology kept.
TEST(MedialFit, HoldsTheSpheresAboutAHoleAndTakesTheRestOfTheStep) {
  MedialMesh sheet;
  constexpr int nx = 8, ny = 4;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) sheet.spheres.push_back(Vec4(i, j, 0, 0.6));
  const auto at = [](int i, int j) { return std::int32_t(i * ny + j); };
  for (int i = 0; i + 1 < nx; ++i)
    for (int j = 0; j + 1 < ny; ++j)
      if (!(i == 1 && j == 1))
        sheet.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)}),
            sheet.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
  std::vector<WeightedPoint> points;
  for (double x = 0.0; x <= nx - 1 + 1e-9; x += 0.25)
    for (double y = 0.0; y <= ny - 1 + 1e-9; y += 0.25)
      if (!(x > 1.0 && x < 2.0 && y > 1.0 && y < 2.0))
        for (const double z : {-0.3, 0.3}) points.push_back({Vec3(x, y, z), 1.0});
  ReconstructOptions o;
  const MedialField field_of = written_field(o);
  TriangleMesh box;  // the mesh's bounding region
  box.vertices = {Vec3(-1, -1, -1), Vec3(nx, ny, 1)};
  const double facet = 0.1;
  const auto topology = [&](const MedialMesh& m) {
    Stage s;
    s.name = "medial";
    s.medial = m;
    return mesh_topology(mesh_stage_unprojected(box, s, o, facet));
  };
  int meshings = 0;
  const TopologyError error = [&](const MedialMesh& m) {
    ++meshings;
    const MeshTopology t = topology(m);
    return std::llabs((long long)t.components - 1) + std::llabs(2 - t.euler_characteristic) / 2;
  };
  ASSERT_EQ(error(sheet), 0) << "the unfitted sheet must cover its hole";
  MedialFitOptions fit;
  fit.min_radius = 0.1;
  fit.fit_centres = false;
  MedialFitReport report;
  const MedialMesh free = fit_medial_mesh(sheet, points, {}, field_of, fit, &report);
  ASSERT_EQ(topology(free).euler_characteristic, 0) << "the fit left alone must open the hole";
  const auto far_end = [&](const MedialMesh& m) {
    double sum = 0.0;
    for (int i = 5; i < nx; ++i)
      for (int j = 0; j < ny; ++j) sum += m.spheres[std::size_t(at(i, j))].w();
    return sum / ((nx - 5) * ny);
  };
  ASSERT_LT(far_end(free), 0.45);  // from 0.6
  meshings = 0;
  const MedialMesh kept = fit_medial_mesh(sheet, points, {}, field_of, fit, &report, {}, error);
  const MeshTopology t = topology(kept);
  EXPECT_EQ(t.components, 1u);
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_LT(far_end(kept), 0.45) << "the far end's radii must come down as the unguarded fit's do";
  // The end, the unfitted sheet and the middle round; per repair and once
  // more, a bisection over at most 64 rounds and the end again; then the
  // spheres' and the tested steps' budgets.
  EXPECT_LE(meshings, 3 + (fit.topology_repairs + 1) * (6 + 1) + fit.localize_checks + fit.topology_checks);
  // Every step that opens the hole refused whole: the far end stays near
  // its unfitted radius.
  MedialFitOptions whole = fit;
  whole.localize_checks = 0;
  const MedialMesh refused = fit_medial_mesh(sheet, points, {}, field_of, whole, &report, {}, error);
  EXPECT_EQ(topology(refused).euler_characteristic, 2);
  EXPECT_GT(far_end(refused), 0.45) << "the case must be one that refusing whole steps gets wrong";
}

/// Two unit balls A and B 10 apart, each with four surface points at
/// distance 1.3 from its centre: the fit left alone grows both to about 1.3.
struct TwoBalls {
  MedialMesh balls;
  std::vector<WeightedPoint> points;
};
TwoBalls two_balls_with_points_at_1_3() {
  TwoBalls t;
  t.balls.spheres = {Vec4(0.0, 0.0, 0.0, 1.0), Vec4(10.0, 0.0, 0.0, 1.0)};
  t.balls.isolated = {0, 1};
  for (const Vec3& centre : {Vec3(0, 0, 0), Vec3(10, 0, 0)})
    for (const Vec3& d : {Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(0, 0.6, 0.8), Vec3(-0.8, 0, 0.6)})
      t.points.push_back({centre + 1.3 * d, 1.0});
  return t;
}

// Two balls 10 apart (their supports, 1.5 r, never meet), each with the
// points 1.3 from its centre that pull its radius from 1 towards 1.3:
// the rounds on first-order distances take it to 1.3296 (printed), then
// 1.299999, and on to 1.3. The topology test fails where A's radius is
// above 1.15 or B's between 1.2 and 1.31 (standing in for two thin places
// that each open a hole). The fit's first round fails; its step is
// bisected over the spheres (hold_group 1): A's half fails and is held at
// radius 1, B's passes (1.3296), and the fit runs on with A held. Its next
// round takes B back to 1.299999: the defect opens again, beside the
// sphere held, where no holding can keep it shut. The repair's first round
// is meshed, the repair stops there and the fit goes back to its first
// bisection's round, tested step by step: after B's step alone passed,
// one meshing (of a mesh with A at 1 and B within 1.2–1.31) is all the repair
// spends, where running its rounds to the end meshed the end and bisected
// its rounds again (at least two).
TEST(MedialFit, ARepairWhoseDefectOpensAgainStopsAtItsFirstRound) {
  const auto [balls, points] = two_balls_with_points_at_1_3();
  const ReconstructOptions o;
  const MedialField field_of = written_field(o);
  MedialFitOptions fit;
  fit.fit_centres = false;
  fit.newton_steps = 0;  // the rounds as derived above, on first-order distances
  // No stall rule: with A held, its points' distance (0.3) is most of the
  // objective, and B's rounds, which lower it little, would stop as stalled.
  fit.stall_fall = 0.0;
  fit.hold_group = 1;
  fit.topology_checks = 0;  // the tested resume takes no step: no meshing after the repair's
  MedialFitReport report;
  const MedialMesh free = fit_medial_mesh(balls, points, {}, field_of, fit, &report);
  ASSERT_GT(free.spheres[0].w(), 1.15);
  ASSERT_GT(free.spheres[1].w(), 1.2);
  ASSERT_LT(free.spheres[1].w(), 1.31) << "the fit left alone must open both";
  int after_repair = 0;
  const TopologyError two_places = [&after_repair](const MedialMesh& m) {
    const double a = m.spheres[0].w(), b = m.spheres[1].w();
    if (a == 1.0 && b > 1.2 && b < 1.31) ++after_repair;
    return a > 1.15 || (b > 1.2 && b < 1.31) ? 1LL : 0LL;
  };
  const MedialMesh kept = fit_medial_mesh(balls, points, {}, field_of, fit, &report, {}, two_places);
  EXPECT_EQ(after_repair, 1);
  EXPECT_EQ(two_places(kept), 0);
  // Run to its end, the same repair meshes its end and its rounds again.
  after_repair = 0;
  MedialFitOptions to_the_end = fit;
  to_the_end.repair_watch_rounds = 0;
  fit_medial_mesh(balls, points, {}, field_of, to_the_end, &report, {}, two_places);
  EXPECT_GE(after_repair, 2) << "the case must be one where the repair's end costs meshings";
}

// The same two balls, the topology test failing where A's radius is above
// 1.15 or B's within 10⁻⁶ of 1.3 (two thin places that each open a hole;
// the fit left alone takes both there). The fit's first round fails, so the
// first bisection leaves it at its start; that round's step is split over
// the spheres (hold_group 1): A is held at 1 and B takes its step (1.3296,
// passes). The repair runs on: its first round (B at 1.2995) is watched and
// passes, its next ones (1.2999994, 1.2999999994) do not, and no repair is
// left (topology_repairs 1). The fit goes back with each step tested (none
// here: topology_checks 0), so the result is the round it goes back to: the
// repair's last round that passes (B 1.2995, A 1), its surface points
// closer than at the start, found by bisection over the repair's rounds;
// not the start (both at 1), which threw away every round the repair
// fitted. Neither is farther from the input's topology than the start.
TEST(MedialFit, AFailedRepairGoesBackToItsLastRoundThatKeepsTheTopologyNotToTheStart) {
  const auto [balls, points] = two_balls_with_points_at_1_3();
  const ReconstructOptions o;
  const MedialField field_of = written_field(o);
  MedialFitOptions fit;
  fit.fit_centres = false;
  fit.newton_steps = 0;  // the rounds on first-order distances
  fit.stall_fall = 0.0;  // with A held, B's rounds lower the objective little
  fit.hold_group = 1;
  fit.topology_repairs = 1;
  fit.topology_checks = 0;  // the tested resume takes no step
  MedialFitReport report;
  const TopologyError two_places = [](const MedialMesh& m) {
    const double a = m.spheres[0].w(), b = m.spheres[1].w();
    return a > 1.15 || std::abs(b - 1.3) < 1e-6 ? 1LL : 0LL;
  };
  const MedialMesh free = fit_medial_mesh(balls, points, {}, field_of, fit, &report);
  ASSERT_EQ(two_places(free), 1) << "the fit left alone must open a hole";
  ASSERT_LT(std::abs(free.spheres[1].w() - 1.3), 1e-6) << "the fit left alone must open both";
  std::vector<std::string> lines;
  const auto progress = [&lines](std::string_view line) { lines.emplace_back(line); };
  const MedialMesh kept = fit_medial_mesh(balls, points, {}, field_of, fit, &report, progress, two_places);
  EXPECT_EQ(two_places(kept), 0);
  EXPECT_EQ(kept.spheres[0].w(), 1.0) << "A stays where the repair held it";
  EXPECT_GT(kept.spheres[1].w(), 1.29) << "B where the repair's last round that passes left it, not at the start's 1";
  EXPECT_LT(kept.spheres[1].w(), 1.3 - 1e-6);
  EXPECT_TRUE(std::any_of(lines.begin(), lines.end(), [](const std::string& line) {
    return line.find("the repair's round") != std::string::npos && line.find("resumed after round") != std::string::npos;
  })) << "the progress line must say it went back to the repair's round";
}


// --- The radii kept as a medial axis's (medial_slope.hpp).

// A chain a–b–c, 0.1 apart, whose radii the fit left at 2, 1.5 and 0.1,
// and a triangle b–c–d with d 0.1 from c at radius 1: c bounds b and d by
// 0.1 + 0.1, b bounds a by 0.2 + 0.1. Radii within the bound stay.
TEST(MedialSlope, NoBallInsideItsNeighbour) {
  MedialMesh m;
  m.spheres = {Vec4(0, 0, 0, 2.0), Vec4(0.1, 0, 0, 1.5), Vec4(0.2, 0, 0, 0.1), Vec4(0.2, 0.1, 0, 1.0)};
  m.edges = {{0, 1}, {1, 2}};
  m.triangles = {{1, 2, 3}};
  limit_radius_slope(m, 1.0);
  EXPECT_NEAR(m.spheres[0].w(), 0.3, 1e-12);
  EXPECT_NEAR(m.spheres[1].w(), 0.2, 1e-12);
  EXPECT_EQ(m.spheres[2].w(), 0.1);
  EXPECT_NEAR(m.spheres[3].w(), 0.2, 1e-12);
  const MedialMesh within = m;
  limit_radius_slope(m, 1.0);
  EXPECT_EQ(m.spheres, within.spheres);
}

// A chain e–a–b–c–d, 0.1 apart, whose radii the fit left at 0.1, 1, 0.2,
// 0.1 and 0.05, their centres 2, 1, 0.5, 0.15 and 0.01 from the input's
// surface. Growing (largest first, each to at most its clearance): a (1)
// asks e and b for 0.9; e takes 0.9, b its clearance 0.5; b asks c for 0.4,
// c takes 0.15; c asks d for 0.05, d already has it (and is past its
// clearance: it stays). Shrinking (smallest first): d 0.05 bounds c by
// 0.15 (kept), c bounds b by 0.25, b bounds a by 0.35, a bounds e by 0.45.
// Shrinking alone would end at 0.4, 0.3, 0.2, 0.1, 0.05: every ball but d
// smaller.
TEST(MedialSlope, TheSmallerBallGrowsWithinTheInputFirst) {
  MedialMesh m;
  m.spheres = {Vec4(-0.1, 0, 0, 0.1), Vec4(0, 0, 0, 1.0), Vec4(0.1, 0, 0, 0.2), Vec4(0.2, 0, 0, 0.1),
               Vec4(0.3, 0, 0, 0.05)};
  m.edges = {{0, 1}, {1, 2}, {2, 3}, {3, 4}};
  const std::vector<double> clearance = {2.0, 1.0, 0.5, 0.15, 0.01};
  const Clearance room = [&](const Vec3& centre) {
    for (std::size_t i = 0; i < m.spheres.size(); ++i)
      if (centre == m.spheres[i].head<3>()) return clearance[i];
    ADD_FAILURE() << "a clearance asked at a point that is no sphere's centre";
    return 0.0;
  };
  const std::vector<double> expected = {0.45, 0.35, 0.25, 0.15, 0.05};
  limit_radius_slope(m, 1.0, room);
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(m.spheres[i].w(), expected[i], 1e-12) << "sphere " << i;
  const MedialMesh within = m;
  limit_radius_slope(m, 1.0, room);
  EXPECT_EQ(m.spheres, within.spheres);
}

// --- The step with the radius bound's active edges tied (medial_step.hpp).

// Two spheres 1 apart on x, radii 1 and 2: their edge is at the bound
// (slope 1). A quadratic model of the objective in the 8 unknowns (x0 y0
// z0 r0 x1 y1 z1 r1), Q(Δ) = ½ Σ Δ_i² over r0, r1 (and x1 where it moves)
// + 0.1 Δr0 − 0.3 Δr1: the fit wants r0 down and r1 up, past the bound.
// Untied, the step is the unconstrained minimiser (r0 −0.1, r1 +0.3) and
// the bound then takes r1 to r0 + 1, Δr1 = −0.1: Q = ½(0.01 + 0.01) − 0.01
// + 0.03 = +0.03, uphill; at any damping λ the step is −g / (1 + λ(1 + μ))
// and Q after the bound is a² + 0.2a, a its length, still uphill. Tied
// (Δr1 = Δr0 + Δx1 − Δx0), by hand:
//  - the centres held: Q(φ) = φ² − 0.2 φ, minimised at φ = 0.1 (the
//    feasible minimiser of Q on r1 ≤ r0 + 1, where the bound is active);
//    damped with λ = 1, μ = 1 (diagonal 2 + 1): 5 φ = 0.2, φ = 0.04,
//    Q = 2 × 0.0016 / 2 − 0.008 = −0.0064;
//  - x1 free too, λ = 0: ZᵀHZ over (r0, x1) = [[2, 1], [1, 2]], Zᵀg =
//    (−0.2, −0.3): Δr0 = 1/30, Δx1 = 4/30, Δr1 = 5/30, and r1 is still at
//    the bound after the step (the distance grows by Δx1 exactly).
TEST(MedialStep, ARadiusTiedAtTheBoundTurnsAnUphillStepDownhill) {
  MedialMesh mesh;
  mesh.spheres = {Vec4(0, 0, 0, 1.0), Vec4(1, 0, 0, 2.0)};
  mesh.edges = {{0, 1}};
  const auto equations = [](bool x1_moves) {
    detail::NormalEquations e;
    std::vector<Eigen::Triplet<double>> entries = {{3, 3, 1.0}, {7, 7, 1.0}};
    if (x1_moves) entries.emplace_back(4, 4, 1.0);
    e.normal.resize(8, 8);
    e.normal.setFromTriplets(entries.begin(), entries.end());
    e.gradient = Eigen::VectorXd::Zero(8);
    e.gradient[3] = 0.1, e.gradient[7] = -0.3;
    e.diagonal = e.normal.diagonal();
    return e;
  };
  const auto q = [](const std::array<double, 3>& d) {  // (Δr0, Δr1, Δx1)
    return 0.5 * (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) + 0.1 * d[0] - 0.3 * d[1];
  };
  // The step taken and bounded as the fit does; its (Δr0, Δr1, Δx1) and
  // which sphere bounded each radius.
  const auto take = [&](const Eigen::VectorXd& step, std::vector<std::size_t>* bounded_by) {
    MedialMesh m = mesh;
    for (std::size_t i = 0; i < 2; ++i)
      for (Eigen::Index c = 0; c < 4; ++c) m.spheres[i][c] += step[Eigen::Index(4 * i) + c];
    limit_radius_slope(m, 1.0, {}, bounded_by);
    return std::array<double, 3>{m.spheres[0].w() - 1.0, m.spheres[1].w() - 2.0, m.spheres[1].x() - 1.0};
  };
  // The centres held: the untied step goes uphill at every damping; the
  // bound says sphere 0 bounded sphere 1.
  const std::vector<std::uint8_t> centres_held = {1, 1, 1, 0, 1, 1, 1, 0};
  detail::NormalEquations held = equations(false);
  held.floor = 1.0;
  std::vector<std::size_t> bounded_by;
  for (const double lambda : {0.0, 1.0, 100.0}) {
    const std::array<double, 3> untied = take(detail::damped_solution(held, lambda, centres_held), &bounded_by);
    EXPECT_GT(q(untied), 0.0) << "λ " << lambda;
  }
  EXPECT_EQ(bounded_by, (std::vector<std::size_t>{0, 0}));
  std::vector<std::size_t> tied_to = {0, 1};
  EXPECT_EQ(detail::tie_lowered_radii(tied_to, bounded_by, {}), 1u);
  EXPECT_EQ(tied_to, (std::vector<std::size_t>{0, 0}));
  const Eigen::SparseMatrix<double> z = detail::radius_ties(mesh, tied_to, 1.0, centres_held);
  const std::array<double, 3> tied = take(detail::damped_solution(held, 1.0, centres_held, &z), &bounded_by);
  EXPECT_NEAR(tied[0], 0.04, 1e-12);
  EXPECT_NEAR(tied[1], 0.04, 1e-12);
  EXPECT_NEAR(q(tied), -0.0064, 1e-12);
  // x1 free: the tie follows the centres' distance.
  const std::vector<std::uint8_t> x1_free = {1, 1, 1, 0, 0, 1, 1, 0};
  const Eigen::SparseMatrix<double> z1 = detail::radius_ties(mesh, tied_to, 1.0, x1_free);
  EXPECT_EQ(z1.coeff(7, 3), 1.0);
  EXPECT_EQ(z1.coeff(7, 4), 1.0);
  EXPECT_EQ(z1.coeff(7, 0), 0.0) << "a held centre adds nothing";
  EXPECT_EQ(z1.col(7).nonZeros(), 0) << "a tied radius is no unknown of its own";
  const detail::NormalEquations moving = equations(true);
  EXPECT_GT(q(take(detail::damped_solution(moving, 0.0, x1_free), nullptr)), 0.0);
  const std::array<double, 3> along = take(detail::damped_solution(moving, 0.0, x1_free, &z1), &bounded_by);
  EXPECT_NEAR(along[0], 1.0 / 30.0, 1e-12);
  EXPECT_NEAR(along[2], 4.0 / 30.0, 1e-12);
  EXPECT_NEAR(along[1], 5.0 / 30.0, 1e-12);
  EXPECT_LT(q(along), 0.0);
  // Half the slope: the tie's centre coefficients halve.
  const Eigen::SparseMatrix<double> half = detail::radius_ties(mesh, tied_to, 0.5, {});
  EXPECT_EQ(half.coeff(7, 4), 0.5);
  EXPECT_EQ(half.coeff(7, 0), -0.5);
}

// Ties never close a loop: b bounded by a, a by b (as two passes may
// report) ties b to a and leaves a free; a held sphere is never tied.
TEST(MedialStep, TiesFormNoLoopAndSpareHeldSpheres) {
  std::vector<std::size_t> tied_to = {0, 1, 2};
  EXPECT_EQ(detail::tie_lowered_radii(tied_to, {0, 0, 2}, {}), 1u);
  EXPECT_EQ(detail::tie_lowered_radii(tied_to, {1, 1, 2}, {}), 0u);
  EXPECT_EQ(tied_to, (std::vector<std::size_t>{0, 0, 2}));
  EXPECT_EQ(detail::tie_lowered_radii(tied_to, {0, 0, 1}, {0, 0, 1}), 0u);
  EXPECT_EQ(detail::tie_lowered_radii(tied_to, {0, 0, 1}, {}), 1u);
  EXPECT_EQ(tied_to, (std::vector<std::size_t>{0, 0, 1}));
}

// A foot (a capsule of radius 0.3) with a toe (a slab 0.12 thick, its
// medial sheet 3 × 3 spheres) on a neck of radius 0.013, thinner than the
// measuring mesh's facet (0.0178); the fit's points on the union's
// surface. Left alone, the fit grows the toe's middle sphere to 2.7 times
// its medial ball, its neighbours' balls inside it (on short triangles the
// field falls as the radius grows), and moves the foot's end sphere into
// the neck, the neck's first ball inside it. With the radii kept as a
// medial axis's (the larger ball shrunk, or the smaller first grown within
// the input), no ball holds a neighbour's and the surface is one piece.
// (Here that costs distance: the foot's end cannot reach into the neck,
// and the RMS distance ends at 0.043 against 0.009 left alone.)
TEST(MedialFit, ThinNeckAndSteepConesKeepTheToe) {
  const double neck = 0.013, toe = 0.06, toe_from = 1.4, toe_length = 0.2, toe_half_width = 0.1;
  const auto capsule = [](const Vec3& p, const Vec3& a, const Vec3& b, double r) {
    const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    return (p - (a + t * (b - a))).norm() - r;
  };
  const auto distance = [&](const Vec3& p) {
    const Vec3 q(std::clamp(p.x(), toe_from, toe_from + toe_length), std::clamp(p.y(), -toe_half_width, toe_half_width), 0);
    return std::min({capsule(p, Vec3(0, 0, 0), Vec3(1, 0, 0), 0.3), capsule(p, Vec3(1, 0, 0), Vec3(toe_from, 0, 0), neck),
                     (p - q).norm() - toe});
  };
  // The points: the nodes of a grid of spacing h near the surface, each
  // projected onto it (Newton on the distance), one per cell.
  const double h = 0.03;
  std::vector<WeightedPoint> points;
  std::set<std::array<long, 3>> cells;
  for (double x = -0.35; x <= toe_from + toe_length + 0.1; x += h)
    for (double y = -0.35; y <= 0.35; y += h)
      for (double z = -0.35; z <= 0.35; z += h) {
        Vec3 p(x, y, z);
        if (std::abs(distance(p)) > h) continue;
        for (int k = 0; k < 3; ++k) {
          Vec3 g;
          for (int c = 0; c < 3; ++c) {
            Vec3 q = p, r = p;
            q[c] += 1e-6, r[c] -= 1e-6;
            g[c] = (distance(q) - distance(r)) / 2e-6;
          }
          p -= distance(p) * g / g.squaredNorm();
        }
        const std::array<long, 3> cell{long(std::floor(p.x() / h)), long(std::floor(p.y() / h)), long(std::floor(p.z() / h))};
        if (std::abs(distance(p)) < 1e-6 && cells.insert(cell).second) points.push_back({p, h * h});
      }
  MedialMesh m;
  m.spheres = {Vec4(0, 0, 0, 0.3), Vec4(1, 0, 0, 0.3), Vec4(1.3 - neck - 0.01, 0, 0, neck + 0.01),
               Vec4(toe_from - 0.02, 0, 0, neck)};
  const std::int32_t sheet = 4;  // the toe's 3 × 3 spheres, row by row along x
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m.spheres.push_back(Vec4(toe_from + toe_length * i / 2, toe_half_width * (j - 1), 0, toe));
  m.edges = {{0, 1}, {1, 2}, {2, 3}, {3, sheet + 1}};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const std::int32_t a = sheet + 3 * i + j;
      m.triangles.push_back({a, a + 3, a + 4}), m.triangles.push_back({a, a + 4, a + 1});
    }
  ReconstructOptions o;
  o.measure_divisions = 120;
  const MedialField field_of = written_field(o);
  TriangleMesh box;  // the measure meshes over the input's bounding box
  box.vertices = {Vec3(-0.3, -0.3, -0.3), Vec3(toe_from + toe_length + toe, 0.3, 0.3)};
  MedialFitOptions fit;
  fit.min_radius = 0.75 * (box.vertices[1] - box.vertices[0]).norm() / o.measure_divisions;
  // Whether a ball holds a neighbour's.
  const auto swallows = [](const MedialMesh& f) {
    std::vector<std::array<std::int32_t, 2>> sides(f.edges.begin(), f.edges.end());
    for (const auto& t : f.triangles) sides.push_back({t[0], t[1]}), sides.push_back({t[1], t[2]}), sides.push_back({t[0], t[2]});
    for (const auto& [u, v] : sides) {
      const Vec4 &a = f.spheres[std::size_t(u)], &b = f.spheres[std::size_t(v)];
      if (std::abs(a.w() - b.w()) > (a.head<3>() - b.head<3>()).norm() * (1 + 1e-9)) return true;
    }
    return false;
  };
  MedialFitReport report;
  MedialFitOptions free = fit;
  free.max_radius_slope = std::numeric_limits<double>::infinity();
  ASSERT_TRUE(swallows(fit_medial_mesh(m, points, {}, field_of, free, &report)))
      << "the case must be one the fit left alone gets wrong";
  // Shrinking the larger ball alone, and growing the smaller within the
  // input first (its clearance: the distance to the union's surface).
  const Clearance clearance = [&](const Vec3& p) { return std::max(0.0, -distance(p)); };
  const MedialMesh shrunk = fit_medial_mesh(m, points, {}, field_of, fit, &report);
  const MedialMesh grown = fit_medial_mesh(m, points, {}, field_of, fit, &report, {}, {}, clearance);
  EXPECT_NE(shrunk.spheres, grown.spheres) << "growing within the input must change something here";
  for (const MedialMesh& fitted : {shrunk, grown}) {
    EXPECT_FALSE(swallows(fitted));
    Stage s;
    s.medial = fitted;
    EXPECT_EQ(mesh_topology(mesh_stage(box, s, o)).components, 1u);
  }
}

// --- The fit's derivatives (medial_derivatives.hpp) against central
// differences of the primitives themselves, at points inside, outside and
// across the supports' rims.

/// (field(+h) − field(−h)) / 2h.
template <class Field>
double central(const Field& field, double h) {
  return (field(h) - field(-h)) / (2 * h);
}

/// Points about a triangle or segment: near its plane, beyond its edges, far.
std::vector<Vec3> probe_points() {
  return {Vec3(0.3, 0.2, 0.25), Vec3(0.1, 0.6, -0.4), Vec3(1.1, 0.5, 0.3), Vec3(-0.3, -0.2, 0.1),
          Vec3(0.5, 0.4, 0.05), Vec3(0.9, -0.1, -0.6), Vec3(0.2, 1.05, 0.0)};
}

/// A central difference of step h is off by ~h² f''' and ~ε f / h, both
/// far below 1e-6 here (f and its derivatives are of order 1), and 1e-6 is
/// far below any error in the formulas (which would be of the derivative's
/// own size).
constexpr double derivative_step = 1e-6, derivative_tolerance = 1e-6;

TEST(MedialDerivatives, TriangleVerticesAndRadiusAreTheCentralDifferences) {
  const ScalisKernel kernel = ScalisKernel::compact(4, 1.5);
  const std::array<Vec3, 3> v{Vec3(0, 0, 0), Vec3(1, 0.1, 0), Vec3(0.2, 0.9, 0.15)};
  const double tau = 0.3;
  const ScalisTriangle triangle(v, {tau, tau, tau}, kernel);
  for (const Vec3& p : probe_points()) {
    const PrimitiveDerivatives<3> d = derivatives(triangle, p);
    for (int i = 0; i < 3; ++i)
      for (int c = 0; c < 3; ++c) {
        const double expected = central(
            [&](double h) {
              std::array<Vec3, 3> moved = v;
              moved[std::size_t(i)][c] += h;
              return ScalisTriangle(moved, {tau, tau, tau}, kernel).value(p);
            },
            derivative_step);
        EXPECT_NEAR(d.vertex[std::size_t(i)][c], expected, derivative_tolerance)
            << "vertex " << i << " axis " << c << " at " << p.transpose();
      }
    const double expected = central(
        [&](double h) { return ScalisTriangle(v, {tau + h, tau + h, tau + h}, kernel).value(p); }, derivative_step);
    EXPECT_NEAR(d.radius[0], expected, derivative_tolerance) << "radius at " << p.transpose();
  }
}

TEST(MedialDerivatives, SegmentEndsAndRadiiAreTheCentralDifferences) {
  const ScalisKernel kernel = ScalisKernel::compact(4, 1.5);
  const std::array<Vec3, 2> v{Vec3(0, 0, 0), Vec3(1, 0.2, 0.1)};
  const std::array<double, 2> tau{0.25, 0.4};
  const auto segment = [&](const std::array<Vec3, 2>& e, const std::array<double, 2>& r) {
    return ScalisSegment(e[0], e[1], r[0], r[1], kernel);
  };
  // The radius derivatives are forward differences (relative error ~1e-6),
  // and enter the ends' derivatives along the axis.
  constexpr double forward_tolerance = 1e-5;
  for (const Vec3& p : probe_points()) {
    const PrimitiveDerivatives<2> d = derivatives(segment(v, tau), p);
    for (int i = 0; i < 2; ++i) {
      for (int c = 0; c < 3; ++c) {
        const double expected = central(
            [&](double h) {
              std::array<Vec3, 2> moved = v;
              moved[std::size_t(i)][c] += h;
              return segment(moved, tau).value(p);
            },
            derivative_step);
        EXPECT_NEAR(d.vertex[std::size_t(i)][c], expected, forward_tolerance)
            << "end " << i << " axis " << c << " at " << p.transpose();
      }
      const double expected = central(
          [&](double h) {
            std::array<double, 2> grown = tau;
            grown[std::size_t(i)] += h;
            return segment(v, grown).value(p);
          },
          derivative_step);
      EXPECT_NEAR(d.radius[std::size_t(i)], expected, forward_tolerance) << "radius " << i << " at " << p.transpose();
    }
  }
}

TEST(MedialDerivatives, OtherKernelsAreRefused) {
  const ScalisTriangle cauchy({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, {0.3, 0.3, 0.3},
                              ScalisKernel::cauchy(4, 1.5));
  EXPECT_THROW(derivatives(cauchy, Vec3(0.2, 0.2, 0.3)), InputError);
}

// --- Cavities the fit opens inside a solid (fill_cavities.hpp).

// The twelve edges of the octahedron of vertices (±1, 0, 0), (0, ±1, 0),
// (0, 0, ±1) as tubes of radius 0.4 (SCALIS segments, support 0.6): every
// edge is 0.707 from the centre, so f = 0 there, while at the faces'
// centres (1/3, 1/3, 1/3) f = 2.76 (`skelconv eval`): a closed shell round
// a hollow. Inside a solid ball of radius 1.5 (the input's depth 1.5 − |x|)
// the hollow is the sum's, as the Chinese dragon's: meshed as the guard
// meshes it, 2 components and χ 4 where the input has 1 and χ 2. The ball
// found is at the centre, at most depth / σ = 1 in radius (its support
// inside the input), and one isolated sphere of it closes the hollow: one
// component, χ 2. Where the input is hollow there too (depth
// min(1.5 − |x|, |x| − 0.3)), nothing is filled.
MedialMesh octahedron_shell() {
  MedialMesh shell;
  for (int axis = 0; axis < 3; ++axis)
    for (const double side : {-1.0, 1.0}) {
      Vec4 sphere(0.0, 0.0, 0.0, 0.4);
      sphere[axis] = side;
      shell.spheres.push_back(sphere);
    }
  for (std::int32_t a = 0; a < 6; ++a)
    for (std::int32_t b = a + 1; b < 6; ++b)
      if (a / 2 != b / 2) shell.edges.push_back({a, b});
  return shell;
}

// The surface of `medial` meshed as the guard meshes it (facet `h`), the
// grid's box the input's: a ball of radius 1.5's bounding box.
TriangleMesh meshed_in_box(const MedialMesh& medial, double h) {
  TriangleMesh input;
  input.vertices = {Vec3(-1.5, -1.5, -1.5), Vec3(1.5, 1.5, 1.5), Vec3(1.5, -1.5, 1.5)};
  input.triangles = {{0, 1, 2}};
  Stage stage;
  stage.name = "medial";
  stage.medial = medial;
  return mesh_stage_unprojected(input, stage, ReconstructOptions{}, h);
}

/// `medial` with an isolated sphere `ball` added.
MedialMesh with_sphere(MedialMesh medial, const Vec4& ball) {
  medial.isolated.push_back(std::int32_t(medial.spheres.size()));
  medial.spheres.push_back(ball);
  return medial;
}

TEST(FillCavities, AHollowTheSumOpensInsideASolidIsFilled) {
  const MedialMesh shell = octahedron_shell();
  ASSERT_EQ(shell.edges.size(), 12u);
  ReconstructOptions o;
  const double h = 0.04;
  const TriangleMesh hollow = meshed_in_box(shell, h);
  const MeshTopology before = mesh_topology(hollow);
  ASSERT_EQ(before.components, 2u);
  ASSERT_EQ(before.euler_characteristic, 4);

  const auto solid = [](const Vec3& p) { return 1.5 - p.norm(); };
  const std::vector<skelconv::detail::Cavity> balls =
      skelconv::detail::spurious_cavities(hollow, solid, true, h, o.medial.kernel_sigma);
  ASSERT_EQ(balls.size(), 1u);
  EXPECT_LT(balls[0].ball.head<3>().norm(), h);
  EXPECT_GT(balls[0].ball.w(), 0.3);  // the wall's box is ±0.3 (`skelconv mesh` of the same skeleton)
  EXPECT_LT(balls[0].ball.w(), 0.6);  // the hollow's ball, not the outer wall's (±1.38)
  EXPECT_LE(o.medial.kernel_sigma * balls[0].ball.w(), solid(balls[0].ball.head<3>()) * (1.0 + 1e-12));

  const MeshTopology after = mesh_topology(meshed_in_box(with_sphere(shell, balls[0].ball), h));
  EXPECT_EQ(after.components, 1u);
  EXPECT_EQ(after.euler_characteristic, 2);

  const auto hollow_input = [](const Vec3& p) { return std::min(1.5 - p.norm(), p.norm() - 0.3); };
  EXPECT_TRUE(skelconv::detail::spurious_cavities(hollow, hollow_input, true, h, o.medial.kernel_sigma).empty());
}

// A bubble of air the sum closes over (CGAL's man: under the chin, where
// the result fills the crease's mouth): the octahedron's shell above where
// the input is air at the centre (its signed distance −0.5 there) but
// encloses no empty space anywhere. The shell's inner wall is then a
// component and a χ of 2 that the input has not: the cavity is found at
// the centre, its wall's χ 2, its ball covering the wall's box (±0.3, so
// more than 0.3) and its surface within the shell's solid (ρ less than the
// outer wall's distance along an axis, 1 + 0.4 − a facet at most). One
// isolated sphere of it closes the bubble: one component, χ 2. Where the
// input encloses empty space somewhere, the air at the centre may be its
// own cavity, and nothing is filled.
TEST(FillCavities, ABubbleOfAirTheSumClosesOverIsFilledWhereTheInputEnclosesNone) {
  ReconstructOptions o;
  const double h = 0.04;
  const TriangleMesh bubble = meshed_in_box(octahedron_shell(), h);
  ASSERT_EQ(mesh_topology(bubble).components, 2u);
  ASSERT_EQ(mesh_topology(bubble).euler_characteristic, 4);
  EXPECT_TRUE(skelconv::detail::encloses_empty_space(bubble));

  const auto air = [](const Vec3& p) { return p.norm() - 0.5; };
  const std::vector<skelconv::detail::Cavity> found =
      skelconv::detail::spurious_cavities(bubble, air, false, h, o.medial.kernel_sigma);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].euler_characteristic, 2);
  EXPECT_LT(found[0].ball.head<3>().norm(), h);
  EXPECT_GT(found[0].ball.w(), 0.3);
  EXPECT_LT(found[0].ball.w(), 1.4);

  const MeshTopology after = mesh_topology(meshed_in_box(with_sphere(octahedron_shell(), found[0].ball), h));
  EXPECT_EQ(after.components, 1u);
  EXPECT_EQ(after.euler_characteristic, 2);

  EXPECT_TRUE(skelconv::detail::spurious_cavities(bubble, air, true, h, o.medial.kernel_sigma).empty());
}

// A solid ball's surface encloses no empty space; the octahedron's shell
// meshed (an outer wall and an inner one facing into the hollow) does.
TEST(FillCavities, AHollowSurfaceEnclosesEmptySpaceASolidOneNot) {
  const TriangleMesh ball = meshed_in_box(with_sphere(MedialMesh{}, Vec4(0.0, 0.0, 0.0, 1.0)), 0.1);
  ASSERT_EQ(mesh_topology(ball).components, 1u);
  EXPECT_FALSE(skelconv::detail::encloses_empty_space(ball));
  EXPECT_TRUE(skelconv::detail::encloses_empty_space(meshed_in_box(octahedron_shell(), 0.04)));
}

// An octahedron's surface about `centre` with its vertices `r` out along
// the axes, its triangles facing out (a solid's wall) or, `inward`, in (a
// cavity's wall): 6 vertices, 12 edges, 8 triangles, χ 2.
void add_octahedron(TriangleMesh& mesh, const Vec3& centre, double r, bool inward) {
  const std::int32_t first = std::int32_t(mesh.vertices.size());
  for (int axis = 0; axis < 3; ++axis)
    for (const double side : {1.0, -1.0}) {
      Vec3 v = centre;
      v[axis] += side * r;
      mesh.vertices.push_back(v);
    }
  // Vertices +x 0, −x 1, +y 2, −y 3, +z 4, −z 5; (+x, +y, +z) turns
  // counter-clockwise seen from outside: (−1, 1, 0) × (−1, 0, 1) = (1, 1, 1).
  const std::array<std::array<std::int32_t, 3>, 8> out{
      {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}};
  for (const auto& t : out)
    mesh.triangles.push_back(inward ? std::array<std::int32_t, 3>{first + t[0], first + t[2], first + t[1]}
                                    : std::array<std::int32_t, 3>{first + t[0], first + t[1], first + t[2]});
}

// The guard counts a bubble of a crease's air as the fill leaves it and a
// hollow in the input's solid as a defect. Two shells, each an outer wall
// (an octahedron of radius 1 facing out) about an inner one (radius 0.3,
// facing in), at x = −3 and x = 3: 4 components, χ 8 (four octahedra,
// 6 − 12 + 8 = 2 each). The input is air at the left shell's centre (its
// signed distance |p − (−3, 0, 0)| − 0.5 there, −0.5) and solid at the
// right's (1.5 − |p − (3, 0, 0)|, 1.5), and encloses no empty space: the
// left inner wall is a bubble, the right a hollow, each a component and a
// χ of 2 that the fill takes away. Counted as filled: none 4 components,
// χ 8; the bubble alone 3, χ 6; both 2, χ 4. Where the input encloses
// empty space, the bubble may be its own and is not filled: the bubbles
// alone leave 4, χ 8, and both 3, χ 6.
TEST(FillCavities, TheGuardCountsABubbleOfAirAsFilledAndAHollowInTheSolidAsADefect) {
  TriangleMesh shells;
  add_octahedron(shells, Vec3(-3.0, 0.0, 0.0), 1.0, false);
  add_octahedron(shells, Vec3(-3.0, 0.0, 0.0), 0.3, true);
  add_octahedron(shells, Vec3(3.0, 0.0, 0.0), 1.0, false);
  add_octahedron(shells, Vec3(3.0, 0.0, 0.0), 0.3, true);
  ASSERT_EQ(mesh_topology(shells).components, 4u);
  ASSERT_EQ(mesh_topology(shells).euler_characteristic, 8);
  const auto depth = [](const Vec3& p) {
    return p.x() < 0.0 ? (p - Vec3(-3.0, 0.0, 0.0)).norm() - 0.5 : 1.5 - (p - Vec3(3.0, 0.0, 0.0)).norm();
  };
  ReconstructOptions o;
  const double sigma = o.medial.kernel_sigma, margin = 0.04;
  using reconstruct::GuardFilledCavities;
  using skelconv::detail::topology_after_fill;

  const std::vector<skelconv::detail::Cavity> found =
      skelconv::detail::spurious_cavities(shells, depth, false, margin, sigma);
  ASSERT_EQ(found.size(), 2u);
  for (const auto& cavity : found) {
    EXPECT_EQ(cavity.euler_characteristic, 2);
    EXPECT_NEAR(std::abs(cavity.ball.x()), 3.0, 1e-12);
    EXPECT_EQ(cavity.air, cavity.ball.x() < 0.0);
  }
  const auto counted = [&](const std::vector<skelconv::detail::Cavity>& cavities, GuardFilledCavities which) {
    const MeshTopology t = topology_after_fill(shells, cavities, which);
    return std::pair<std::size_t, long long>(t.components, t.euler_characteristic);
  };
  EXPECT_EQ(counted(found, GuardFilledCavities::none), (std::pair<std::size_t, long long>(4, 8)));
  EXPECT_EQ(counted(found, GuardFilledCavities::air), (std::pair<std::size_t, long long>(3, 6)));
  EXPECT_EQ(counted(found, GuardFilledCavities::all), (std::pair<std::size_t, long long>(2, 4)));

  const std::vector<skelconv::detail::Cavity> hollow_input =
      skelconv::detail::spurious_cavities(shells, depth, true, margin, sigma);
  ASSERT_EQ(hollow_input.size(), 1u);
  EXPECT_FALSE(hollow_input[0].air);
  EXPECT_EQ(counted(hollow_input, GuardFilledCavities::air), (std::pair<std::size_t, long long>(4, 8)));
  EXPECT_EQ(counted(hollow_input, GuardFilledCavities::all), (std::pair<std::size_t, long long>(3, 6)));
}

// --- Tunnels through air (plug_tunnels.hpp).

// A ring of 12 spheres of radius 0.35 on a circle of radius 0.5 about the
// z axis, joined by tube edges: a torus whose hole, 0.13 across at its
// narrowest (the meshed vertices nearest the axis, 3.3 facets), is a pipe of
// air, as homer's mouth sealed at its front is. Meshed as the guard meshes
// it (facet 0.04): one component, χ 0.
MedialMesh narrow_ring() {
  MedialMesh ring;
  constexpr int n = 12;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    ring.spheres.push_back(Vec4(0.5 * std::cos(a), 0.5 * std::sin(a), 0.0, 0.35));
    ring.edges.push_back({std::int32_t(i), std::int32_t((i + 1) % n)});
  }
  return ring;
}

// Taking out a triangle lowers no genus; taking out the triangles whose
// centroids lie within 0.3 of the z axis (the hole's wall, a band round the
// handle: the hole's narrowest ring is 0.067 from the axis, the tube's far
// side 0.067 + 0.7) lowers it by one. A band round a capsule's middle (a
// tube edge from x = −0.5 to 0.5, radius 0.2; the triangles with |x| <
// 0.1) cuts it in two and lowers no genus.
TEST(PlugTunnels, ABandRoundAHandleLowersTheGenusADiscNot) {
  const TriangleMesh ring = meshed_in_box(narrow_ring(), 0.04);
  ASSERT_EQ(mesh_topology(ring).components, 1u);
  ASSERT_EQ(mesh_topology(ring).euler_characteristic, 0);
  EXPECT_EQ(skelconv::detail::genus_drop_doubled(ring, {0}), 0);
  std::vector<std::int32_t> band;
  for (std::size_t t = 0; t < ring.triangles.size(); ++t) {
    Vec3 centroid = Vec3::Zero();
    for (const std::int32_t v : ring.triangles[t]) centroid += ring.vertices[std::size_t(v)] / 3.0;
    if (centroid.head<2>().norm() < 0.3) band.push_back(std::int32_t(t));
  }
  ASSERT_FALSE(band.empty());
  EXPECT_EQ(skelconv::detail::genus_drop_doubled(ring, band), 2);

  MedialMesh stick;
  stick.spheres = {Vec4(-0.5, 0.0, 0.0, 0.2), Vec4(0.5, 0.0, 0.0, 0.2)};
  stick.edges = {{0, 1}};
  const TriangleMesh capsule = meshed_in_box(stick, 0.04);
  ASSERT_EQ(mesh_topology(capsule).euler_characteristic, 2);
  std::vector<std::int32_t> middle;
  for (std::size_t t = 0; t < capsule.triangles.size(); ++t) {
    double x = 0.0;
    for (const std::int32_t v : capsule.triangles[t]) x += capsule.vertices[std::size_t(v)].x() / 3.0;
    if (std::abs(x) < 0.1) middle.push_back(std::int32_t(t));
  }
  ASSERT_FALSE(middle.empty());
  EXPECT_EQ(skelconv::detail::genus_drop_doubled(capsule, middle), 0);
}

// Where the input has no tunnel there (a solid ball of radius 1.5, an
// octahedron's surface), the ring's hole is a tunnel through air too many:
// with boxes of 0.2 a side (5 facets: the hole's wall is wider than the
// boxes of 2 to 4 facets the medial stage tries on homer's sub-facet
// mouth), a plug is found near the z axis, smaller than the tube, and the
// ring meshed again with that isolated sphere has the ball's topology (χ
// 2). Where the input is the ring itself, its hole is the input's own
// tunnel and nothing is plugged.
TEST(PlugTunnels, APipeOfAirTheInputDoesNotHaveIsPlugged) {
  const double h = 0.04;
  const TriangleMesh ring = meshed_in_box(narrow_ring(), h);
  ASSERT_EQ(mesh_topology(ring).euler_characteristic, 0);
  TriangleMesh ball;
  add_octahedron(ball, Vec3::Zero(), 1.5, false);
  const std::vector<Vec4> plugs = skelconv::detail::air_tunnel_plugs(ring, ball, 2.5 * h);
  ASSERT_FALSE(plugs.empty());
  EXPECT_LT(plugs[0].head<2>().norm(), h);
  EXPECT_LT(std::abs(plugs[0].z()), 2.0 * h);
  EXPECT_LT(plugs[0].w(), 0.35);
  const MeshTopology plugged = mesh_topology(meshed_in_box(with_sphere(narrow_ring(), plugs[0]), h));
  EXPECT_EQ(plugged.components, 1u);
  EXPECT_EQ(plugged.euler_characteristic, 2);

  EXPECT_TRUE(skelconv::detail::air_tunnel_plugs(ring, ring, 2.5 * h).empty());
}

// A piece apart (the dino rotated: a toe's tip whose neck the fit thinned
// below the facet): a stick from x = −0.5 to 0.5 of radius 0.2 and an
// isolated sphere of radius 0.1 at x = 1 (its surface from 0.9), whose
// supports (σ = 1.5: out to 0.8 and from 0.85) do not meet. The gap runs
// along the x axis from the stick's cap (its farthest x, read off the
// meshed surface) to the sphere's nearest x; the bridge is the smallest
// ball holding the gap's two nearest vertices: the gap's midpoint and half
// its length, each within the facets' roundings. With it the surface is
// one sphere's topology. The stick's surface alone, and the shell round a
// hollow (a cavity, no piece), are bridged nowhere; with two components
// counted for the input, the two are left apart.
TEST(BridgePieces, APieceApartIsBridgedToTheNearestShell) {
  const double h = 0.04;
  MedialMesh stick;
  stick.spheres = {Vec4(-0.5, 0.0, 0.0, 0.2), Vec4(0.5, 0.0, 0.0, 0.2)};
  stick.edges = {{0, 1}};
  const MedialMesh apart = with_sphere(stick, Vec4(1.0, 0.0, 0.0, 0.1));
  const TriangleMesh two = meshed_in_box(apart, h);
  ASSERT_EQ(mesh_topology(two).components, 2u);
  ASSERT_EQ(mesh_topology(two).euler_characteristic, 4);

  double cap = -1.0, near = 2.0;
  for (const Vec3& v : two.vertices) (v.x() < 0.85 ? cap : near) = v.x() < 0.85 ? std::max(cap, v.x()) : std::min(near, v.x());
  ASSERT_GT(cap, 0.5);
  ASSERT_NEAR(near, 0.9, h);
  const std::vector<Vec4> bridges = skelconv::detail::piece_bridges(two, 1);
  ASSERT_EQ(bridges.size(), 1u);
  EXPECT_NEAR(bridges[0].x(), 0.5 * (cap + near), h);
  EXPECT_LT(bridges[0].head<3>().tail<2>().norm(), h);
  EXPECT_NEAR(bridges[0].w(), 0.5 * (near - cap), h);
  const MeshTopology joined = mesh_topology(meshed_in_box(with_sphere(apart, bridges[0]), h));
  EXPECT_EQ(joined.components, 1u);
  EXPECT_EQ(joined.euler_characteristic, 2);

  EXPECT_TRUE(skelconv::detail::piece_bridges(two, 2).empty());
  EXPECT_TRUE(skelconv::detail::piece_bridges(meshed_in_box(stick, h), 1).empty());
  const TriangleMesh hollow = meshed_in_box(octahedron_shell(), h);
  ASSERT_EQ(mesh_topology(hollow).components, 2u);
  EXPECT_TRUE(skelconv::detail::piece_bridges(hollow, 1).empty());
}

// The smallest ball holding a set of points, against balls known from
// their definition: a far point and a cluster inside the diametral ball of
// it and the cluster's centre (the ball is that diametral ball, centre
// (0.5, 0, 0), radius 0.5; a ball about the points' mean out to the
// farthest is twice as large); a regular tetrahedron's corners with its
// edges' midpoints (its circumsphere, centre 0, radius √3); an obtuse
// triangle's corners (the diametral ball of its longest side); an
// equilateral triangle's corners after points inside it (its circumcircle,
// radius 1).
TEST(PlugTunnels, TheSmallestBallHoldingPoints) {
  using skelconv::detail::smallest_ball;
  const auto expect_ball = [](const Vec4& got, const Vec3& centre, double radius) {
    EXPECT_NEAR((got.head<3>() - centre).norm(), 0.0, 1e-12 * (1.0 + radius));
    EXPECT_NEAR(got.w(), radius, 1e-12 * (1.0 + radius));
  };
  std::vector<Vec3> lopsided;
  for (int i = 0; i < 50; ++i) {
    const double t = 2.0 * std::numbers::pi * i / 50;
    lopsided.push_back(Vec3(0.01, 0.01 * std::cos(t), 0.01 * std::sin(t)));
  }
  lopsided.push_back(Vec3(0.0, 0.0, 0.0));
  lopsided.push_back(Vec3(1.0, 0.0, 0.0));
  expect_ball(smallest_ball(lopsided), Vec3(0.5, 0.0, 0.0), 0.5);

  const std::vector<Vec3> corners{Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)};
  std::vector<Vec3> tetrahedron;
  for (std::size_t i = 0; i < corners.size(); ++i)
    for (std::size_t j = i + 1; j < corners.size(); ++j) tetrahedron.push_back((corners[i] + corners[j]) / 2.0);
  tetrahedron.insert(tetrahedron.end(), corners.begin(), corners.end());
  expect_ball(smallest_ball(tetrahedron), Vec3::Zero(), std::sqrt(3.0));

  expect_ball(smallest_ball({Vec3(0, 0, 0), Vec3(1, 0.2, 0), Vec3(2, 0, 0)}), Vec3(1, 0, 0), 1.0);

  std::vector<Vec3> triangle{Vec3(0.1, 0.1, 0.0), Vec3(-0.2, 0.0, 0.0), Vec3(0.0, -0.3, 0.0)};
  for (int i = 0; i < 3; ++i) {
    const double a = 2.0 * std::numbers::pi * i / 3 + 0.3;
    triangle.push_back(Vec3(std::cos(a), std::sin(a), 0.0));
  }
  expect_ball(smallest_ball(triangle), Vec3::Zero(), 1.0);
  EXPECT_EQ(smallest_ball({}), Vec4::Zero());
}

// Room within the budget for a cavity's sphere: a chain A–B–C–D–E along x
// (A 0, B 1, C 1.05, D 2, E 2.01, radii 0.1). D–E is the shortest edge but
// E is on no other, and A–B would leave A on none. B–C (0.05 long) and
// C–D (0.95) can go without leaving a sphere bare; B–C is the smaller
// support and goes first, and then C is on C–D alone. Asked for two, it
// drops the one and says so.
TEST(FillCavities, RoomIsMadeWithoutLeavingASphereBare) {
  MedialMesh chain;
  for (const double x : {0.0, 1.0, 1.05, 2.0, 2.01}) chain.spheres.push_back(Vec4(x, 0.0, 0.0, 0.1));
  chain.edges = {{0, 1}, {1, 2}, {2, 3}, {3, 4}};
  EXPECT_EQ(skelconv::detail::drop_smallest_primitives(chain, 2, 1.5), 1u);
  const std::vector<std::array<std::int32_t, 2>> left{{0, 1}, {2, 3}, {3, 4}};
  EXPECT_EQ(chain.edges, left);
  EXPECT_EQ(chain.spheres.size(), 5u);
}

}  // namespace
}  // namespace skelconv::reconstruct
