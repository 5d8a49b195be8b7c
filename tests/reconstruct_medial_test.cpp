// The medial-mesh path (reconstruct/medial_mesh.hpp, medial_fit.hpp,
// docs/reconstruction_medial.md) on graphs built by hand, whose answer is
// known without running the code: a sheet of Voronoi vertices gives
// triangles and no tube, a line gives a chain of edges, a spike is removed
// and a limb kept, pieces whose balls overlap are joined. Then the whole
// path on a plate, where the fit may only lower its RMS distance.
#include <cmath>
#include <filesystem>
#include <set>

#include <gtest/gtest.h>

#include "skelconv/mesh/mesh_reader.hpp"
#include "skelconv/reconstruct/medial_mesh.hpp"
#include "skelconv/reconstruct/reconstruct.hpp"

namespace skelconv::reconstruct {
namespace {

std::int32_t add_vertex(MedialGraph& g, const Vec3& c, double radius) {
  g.vertices.push_back(MedialVertex{c, radius, {0, 0, 0, 0}});
  return std::int32_t(g.vertices.size() - 1);
}

void add_edge(MedialGraph& g, std::int32_t a, std::int32_t b) { g.edges.push_back(MedialEdge{a, b, {0, 0, 0}}); }

/// An n × n grid of spacing h in the plane z = 0 from the origin, radius r,
/// joined to its 4 neighbours: a medial sheet. Returns the first index.
std::int32_t add_sheet(MedialGraph& g, int n, double h, double r) {
  const std::int32_t first = std::int32_t(g.vertices.size());
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) add_vertex(g, Vec3(i * h, j * h, 0), r);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const std::int32_t v = first + i * n + j;
      if (i + 1 < n) add_edge(g, v, v + n);
      if (j + 1 < n) add_edge(g, v, v + 1);
    }
  return first;
}

/// A line of `count` vertices from `start` in steps `step`, radius r(k),
/// joined in order; its first vertex joined to `attach` if ≥ 0.
template <class Radius>
void add_line(MedialGraph& g, const Vec3& start, const Vec3& step, int count, Radius r, std::int32_t attach = -1) {
  std::int32_t previous = attach;
  for (int k = 0; k < count; ++k) {
    const std::int32_t v = add_vertex(g, start + k * step, r(k));
    if (previous >= 0) add_edge(g, previous, v);
    previous = v;
  }
}

double triangle_area(const MedialMesh& m, const std::array<std::int32_t, 3>& t) {
  const Vec3 a = m.spheres[std::size_t(t[0])].head<3>(), b = m.spheres[std::size_t(t[1])].head<3>(),
             c = m.spheres[std::size_t(t[2])].head<3>();
  return (b - a).cross(c - a).norm() / 2;
}

TEST(MedialMesh, SheetBecomesTrianglesThatDoNotOverlap) {
  MedialGraph g;
  add_sheet(g, 41, 0.05, 0.5);  // 2 × 2, radius 0.5: spheres about 0.5 apart
  const MedialMesh m = simplify_medial_graph(g, {});
  EXPECT_GE(m.spheres.size(), 9u);
  EXPECT_LE(m.edges.size(), 4u) << "at most one per corner";
  EXPECT_GE(m.triangles.size(), 8u);
  EXPECT_TRUE(m.isolated.empty());
  // No tube runs across the sheet: an edge in no triangle can only join a
  // corner's region, which meets one neighbour and no triple point, to the
  // sheet (one end on a triangle, the other on this edge alone).
  std::vector<int> triangles_at(m.spheres.size(), 0), edges_at(m.spheres.size(), 0);
  for (const auto& t : m.triangles)
    for (const std::int32_t i : t) ++triangles_at[std::size_t(i)];
  for (const auto& e : m.edges) ++edges_at[std::size_t(e[0])], ++edges_at[std::size_t(e[1])];
  for (const auto& e : m.edges) {
    const auto [a, b] = std::pair{std::size_t(e[0]), std::size_t(e[1])};
    EXPECT_TRUE((triangles_at[a] > 0 && triangles_at[b] == 0 && edges_at[b] == 1) ||
                (triangles_at[b] > 0 && triangles_at[a] == 0 && edges_at[a] == 1))
        << "edge " << e[0] << "–" << e[1] << " is not a corner";
  }
  // The spheres are grid vertices, so the triangles lie in the 2 × 2
  // square: more than its area in all means two triangles overlap (the
  // sum blend would count the sheet twice there).
  double area = 0.0;
  for (const auto& t : m.triangles) area += triangle_area(m, t);
  EXPECT_LE(area, 4.0 + 1e-9);
  // Every vertex is within 1 radius (0.5) of a seed along the grid, so the
  // seeds' hull reaches within 0.5 of every side: at least a 1 × 1 square.
  EXPECT_GE(area, 1.0);
}

TEST(MedialMesh, TubeBecomesAChainOfEdges) {
  MedialGraph g;
  add_line(g, Vec3(0, 0, 0), Vec3(0.05, 0, 0), 101, [](int) { return 0.5; });  // 5 long, radius 0.5
  const MedialMesh m = simplify_medial_graph(g, {});
  EXPECT_TRUE(m.triangles.empty());
  // Seeds until every vertex is within 1 radius (0.5) of one: at least
  // 5 / (2 × 0.5) = 5 spheres; a chain joins n spheres by n − 1 edges.
  EXPECT_GE(m.spheres.size(), 5u);
  EXPECT_EQ(m.edges.size(), m.spheres.size() - 1);
  std::set<std::int32_t> used;
  for (const auto& e : m.edges) used.insert(e[0]), used.insert(e[1]);
  EXPECT_EQ(used.size(), m.spheres.size());
}

TEST(MedialMesh, SpikeIsRemovedLimbIsKept) {
  // A sheet of radius 0.5 with, at its centre, a spike whose balls shrink
  // as it rises (h + r = 0.5: it reaches no farther than the sheet's ball)
  // and, at a corner, a limb 3 long of radius 0.3 (reaches 2.8 beyond).
  const auto highest_sphere = [](const MedialMesh& m) {
    double highest = 0.0;
    for (const Vec4& s : m.spheres) highest = std::max(highest, s.z());
    return highest;
  };
  MedialGraph g;
  const std::int32_t first = add_sheet(g, 41, 0.05, 0.5);
  add_line(g, Vec3(1, 1, 0.02), Vec3(0, 0, 0.02), 20, [](int k) { return 0.5 - 0.02 * (k + 1); }, first + 20 * 41 + 20);
  MedialGraph with_limb = g;
  add_line(with_limb, Vec3(0, 0, 0.05), Vec3(0, 0, 0.05), 60, [](int) { return 0.3; }, first);
  MedialMeshOptions keep_all;
  keep_all.spur_protrusion = 0.0;
  keep_all.contained_slack = -1.0;
  EXPECT_GT(highest_sphere(simplify_medial_graph(g, keep_all)), 0.1) << "the spike has spheres before the rule";
  EXPECT_LT(highest_sphere(simplify_medial_graph(g, {})), 1e-12) << "the spike must go";
  EXPECT_GT(highest_sphere(simplify_medial_graph(with_limb, {})), 2.5) << "the limb must stay";
}

TEST(MedialMesh, PiecesWhoseBallsOverlapAreJoined) {
  // Two lines with no Voronoi edge between them: 0.6 apart with radius 0.5
  // (the balls overlap: one body cut by pruning), and 3 apart (two bodies).
  const auto pieces = [](const MedialMesh& m) {
    std::vector<std::int32_t> parent(m.spheres.size());
    for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = std::int32_t(i);
    const auto root = [&parent](std::int32_t x) {
      while (parent[std::size_t(x)] != x) x = parent[std::size_t(x)];
      return x;
    };
    for (const auto& e : m.edges) parent[std::size_t(root(e[0]))] = root(e[1]);
    std::set<std::int32_t> roots;
    for (std::size_t i = 0; i < parent.size(); ++i) roots.insert(root(std::int32_t(i)));
    return roots.size();
  };
  for (const auto& [gap, expected] : {std::pair{0.6, std::size_t{1}}, std::pair{3.0, std::size_t{2}}}) {
    MedialGraph g;
    add_line(g, Vec3(0, 0, 0), Vec3(0.05, 0, 0), 41, [](int) { return 0.5; });
    add_line(g, Vec3(2 + gap, 0, 0), Vec3(0.05, 0, 0), 41, [](int) { return 0.5; });
    EXPECT_EQ(pieces(simplify_medial_graph(g, {})), expected) << "gap " << gap;
  }
}

TEST(MedialMesh, SameGraphSameMesh) {
  MedialGraph g;
  const std::int32_t first = add_sheet(g, 31, 0.05, 0.4);
  add_line(g, Vec3(0, 0, 0.05), Vec3(0, 0, 0.05), 40, [](int) { return 0.2; }, first);
  const MedialMesh a = simplify_medial_graph(g, {}), b = simplify_medial_graph(g, {});
  EXPECT_EQ(a.spheres, b.spheres);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.triangles, b.triangles);
}

TEST(MedialMesh, BudgetIsRespected) {
  const TriangleMesh cube = read_mesh(std::filesystem::path(SKELCONV_TEST_DATA) / "reconstruct" / "cube.ply");
  for (const std::size_t budget : {5u, 40u, 500u}) {
    ReconstructOptions o;
    o.method = SkeletonMethod::medial;
    o.medial.budget = budget;
    const Reconstruction r = reconstruct(cube, o);
    ASSERT_EQ(r.stages.back().name, "medial");
    EXPECT_LE(primitive_counts(r.stages.back(), o).total(), budget);
    EXPECT_GT(primitive_counts(r.stages.back(), o).total(), 0u);
  }
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
}

}  // namespace
}  // namespace skelconv::reconstruct
