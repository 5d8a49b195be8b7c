// Unit tests of the reconstruction algorithms (include/skelconv/reconstruct/,
// docs/reconstruction.md) on small cases whose answers are derived by hand
// in the comments, and of the mesh reader on files written by write_mesh and
// by hand.
#include <algorithm>
#include <cmath>
#include <tuple>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <numeric>
#include <cstring>

#include <gtest/gtest.h>

#include "skelconv/errors.hpp"
#include "skelconv/mesh/mesh_reader.hpp"
#include "skelconv/reconstruct/branch_graph.hpp"
#include "skelconv/reconstruct/bspline.hpp"
#include "skelconv/reconstruct/medial_graph.hpp"
#include "skelconv/reconstruct/pavlidis.hpp"
#include "skelconv/reconstruct/pruning.hpp"
#include "src/reconstruct/thin_walls.hpp"

namespace skelconv::reconstruct {
namespace {

// An equilateral triangle v, p⁻, p⁺ of side 1: |vp±| = ρ = 1 and
// |p⁻p⁺| = 1, so θ = 2 asin(1/2) = π/3 (the triangle's angle at v).
TEST(PruningAngle, EquilateralTriangleIsSixtyDegrees) {
  const Vec3 v(0, 0, 0), p_minus(1, 0, 0), p_plus(0.5, std::sqrt(3.0) / 2, 0);
  EXPECT_NEAR(pruning_angle(p_minus, p_plus, (p_minus - v).norm()), std::numbers::pi / 3, 1e-15);
}

// A right isosceles triangle at v: |p⁻p⁺| = √2 ρ, θ = 2 asin(√2/2) = π/2;
// a diameter gives π.
TEST(PruningAngle, RightAngleAndDiameter) {
  EXPECT_NEAR(pruning_angle(Vec3(2, 0, 0), Vec3(0, 2, 0), 2.0), std::numbers::pi / 2, 1e-15);
  EXPECT_NEAR(pruning_angle(Vec3(-1, 0, 0), Vec3(1, 0, 0), 1.0), std::numbers::pi, 1e-15);
}

// The vertex angle uses the longest edge of the tetrahedron: a ball of
// radius 1 at the origin touching (±1, 0, 0) and two close samples sees a
// diameter, θ = π, and is kept by any threshold below π; a ball touching
// four samples within 0.1 of each other sees θ ≤ 2 asin(0.05 × √2) ≈ 8°.
TEST(Pruning, VertexAngleAndRemoval) {
  MedialGraph graph;
  graph.samples = {Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0.995, 0.0998749),
                   Vec3(0.0998749, 0.995, 0), Vec3(0, 0.99, 0.14)};
  graph.vertices.push_back({Vec3::Zero(), 1.0, {0, 1, 2, 3}});
  graph.vertices.push_back({Vec3::Zero(), 1.0, {2, 3, 4, 5}});
  graph.edges.push_back({0, 1, {2, 3, 0}});
  EXPECT_NEAR(vertex_angle(graph, 0), std::numbers::pi, 1e-12);
  EXPECT_LT(vertex_angle(graph, 1), 10.0 * std::numbers::pi / 180);
  const PruningReport report = prune_medial_graph(graph, std::numbers::pi / 4);
  EXPECT_EQ(report.vertices_removed, 1u);
  ASSERT_EQ(graph.vertices.size(), 1u);
  EXPECT_EQ(graph.vertices[0].samples[0], 0);
  EXPECT_TRUE(graph.edges.empty());
}

// The contact span is the longest edge of the tetrahedron: 2 for the ball
// of radius 1 touching (±1, 0, 0); 0.2 for the ball of radius 0.1 at
// (5, 0, 0) touching (5 ± 0.1, 0, 0), whose θ is π too (a diameter: kept by
// the angle), but a minimum span of 0.5 removes it; the large ball stays.
TEST(Pruning, ContactSpan) {
  MedialGraph graph;
  graph.samples = {Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0),   Vec3(0, 0, 1),
                   Vec3(4.9, 0, 0), Vec3(5.1, 0, 0), Vec3(5, 0.1, 0), Vec3(5, 0, 0.1)};
  graph.vertices.push_back({Vec3::Zero(), 1.0, {0, 1, 2, 3}});
  graph.vertices.push_back({Vec3(5, 0, 0), 0.1, {4, 5, 6, 7}});
  EXPECT_NEAR(contact_span(graph, 0), 2.0, 1e-15);
  EXPECT_NEAR(contact_span(graph, 1), 0.2, 1e-15);
  EXPECT_NEAR(vertex_angle(graph, 1), std::numbers::pi, 1e-6);
  MedialGraph kept = graph;
  EXPECT_EQ(prune_medial_graph(kept, std::numbers::pi / 2, 0.0).vertices_removed, 0u);
  const PruningReport report = prune_medial_graph(graph, std::numbers::pi / 2, 0.0, 0.5);
  EXPECT_EQ(report.vertices_removed, 1u);
  ASSERT_EQ(graph.vertices.size(), 1u);
  EXPECT_EQ(graph.vertices[0].radius, 1.0);
}

/// A medial vertex at `centre` of `radius`, its four contact samples on the
/// sphere (two opposite along x, one along y, one along z).
void add_ball(MedialGraph& graph, const Vec3& centre, double radius) {
  const auto first = std::int32_t(graph.samples.size());
  graph.samples.push_back(centre - Vec3(radius, 0, 0));
  graph.samples.push_back(centre + Vec3(radius, 0, 0));
  graph.samples.push_back(centre + Vec3(0, radius, 0));
  graph.samples.push_back(centre + Vec3(0, 0, radius));
  graph.vertices.push_back({centre, radius, {first, first + 1, first + 2, first + 3}});
}

/// The large piece of the islands tests: `count` balls of radius 1 along x,
/// `step` apart from the origin, each joined to the next.
void add_chain(MedialGraph& graph, int count, double step) {
  const auto first = std::int32_t(graph.vertices.size());
  for (int i = 0; i < count; ++i) add_ball(graph, Vec3(step * i, 0, 0), 1.0);
  for (std::int32_t i = 0; i + 1 < count; ++i) graph.edges.push_back({first + i, first + i + 1, {0, 1, 2}});
}

// The islands rule and its lobes: a chain of 40 balls of radius 1 along x
// (centres (i, 0, 0), each touching a diameter, θ = π) is the large piece;
// three single vertices are islands (1 < 5% of 40). A ball of radius 2 at
// (45, 0, 0) is deep (2 ≥ 0.5 × 1) and outside the chain: the nearest
// chain ball, centre 39, reaches 1 − 6 = −5 at its centre, so it reaches
// 2 + 5 = 7 ≥ 0.5 × 2 beyond: kept. A ball of radius 1 at (20, 0.2, 0) is
// deep but inside: the chain ball at 20 reaches 1 − 0.2 = 0.8 at its
// centre, 1 − 0.8 = 0.2 < 0.5 beyond: dropped. A ball of radius 0.2 at
// (60, 0, 0) is shallow (0.2 < 0.5): dropped. Without lobes all three go.
TEST(Pruning, SmallPiecesKeptAsLobes) {
  MedialGraph graph;
  const auto add = [&graph](const Vec3& centre, double radius) { add_ball(graph, centre, radius); };
  add_chain(graph, 40, 1.0);
  add(Vec3(45, 0, 0), 2.0);
  add(Vec3(20, 0.2, 0), 1.0);
  add(Vec3(60, 0, 0), 0.2);
  MedialGraph without = graph;
  const PruningReport dropped = prune_medial_graph(without, std::numbers::pi / 4);
  EXPECT_EQ(dropped.small_pieces_removed, 3u);
  EXPECT_EQ(dropped.lobes_kept, 0u);
  EXPECT_EQ(without.vertices.size(), 40u);
  const PruningReport report = prune_medial_graph(graph, std::numbers::pi / 4, 0.05, 0.0, LobeOptions{0.5, 0.5});
  EXPECT_EQ(report.vertices_removed, 0u);
  EXPECT_EQ(report.small_pieces_removed, 2u);
  EXPECT_EQ(report.lobes_kept, 1u);
  ASSERT_EQ(graph.vertices.size(), 41u);
  EXPECT_EQ(graph.vertices[40].centre, Vec3(45, 0, 0));
  EXPECT_EQ(graph.edges.size(), 39u);
}

// The islands rule and its tips: a chain of 100 balls of radius 1 along x
// (centres (0.4 i, 0, 0), each touching a diameter, θ = π) is the large
// piece; four small pieces (under 5% of 100 vertices) stand off it.
// - A teat: three balls of radius 0.1 at (20, 1.3 / 1.5 / 1.7, 0), joined.
//   The chain ball at (20, 0, 0) is the nearest: at the last centre it
//   reaches 1 − 1.7 = −0.7, so that ball reaches 0.1 + 0.7 = 0.8 beyond,
//   at least 0.5 and 2 × 0.1: kept.
// - Noise on the body's boundary: radius 0.2 at (10, 1, 0), held 1 − 1 = 0
//   deep by the chain ball at x = 10: reaches 0.2, its own radius: dropped.
// - Thick and short: radius 0.4 at (30, 1.2, 0): reaches 0.4 + 0.2 = 0.6 ≥
//   0.5 but under 2 × 0.4 = 0.8: dropped.
// - Thin and short: radius 0.05 at (4.8, 1.1, 0): reaches 0.05 + 0.1 = 0.15
//   ≥ 2 × 0.05 but under 0.5: dropped.
// Without tips (reach 0) all four go, the teat with them.
TEST(Pruning, SmallPiecesKeptAsThinProtrusions) {
  MedialGraph graph;
  const auto add = [&graph](const Vec3& centre, double radius) { add_ball(graph, centre, radius); };
  add_chain(graph, 100, 0.4);
  for (const double y : {1.3, 1.5, 1.7}) add(Vec3(20, y, 0), 0.1);
  graph.edges.push_back({100, 101, {0, 1, 2}});
  graph.edges.push_back({101, 102, {0, 1, 2}});
  add(Vec3(10, 1, 0), 0.2);
  add(Vec3(30, 1.2, 0), 0.4);
  add(Vec3(4.8, 1.1, 0), 0.05);
  MedialGraph without = graph;
  const PruningReport dropped = prune_medial_graph(without, std::numbers::pi / 4);
  EXPECT_EQ(dropped.small_pieces_removed, 4u);
  EXPECT_EQ(dropped.tips_kept, 0u);
  EXPECT_EQ(without.vertices.size(), 100u);
  const PruningReport report = prune_medial_graph(graph, std::numbers::pi / 4, 0.05, 0.0, LobeOptions{}, TipOptions{0.5, 2.0});
  EXPECT_EQ(report.vertices_removed, 0u);
  EXPECT_EQ(report.small_pieces_removed, 3u);
  EXPECT_EQ(report.tips_kept, 1u);
  ASSERT_EQ(graph.vertices.size(), 103u);
  EXPECT_EQ(graph.vertices[102].centre, Vec3(20, 1.7, 0));
  EXPECT_EQ(graph.edges.size(), 101u);
}

/// A medial vertex at `centre` of `radius` whose four contact samples lie
/// within a cap of the sphere about +z, 0.1 × radius from its pole: its
/// contacts span at most 0.2 × radius, θ ≤ 2 asin(0.1) ≈ 11.5°, pruned by
/// any angle above that.
void add_shallow_ball(MedialGraph& graph, const Vec3& centre, double radius) {
  const auto first = std::int32_t(graph.samples.size());
  const double side = 0.1 * radius, up = std::sqrt(radius * radius - side * side);
  graph.samples.push_back(centre + Vec3(side, 0, up));
  graph.samples.push_back(centre + Vec3(-side, 0, up));
  graph.samples.push_back(centre + Vec3(0, side, up));
  graph.samples.push_back(centre + Vec3(0, 0, radius));
  graph.vertices.push_back({centre, radius, {first, first + 1, first + 2, first + 3}});
}

/// The number of connected pieces of `graph` (its vertices joined by its edges).
std::size_t graph_pieces(const MedialGraph& graph) {
  std::vector<std::size_t> parent(graph.vertices.size());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  const auto find = [&parent](std::size_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const MedialEdge& e : graph.edges) parent[find(std::size_t(e.a))] = find(std::size_t(e.b));
  std::size_t count = 0;
  for (std::size_t v = 0; v < parent.size(); ++v) count += find(v) == v;
  return count;
}

// A tail the angle cut in the middle, joined to the body again along its
// pruned medial path. The body is the chain of 100 balls of radius 1 along
// x (centres (0.4 i, 0, 0); vertex 50 at (20, 0, 0)). The tail hangs from
// vertex 50 along y: two vertices the angle prunes (radius 0.1 at (20, 1.1,
// 0) and (20, 1.3, 0), contacts within 0.02: θ ≈ 11.5° < 45°), then the
// tail's end, three balls of radius 0.1 at y = 1.5, 1.7, 1.9 (θ = π), a
// small piece (3 < 5% of 100) reaching 0.1 + (1.9 − 1) = 1.0 beyond the
// chain: kept as a tip. Edges 50 – 1.1 – 1.3 – 1.5 – 1.7 – 1.9, and a
// detour from the tail's end (20, 1.5, 0) through a pruned vertex at (21.5,
// 1.5, 0) to the chain's vertex 52 at (20.8, 0, 0): 1.5 + √(0.7² + 1.5²) ≈
// 3.16 long, against 0.2 + 0.2 + 1.1 = 1.5 through the cut. Two more tips
// with no edge to the rest, out of the graph's reach:
// - a tail whose graph broke off: balls of radius 0.1 at (10, 1.05 / 1.25
//   / 1.45, 0), reaching 0.1 + 0.45 beyond the chain. Its first ball
//   overlaps the chain's vertex 25 at (10, 0, 0) (1.05 < 1 + 0.1) and no
//   other (the chain's next centres are √(0.4² + 1.05²) ≈ 1.124 away):
//   bridged by the edge 25 – 106;
// - a teat at (30, 1.3 / 1.5 / 1.7, 0): its nearest chain ball, at (30, 0,
//   0), is 1.3 > 1 + 0.1 away: no overlap; the tube between them passes
//   that ball's sample at (30, 1, 0), the body's surface: it stays apart.
// Without `connect`: 100 + 3 + 3 + 3 vertices in four pieces. With it: the
// two cut vertices come back (not the detour's), 111 vertices, the two
// tails one piece with the body: two pieces, 99 + 5 + (1 + 2) + 2 edges.
TEST(Pruning, ThinProtrusionsAreJoinedToTheBodyAlongTheirPrunedPath) {
  MedialGraph graph;
  add_chain(graph, 100, 0.4);
  add_shallow_ball(graph, Vec3(20, 1.1, 0), 0.1);  // 100
  add_shallow_ball(graph, Vec3(20, 1.3, 0), 0.1);  // 101
  for (const double y : {1.5, 1.7, 1.9}) add_ball(graph, Vec3(20, y, 0), 0.1);  // 102, 103, 104
  add_shallow_ball(graph, Vec3(21.5, 1.5, 0), 0.1);  // 105, the detour
  for (const double y : {1.05, 1.25, 1.45}) add_ball(graph, Vec3(10, y, 0), 0.1);  // 106, 107, 108
  for (const double y : {1.3, 1.5, 1.7}) add_ball(graph, Vec3(30, y, 0), 0.1);  // 109, 110, 111
  for (const auto& [a, b] : {std::pair{50, 100}, {100, 101}, {101, 102}, {102, 103}, {103, 104}, {102, 105},
                             {105, 52}, {106, 107}, {107, 108}, {109, 110}, {110, 111}})
    graph.edges.push_back({a, b, {0, 1, 2}});
  MedialGraph apart = graph;
  const PruningReport kept_apart =
      prune_medial_graph(apart, std::numbers::pi / 4, 0.05, 0.0, LobeOptions{}, TipOptions{0.5, 2.0, false});
  EXPECT_EQ(kept_apart.vertices_removed, 3u);
  EXPECT_EQ(kept_apart.tips_kept, 3u);
  EXPECT_EQ(kept_apart.tips_connected + kept_apart.tips_bridged, 0u);
  EXPECT_EQ(apart.vertices.size(), 109u);
  EXPECT_EQ(graph_pieces(apart), 4u);
  const PruningReport report =
      prune_medial_graph(graph, std::numbers::pi / 4, 0.05, 0.0, LobeOptions{}, TipOptions{0.5, 2.0, true});
  EXPECT_EQ(report.tips_kept, 3u);
  EXPECT_EQ(report.tips_connected, 1u);
  EXPECT_EQ(report.connecting_vertices, 2u);
  EXPECT_EQ(report.tips_bridged, 1u);
  ASSERT_EQ(graph.vertices.size(), 111u);
  EXPECT_EQ(graph.vertices[100].centre, Vec3(20, 1.1, 0));
  EXPECT_EQ(graph.vertices[101].centre, Vec3(20, 1.3, 0));
  EXPECT_EQ(graph.vertices[105].centre, Vec3(10, 1.05, 0));
  EXPECT_EQ(graph.vertices[108].centre, Vec3(30, 1.3, 0));
  ASSERT_EQ(graph.edges.size(), 109u);
  EXPECT_EQ(graph.edges.back().a, 25);
  EXPECT_EQ(graph.edges.back().b, 105);
  EXPECT_EQ(graph_pieces(graph), 2u);
}

/// A medial vertex at `centre` of `radius` inside a tube along `axis` (in
/// the xy plane): its four contact samples on the tube's wall, across two
/// diameters perpendicular to the axis (θ = π).
void add_tube_ball(MedialGraph& graph, const Vec3& centre, double radius, const Vec3& axis) {
  const auto first = std::int32_t(graph.samples.size());
  const Vec3 u = axis.cross(Vec3::UnitZ()).normalized(), w = Vec3::UnitZ();
  for (const Vec3& d : {u, Vec3(-u), w, Vec3(-w)}) graph.samples.push_back(centre + radius * d);
  graph.vertices.push_back({centre, radius, {first, first + 1, first + 2, first + 3}});
}

// A bent horn whose two tip pieces neither meet the body in the graph nor
// overlap its balls, each ball's samples on the horn's wall across its way
// (A's along y, B's along the way from A). The body: 60 balls of radius 1 along x, 2 apart
// (vertex 10 at (20, 0, 0)). The horn leaves it along −y: A, radius 0.2 at
// (20, −1.5, 0) (gap 1.5 − 1.2 = 0.3 to vertex 10, its nearest), then bends
// to its end B, radius 0.1 at (20.8, −3, 0). B's nearest body ball is
// vertex 10 (gap √(0.8² + 3²) − 1.1 ≈ 2.005; vertex 11 at (22, 0, 0): 2.13),
// but the straight tube to it passes a sample of the horn's bend at (20.4,
// −1.5, 0), its midpoint, where the tube's radius is 0.55: across air. A
// is bridged to vertex 10 (the tube clear: that sample 0.4 from A's
// centre, at least 0.47 from the tube's axis where its half radius is under
// 0.17); then B's nearest held ball is A (gap √(0.8² + 1.5²) − 0.3 = 1.4),
// the tube between them clear (the bend's sample 0.35 from its axis, half
// radii under 0.1): bridged. Both tips joined: one piece, edges 10 – 60 and
// 60 – 61. Were bridged pieces not to anchor the next round, B would stay
// apart; were the tube not tested, B would join the body straight across
// the bend.
TEST(Pruning, ABentHornsPiecesAreBridgedInAChainFromTheBody) {
  MedialGraph graph;
  add_chain(graph, 60, 2.0);
  add_tube_ball(graph, Vec3(20, -1.5, 0), 0.2, Vec3(0, 1, 0));     // 60, A
  add_tube_ball(graph, Vec3(20.8, -3, 0), 0.1, Vec3(0.8, -1.5, 0));  // 61, B, its wall across the way from A
  graph.samples.push_back(Vec3(20.4, -1.5, 0));     // the bend's wall
  MedialGraph apart = graph;
  const PruningReport kept_apart =
      prune_medial_graph(apart, std::numbers::pi / 4, 0.05, 0.0, LobeOptions{}, TipOptions{0.5, 2.0, false});
  EXPECT_EQ(kept_apart.tips_kept, 2u);
  EXPECT_EQ(graph_pieces(apart), 3u);
  const PruningReport report =
      prune_medial_graph(graph, std::numbers::pi / 4, 0.05, 0.0, LobeOptions{}, TipOptions{0.5, 2.0, true});
  EXPECT_EQ(report.tips_kept, 2u);
  EXPECT_EQ(report.tips_connected, 0u);
  EXPECT_EQ(report.tips_bridged, 2u);
  ASSERT_EQ(graph.vertices.size(), 62u);
  ASSERT_EQ(graph.edges.size(), 61u);
  EXPECT_EQ(graph.edges[59].a, 10);
  EXPECT_EQ(graph.edges[59].b, 60);
  EXPECT_EQ(graph.edges[60].a, 60);
  EXPECT_EQ(graph.edges[60].b, 61);
  EXPECT_EQ(graph_pieces(graph), 1u);
}

// The islands rule measures a piece against the largest piece of its own
// part of the surface: the chain of 40 balls (part 0) and, 100 away, a
// separate small part (part 1, a bone beside a foot) whose medial graph is
// one piece of 1 ball, with one noise vertex beside the chain (part 0).
// With one part all 2 are islands (1 < 5% of 40); with the parts given, the
// small part's piece is its part's largest and stays, the noise goes. A
// vertex's part is the one most of its samples lie on: the noise vertex has
// 3 of 4 samples in part 0.
TEST(Pruning, SeparatePartsKeepTheirLargestPiece) {
  MedialGraph graph;
  const auto add = [&graph](const Vec3& centre, double radius, std::int32_t part, std::int32_t odd_part = -1) {
    const auto first = std::int32_t(graph.samples.size());
    graph.samples.push_back(centre - Vec3(radius, 0, 0));
    graph.samples.push_back(centre + Vec3(radius, 0, 0));
    graph.samples.push_back(centre + Vec3(0, radius, 0));
    graph.samples.push_back(centre + Vec3(0, 0, radius));
    for (int k = 0; k < 4; ++k) graph.sample_parts.push_back(k == 3 && odd_part >= 0 ? odd_part : part);
    graph.vertices.push_back({centre, radius, {first, first + 1, first + 2, first + 3}});
  };
  for (int i = 0; i < 40; ++i) add(Vec3(i, 0, 0), 1.0, 0);
  for (std::int32_t i = 0; i + 1 < 40; ++i) graph.edges.push_back({i, i + 1, {0, 1, 2}});
  add(Vec3(140, 0, 0), 0.3, 1);
  add(Vec3(20, 1.5, 0), 0.1, 0, 1);
  MedialGraph one_part = graph;
  one_part.sample_parts.clear();
  EXPECT_EQ(prune_medial_graph(one_part, std::numbers::pi / 4).small_pieces_removed, 2u);
  EXPECT_EQ(one_part.vertices.size(), 40u);
  const PruningReport report = prune_medial_graph(graph, std::numbers::pi / 4);
  EXPECT_EQ(report.small_pieces_removed, 1u);
  ASSERT_EQ(graph.vertices.size(), 41u);
  EXPECT_EQ(graph.vertices[40].centre, Vec3(140, 0, 0));
}

// The parts of a surface of two closed pieces (the unit tetrahedron and a
// copy 10 to the side): every sample of the first is in part 0, of the
// second in part 1; one piece alone has no parts (empty).
TEST(MedialGraph, SamplesKnowTheirPart) {
  const TriangleMesh one = read_mesh(std::string(SKELCONV_TEST_DATA) + "/reconstruct/tetrahedron.obj");
  TriangleMesh two = one;
  const auto n = std::int32_t(one.vertices.size());
  for (const Vec3& v : one.vertices) two.vertices.push_back(v + Vec3(10, 0, 0));
  for (auto t : one.triangles) {
    for (auto& i : t) i += n;
    two.triangles.push_back(t);
  }
  EXPECT_TRUE(medial_graph(one).sample_parts.empty());
  const MedialGraph graph = medial_graph(two);
  ASSERT_EQ(graph.sample_parts.size(), graph.samples.size());
  for (std::size_t k = 0; k < graph.samples.size(); ++k)
    EXPECT_EQ(graph.sample_parts[k], graph.samples[k].x() > 5 ? 1 : 0) << k;
}

// Flat faces sampled on a grid give Delaunay slivers, four samples within
// rounding of a plane, whose circumcentre cannot be computed in double (CGAL
// asserts on them where its assertions are on, and returns an infinite or
// arbitrary point where they are off). The graph leaves them out: every
// Voronoi vertex it keeps is finite and equidistant from its four samples.
TEST(MedialGraph, FlatFacesGiveFiniteEquidistantVertices) {
  for (const char* name : {"tetrahedron.obj", "cube.ply"}) {
    const MedialGraph graph = medial_graph(read_mesh(std::string(SKELCONV_TEST_DATA) + "/reconstruct/" + name));
    ASSERT_FALSE(graph.vertices.empty()) << name;
    for (const MedialVertex& v : graph.vertices) {
      ASSERT_TRUE(v.centre.allFinite() && std::isfinite(v.radius)) << name;
      for (int k = 1; k < 4; ++k) {
        const double r = (v.centre - graph.samples[std::size_t(v.samples[k])]).norm();
        ASSERT_NEAR(r, v.radius, 1e-9 * (1 + v.radius)) << name;
      }
    }
  }
}

/// find_thin_walls on `name` as the medial stage calls it: samples the
/// diagonal / 40 apart, the graph pruned at 90°, thin below 0.75 spacings.
detail::ThinWalls thin_walls_of(const char* name) {
  const TriangleMesh mesh = read_mesh(std::string(SKELCONV_TEST_DATA) + "/reconstruct/" + name);
  Vec3 lo = mesh.vertices.front(), hi = lo;
  for (const Vec3& v : mesh.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  SamplingOptions sampling;
  sampling.diagonal_divisions = 40.0;
  MedialGraph graph = medial_graph(mesh, 20, sampling);
  prune_medial_graph(graph, std::numbers::pi / 2);
  return detail::find_thin_walls(mesh, graph, sampling, (hi - lo).norm() / 40.0, 0.75, 2.5);
}

// The plate 1 × 1 × 0.03 (diagonal 1.4145, spacing h = 0.0354): a wall of
// half-thickness 0.015 = 0.42 h, its sheet far wider than R = 3 h: one
// wall, every one of its 12 triangles sampled finer, at most 2.5 times.
TEST(ThinWalls, ThinPlateIsAWall) {
  const detail::ThinWalls walls = thin_walls_of("plate_thin.obj");
  EXPECT_EQ(walls.walls, 1u);
  EXPECT_EQ(walls.triangles, 12u);
  ASSERT_EQ(walls.triangle_refinement.size(), 12u);
  for (const double f : walls.triangle_refinement) {
    EXPECT_GT(f, 1.0);
    EXPECT_LE(f, 2.5);
  }
}

// The rod of radius 0.012 (diagonal 1.0006, h = 0.025): thin (0.48 h), but a
// limb: its medial vertices lie within its radius of its axis, less than
// R / 4 = 0.75 h from it, so none spreads as a sheet and nothing is
// sampled again.
TEST(ThinWalls, ThinRodIsNotAWall) {
  const detail::ThinWalls walls = thin_walls_of("rod_thin.obj");
  EXPECT_GT(walls.thin_vertices, 0u);
  EXPECT_EQ(walls.wall_vertices, 0u);
  EXPECT_TRUE(walls.triangle_refinement.empty());
}

// A slab as wide as the plate but 0.2 thick (diagonal 1.4283, h = 0.0357:
// 5.6 h): its mid-sheet is 2.8 h deep, not thin; its thin medial vertices
// are the ones towards its edges and corners, each on a strip about a
// spacing wide or where a few such strips meet: no wall.
TEST(ThinWalls, ThickSlabIsNotAWall) {
  const detail::ThinWalls walls = thin_walls_of("slab_thick.obj");
  EXPECT_TRUE(walls.triangle_refinement.empty());
}

// Pavlidis on (0,0) (1,0.1) (2,−0.1) (3,0.5) (4,0), radius 0 everywhere.
// Chord (0,0)–(4,0): distances 0.1, 0.1, 0.5 → the split keeps (3,0.5) when
// the tolerance is below 0.5. Then on (0,0)…(3,0.5): the chord direction is
// (6, 1)/√37; distances |0.1·6 − 1·1|/√37 = 0.4/√37 ≈ 0.0658 for (1,0.1) and
// |−0.1·6 − 2|/√37 = 2.6/√37 ≈ 0.4274 for (2,−0.1).
std::vector<Vec4> five_points() {
  return {Vec4(0, 0, 0, 0), Vec4(1, 0.1, 0, 0), Vec4(2, -0.1, 0, 0), Vec4(3, 0.5, 0, 0), Vec4(4, 0, 0, 0)};
}

TEST(Pavlidis, FivePointsAtThreeTolerances) {
  EXPECT_EQ(pavlidis_split(five_points(), 0.6).size(), 2u);  // 0.5 ≤ 0.6: only the ends
  const std::vector<Vec4> middle = pavlidis_split(five_points(), 0.45);
  ASSERT_EQ(middle.size(), 3u);  // (3, 0.5) kept; 0.4274 ≤ 0.45 on the left half
  EXPECT_EQ(middle[1], five_points()[3]);
  const std::vector<Vec4> fine = pavlidis_split(five_points(), 0.05);
  EXPECT_EQ(fine.size(), 5u);  // 0.0658 > 0.05: every point kept
}

// The radius counts in 4-D and not in 3-D: a straight line whose middle
// point has radius 1 more than its ends.
TEST(Pavlidis, RadiusIsADimension) {
  const std::vector<Vec4> line = {Vec4(0, 0, 0, 1), Vec4(1, 0, 0, 2), Vec4(2, 0, 0, 1)};
  EXPECT_EQ(pavlidis_split(line, 0.5, PavlidisDimension::space_and_radius).size(), 3u);
  EXPECT_EQ(pavlidis_split(line, 0.5, PavlidisDimension::space).size(), 2u);
}

// Q(u) = Σ B_k(u) V_k with the uniform cubic basis: at u = 1/2 the weights
// are 1/48, 23/48, 23/48, 1/48. With V = 0, 6, 12, 48 (in x):
// (0 + 138 + 276 + 48)/48 = 462/48 = 9.625.
TEST(BSpline, SpanValueAtOneHalf) {
  const Vec4 q = bspline_span_point(Vec4(0, 0, 0, 0), Vec4(6, 0, 0, 1), Vec4(12, 0, 0, 1), Vec4(48, 0, 0, 1), 0.5);
  EXPECT_DOUBLE_EQ(q.x(), 9.625);
  EXPECT_DOUBLE_EQ(q.w(), 47.0 / 48.0);  // weights of the three 1s: 23 + 23 + 1
}

// Tripled ends interpolate; a straight, evenly spaced control polygon is
// reproduced as a straight line (the basis reproduces linear functions).
TEST(BSpline, TripledEndsInterpolateAndLinesStayLines) {
  const std::vector<Vec4> control = {Vec4(0, 0, 0, 1), Vec4(1, 1, 0, 1), Vec4(3, 0, 1, 2)};
  const std::vector<Vec4> curve = smooth_bspline(control, 4);
  EXPECT_EQ(curve.front(), control.front());
  EXPECT_EQ(curve.back(), control.back());
  const std::vector<Vec4> line = smooth_bspline({Vec4(0, 0, 0, 1), Vec4(1, 0, 0, 1), Vec4(2, 0, 0, 1)}, 3);
  for (const Vec4& p : line) {
    EXPECT_NEAR(p.y(), 0.0, 1e-15);
    EXPECT_NEAR(p.w(), 1.0, 1e-15);
  }
}

// A Y of three chains and a ring: ends, junctions and branch count.
TEST(Branches, YAndRing) {
  CurveSkeleton y;
  for (int k = 0; k < 7; ++k) y.nodes.push_back(Vec4(k, 0, 0, 0.1));
  y.edges = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {2, 5}, {5, 6}};
  const BranchGraph g = extract_branches(y);
  EXPECT_EQ(g.branches.size(), 3u);
  EXPECT_EQ(g.ends, 3u);
  EXPECT_EQ(g.junctions, 1u);
  CurveSkeleton ring;
  for (int k = 0; k < 5; ++k) ring.nodes.push_back(Vec4(std::cos(k), std::sin(k), 0, 0.1));
  ring.edges = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {0, 4}};
  const BranchGraph r = extract_branches(ring);
  ASSERT_EQ(r.branches.size(), 1u);
  EXPECT_EQ(r.branches[0].points.size(), 6u);  // closed: first = last
  EXPECT_EQ(r.ends + r.junctions, 0u);
}

// A spur of length 0.1 at a junction of radius 1 goes; the long arms stay.
TEST(Branches, SpurRemoval) {
  CurveSkeleton s;
  s.nodes = {Vec4(-3, 0, 0, 1), Vec4(0, 0, 0, 1), Vec4(3, 0, 0, 1), Vec4(0, 0.1, 0, 1)};
  s.edges = {{0, 1}, {1, 2}, {1, 3}};
  EXPECT_EQ(remove_spurs(s, 1.5), 1u);
  const BranchGraph g = extract_branches(s);
  EXPECT_EQ(g.branches.size(), 1u);
  EXPECT_EQ(g.ends, 2u);
}

// The protrusion rule: on an axis of radius 1 from (−3,0,0) to (3,0,0) with
// a junction at the origin, a branch to (0, 1.6, 0) of end radius 0.1 is
// longer than 1.5 junction radii but its end ball reaches only 1.6 + 0.1 −
// 1 = 0.7 radii beyond the axis's balls (a noise spur inside the tube): it
// goes at factor 1 and stays at 0 (rule off). The branch to (0, 3, 0) of
// radius 0.5 reaches 3 + 0.5 − 1 = 2.5: it stays.
TEST(Branches, SpurByProtrusion) {
  const auto make = [] {
    CurveSkeleton s;
    s.nodes = {Vec4(-3, 0, 0, 1), Vec4(0, 0, 0, 1), Vec4(3, 0, 0, 1), Vec4(0, 0.8, 0, 0.5), Vec4(0, 1.6, 0, 0.1),
               Vec4(0, 0, 1.5, 0.7), Vec4(0, 0, 3, 0.5)};
    s.edges = {{0, 1}, {1, 2}, {1, 3}, {3, 4}, {1, 5}, {5, 6}};
    return s;
  };
  CurveSkeleton kept = make();
  EXPECT_EQ(remove_spurs(kept, 1.5, 0.0), 0u);
  CurveSkeleton pruned = make();
  EXPECT_EQ(remove_spurs(pruned, 1.5, 1.0), 1u);
  const BranchGraph g = extract_branches(pruned);
  EXPECT_EQ(g.branches.size(), 3u);
  EXPECT_EQ(g.ends, 3u);
  for (const Branch& b : g.branches) {
    for (const Vec4& p : b.points) EXPECT_NE(p.y(), 1.6);
  }
}

/// Area-weighted points on the surface of the union of `capsules` (a, b,
/// radius): each capsule's cylinder and two hemispheres on a fine
/// parameter grid (exact area weights), without the points inside another
/// capsule, so that the points cover the union's boundary.
std::vector<WeightedPoint> union_of_capsules(const std::vector<std::tuple<Vec3, Vec3, double>>& capsules) {
  const auto inside = [&](const Vec3& p, std::size_t except) {
    for (std::size_t k = 0; k < capsules.size(); ++k) {
      if (k == except) continue;
      const auto& [a, b, r] = capsules[k];
      const Vec3 d = b - a;
      const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
      if ((p - a - t * d).norm() < r) return true;
    }
    return false;
  };
  std::vector<WeightedPoint> points;
  constexpr int n = 64;  // steps per parameter
  constexpr double pi = std::numbers::pi;
  for (std::size_t k = 0; k < capsules.size(); ++k) {
    const auto& [a, b, r] = capsules[k];
    const Vec3 axis = (b - a).normalized();
    const Vec3 u = axis.cross(std::abs(axis.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).normalized(), v = axis.cross(u);
    const double length = (b - a).norm();
    const auto add = [&](const Vec3& p, double weight) {
      if (!inside(p, k)) points.push_back({p, weight});
    };
    for (int i = 0; i < n; ++i) {
      const double phi = 2 * pi * (i + 0.5) / n;
      const Vec3 out = std::cos(phi) * u + std::sin(phi) * v;
      for (int j = 0; j < n; ++j) add(a + (j + 0.5) / n * length * axis + r * out, 2 * pi * r * length / (n * n));
      for (int j = 0; j < n; ++j) {  // hemispheres: polar angle θ from the axis, dA = r² sin θ dθ dφ
        const double theta = (pi / 2) * (j + 0.5) / n, weight = r * r * std::sin(theta) * (pi / 2 / n) * (2 * pi / n);
        add(b + r * (std::cos(theta) * axis + std::sin(theta) * out), weight);
        add(a + r * (-std::cos(theta) * axis + std::sin(theta) * out), weight);
      }
    }
  }
  return points;
}

// Limb against spur, where the length and protrusion rules fail. A trunk of
// radius 1 along x from −3 to 3 with a junction at the origin carries a
// short thick limb (to (0, 0, 1.4), radius 0.9: 1.4 junction radii long,
// reaching 1.4 + 0.9 − 1 = 1.3 beyond the trunk's balls) and a long thin
// needle (to (0, 2.5, 0), radius 0.05: 2.5 radii long, reaching 2.5 + 0.05
// − 1 = 1.55). The length and protrusion rules at 1.5 remove the limb and
// keep the needle. The input surface is the union of the trunk, the limb and
// the needle: the limb explains its cap and side beyond the trunk (a
// hemisphere alone is 2π 0.9² ≈ 5.1), the needle the part of its side more
// than 0.25 beyond the trunk (2π 0.05 × 1.25 + its cap ≈ 0.4), against the
// threshold 0.5 π 1² ≈ 1.57: the area rule keeps the limb and removes the
// needle.
TEST(Branches, SpurByExplainedArea) {
  const auto make = [] {
    CurveSkeleton s;
    s.nodes = {Vec4(-3, 0, 0, 1), Vec4(0, 0, 0, 1), Vec4(3, 0, 0, 1), Vec4(0, 0, 0.7, 0.9), Vec4(0, 0, 1.4, 0.9),
               Vec4(0, 1.25, 0, 0.05), Vec4(0, 2.5, 0, 0.05)};
    s.edges = {{0, 1}, {1, 2}, {1, 3}, {3, 4}, {1, 5}, {5, 6}};
    return s;
  };
  const std::vector<WeightedPoint> surface = union_of_capsules(
      {{Vec3(-3, 0, 0), Vec3(3, 0, 0), 1.0}, {Vec3(0, 0, 0), Vec3(0, 0, 1.4), 0.9}, {Vec3(0, 0, 0), Vec3(0, 2.5, 0), 0.05}});
  const auto has_end = [](const CurveSkeleton& s, const Vec3& end) {
    return std::any_of(s.nodes.begin(), s.nodes.end(), [&](const Vec4& p) { return p.head<3>() == end; });
  };
  // The explained areas, against the estimates above.
  const BranchGraph g = extract_branches(make());
  int found = 0;
  for (std::size_t k = 0; k < g.branches.size(); ++k) {
    const Vec3 end = g.branches[k].points.back().head<3>();
    const double area = explained_area(g.branches, k, surface, 0.25);
    if (end == Vec3(0, 0, 1.4)) {
      EXPECT_GT(area, 5.0);
      ++found;
    }
    if (end == Vec3(0, 2.5, 0)) {
      EXPECT_LT(area, 0.6);
      ++found;
    }
  }
  EXPECT_EQ(found, 2);
  CurveSkeleton old_rule = make();
  EXPECT_EQ(remove_spurs(old_rule, 1.5, 1.5), 1u);
  EXPECT_FALSE(has_end(old_rule, Vec3(0, 0, 1.4)));  // the limb went
  EXPECT_TRUE(has_end(old_rule, Vec3(0, 2.5, 0)));   // the needle stayed
  CurveSkeleton area_rule = make();
  SpurRule rule{1.5, 1.5, &surface};
  EXPECT_EQ(remove_spurs(area_rule, rule), 1u);
  EXPECT_TRUE(has_end(area_rule, Vec3(0, 0, 1.4)));
  EXPECT_FALSE(has_end(area_rule, Vec3(0, 2.5, 0)));
  EXPECT_EQ(extract_branches(area_rule).ends, 3u);
}

// A junction split into a triangle: three nodes of radius 0.45, 0.4 from
// the origin (sides 0.69, more than the 1.5 × 0.45 = 0.675 a bubble is
// contracted below), each with one arm of a plane Y. The triangle's centroid
// (the origin) is 0.4 from each node, inside their balls: no hole, so the
// three become one junction and the Y has 3 branches. The same triangle
// scaled to 3 from the origin (a ring with three arms, its centre 3 from
// every ball of radius 0.45) encloses a hole and stays: 6 branches.
TEST(Branches, JunctionTriangleContracted) {
  const auto y = [](double scale) {
    CurveSkeleton s;
    for (int k = 0; k < 3; ++k) {
      const double a = 2 * std::numbers::pi * k / 3;
      const Vec3 d(std::cos(a), std::sin(a), 0);
      s.nodes.push_back(Vec4(scale * d.x(), scale * d.y(), 0, 0.45));
      s.nodes.push_back(Vec4((scale + 3) * d.x(), (scale + 3) * d.y(), 0, 0.3));
    }
    s.edges = {{0, 1}, {2, 3}, {4, 5}, {0, 2}, {2, 4}, {0, 4}};
    return s;
  };
  CurveSkeleton split = y(0.4);
  remove_spurs(split, 1.5);
  const BranchGraph g = extract_branches(split);
  EXPECT_EQ(g.branches.size(), 3u);
  EXPECT_EQ(g.ends, 3u);
  EXPECT_EQ(g.junctions, 1u);
  for (const Vec4& node : split.nodes) {
    if (node.w() == 0.45) {
      EXPECT_LT(node.head<3>().norm(), 1e-12);  // at the mean of the three
    }
  }
  CurveSkeleton ring = y(3.0);
  remove_spurs(ring, 1.5);
  EXPECT_EQ(extract_branches(ring).branches.size(), 6u);
}

// A plane Y of three straight arms meeting at the origin (nodes every 0.5
// along each arm, radius 0.3), whose junction node sits 0.4 down arm 0, as
// a level-set graph puts it: the arms' axes (chords from 0.3 to 0.9 along
// each branch) all pass through the origin, so the junction moves there
// exactly (up to rounding), and arm 0's node at 0.5 stays (0.5 ahead of it,
// more than half the radius).
TEST(Branches, JunctionRelocation) {
  CurveSkeleton y;
  y.nodes.push_back(Vec4(0.4, 0, 0, 0.3));
  for (int arm = 0; arm < 3; ++arm) {
    const double angle = 2.0 * std::numbers::pi * arm / 3.0;
    for (int k = 1; k <= 6; ++k) {
      const double t = 0.5 * k;
      y.nodes.push_back(Vec4(t * std::cos(angle), t * std::sin(angle), 0, 0.3));
      const auto node = std::int32_t(y.nodes.size() - 1);
      y.edges.push_back({k == 1 ? 0 : node - 1, node});
    }
  }
  EXPECT_EQ(relocate_junctions(y), 1u);
  const BranchGraph g = extract_branches(y);
  EXPECT_EQ(g.branches.size(), 3u);
  EXPECT_EQ(g.ends, 3u);
  EXPECT_EQ(g.junctions, 1u);
  EXPECT_LT(y.nodes[0].head<3>().norm(), 1e-12);
  EXPECT_EQ(y.nodes.size(), 19u);  // nothing dropped
}

// --- mesh reader ------------------------------------------------------------

TriangleMesh tetrahedron() {
  TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

std::filesystem::path temporary(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("skelconv_reconstruct_test_" + name);
}

TEST(MeshReader, ReadsWhatWriteMeshWrites) {
  for (const char* name : {"t.ply", "t.obj"}) {
    for (PlyEncoding encoding : {PlyEncoding::binary, PlyEncoding::ascii}) {
      const auto path = temporary(name);
      write_mesh(tetrahedron(), path, encoding);
      const TriangleMesh back = read_mesh(path);
      EXPECT_EQ(back.vertices, tetrahedron().vertices) << name;
      EXPECT_EQ(back.triangles, tetrahedron().triangles) << name;
      std::filesystem::remove(path);
    }
  }
}

TEST(MeshReader, BigEndianFloatQuadsAndObjPolygons) {
  const auto ply = temporary("big.ply");
  {
    std::ofstream out(ply, std::ios::binary);
    out << "ply\nformat binary_big_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
           "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const float xyz[12] = {0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0};
    for (float f : xyz) {
      unsigned char b[4];
      std::memcpy(b, &f, 4);
      out.put(char(b[3])).put(char(b[2])).put(char(b[1])).put(char(b[0]));
    }
    out.put(char(4));
    for (int i : {0, 1, 2, 3}) out.put(0).put(0).put(0).put(char(i));
  }
  const TriangleMesh quad = read_mesh(ply);
  ASSERT_EQ(quad.vertices.size(), 4u);
  EXPECT_EQ(quad.vertices[2], Vec3(2, 2, 0));
  ASSERT_EQ(quad.triangles.size(), 2u);  // the fan 0 1 2, 0 2 3
  EXPECT_EQ(quad.triangles[1], (std::array<std::int32_t, 3>{0, 2, 3}));
  std::filesystem::remove(ply);

  const auto obj = temporary("poly.obj");
  std::ofstream(obj) << "# a quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1 -1//1\n";
  EXPECT_EQ(read_mesh(obj).triangles.size(), 2u);
  std::ofstream(obj) << "v 0 0 0\nv 1 0 0\nf 1 2 7\n";
  try {
    read_mesh(obj);
    ADD_FAILURE() << "no error for an index out of range";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("line 3"), std::string::npos) << error.what();
  }
  std::filesystem::remove(obj);
  EXPECT_THROW(read_mesh(temporary("x.stl")), InputError);
}

// A polygon that is not convex, or has three corners on a line, is cut
// into triangles that each turn the polygon's way with positive area and
// add up to its area (covering it once): a fan from the first corner
// would fold over the L below, and leave a triangle of zero area in the
// square with a corner in the middle of a side (CGAL's mpi.off, the
// letters M, P, I as prisms, was refused for such triangles).
TEST(MeshReader, PolygonsAreCutIntoTrianglesThatCoverThemOnce) {
  const auto obj = temporary("polygons.obj");
  struct Case {
    const char* name;
    std::vector<std::array<double, 2>> corners;
    double area;  // by hand
  };
  const Case cases[] = {
      {"an L, from its corner at the reflex one's side", {{2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 0}, {2, 0}}, 3.0},
      {"a square with a corner on a side", {{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}, 4.0},
      {"a comb of two teeth", {{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, 5.0},
  };
  for (const Case& c : cases) {
    std::ofstream out(obj);
    for (const auto& p : c.corners) out << "v " << p[0] << ' ' << p[1] << " 0\n";
    out << 'f';
    for (std::size_t k = 1; k <= c.corners.size(); ++k) out << ' ' << k;
    out << '\n';
    out.close();
    const TriangleMesh m = read_mesh(obj);
    ASSERT_EQ(m.triangles.size(), c.corners.size() - 2) << c.name;
    double total = 0.0;
    for (const auto& t : m.triangles) {
      const Vec3 &a = m.vertices[std::size_t(t[0])], &b = m.vertices[std::size_t(t[1])], &d = m.vertices[std::size_t(t[2])];
      const double signed_area = 0.5 * (b - a).cross(d - a).z();
      EXPECT_GT(signed_area, 0.0) << c.name << ": triangle " << t[0] << ' ' << t[1] << ' ' << t[2];
      total += signed_area;
    }
    EXPECT_DOUBLE_EQ(total, c.area) << c.name;
  }
  std::filesystem::remove(obj);
}

// An element without properties holds no data, whatever count its header
// declares: it is skipped, not looped over (libFuzzer found a header
// declaring 10^14 items of one, tests/data/fuzz/mesh_reader/, on which the
// reader never returned).
TEST(MeshReader, ElementWithoutPropertiesIsSkipped) {
  const auto ply = temporary("empty_element.ply");
  std::ofstream(ply) << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                        "property float z\nelement unused 111111111111111\nelement face 1\n"
                        "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const TriangleMesh mesh = read_mesh(ply);
  EXPECT_EQ(mesh.vertices.size(), 3u);
  EXPECT_EQ(mesh.triangles.size(), 1u);
  std::filesystem::remove(ply);
}

}  // namespace
}  // namespace skelconv::reconstruct
