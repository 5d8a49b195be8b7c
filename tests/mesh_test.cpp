// skelconv mesh (mesh_iso_surface): topology and accuracy of the meshes of
// skeletons whose surface topology is known by construction (docs/mesh.md,
// "Verification"). Every property is checked with tools independent of the
// mesher's own summary: CGAL Polygon_mesh_processing for manifoldness,
// closedness, components and self-intersections, the Skeleton itself for
// the distance of every vertex to the surface and for the normals.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <gtest/gtest.h>

#include "skelconv/errors.hpp"
#include "skelconv/mesh/implicit_field.hpp"
#include "skelconv/mesh/mesh_topology.hpp"
#include "skelconv/mesh/mesh_iso_surface.hpp"
#include "skelconv/mesh/surface_projection.hpp"
#include "skelconv/mesh/surface_seeds.hpp"
#include "skelconv/skeleton/skeleton_file.hpp"
#include "walk_skeleton.hpp"

#ifndef SKELCONV_BINARY
#error "SKELCONV_BINARY (path of the skelconv executable) is set by tests/CMakeLists.txt"
#endif
#ifndef SKELCONV_TEST_DATA
#error "SKELCONV_TEST_DATA (tests/data) is set by tests/CMakeLists.txt"
#endif

namespace skelconv {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;

Skeleton load(const std::string& name) {
  return load_skeleton_file(std::string(SKELCONV_TEST_DATA) + "/mesh/" + name + ".json");
}

/// The mesh as a CGAL Surface_mesh; fails the test if the triangle soup is
/// not a polygon mesh (an edge on more than two triangles, a non-manifold
/// vertex, inconsistent orientation).
SurfaceMesh to_surface_mesh(const TriangleMesh& mesh) {
  std::vector<Point> points;
  for (const Vec3& v : mesh.vertices) points.emplace_back(v.x(), v.y(), v.z());
  std::vector<std::vector<std::size_t>> faces;
  for (const auto& t : mesh.triangles) faces.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});
  EXPECT_TRUE(PMP::is_polygon_soup_a_polygon_mesh(faces)) << "not a manifold, consistently oriented mesh";
  SurfaceMesh surface;
  PMP::polygon_soup_to_polygon_mesh(points, faces, surface);
  return surface;
}

/// Per component: (Euler characteristic V − E + F, signed volume).
std::vector<std::pair<long long, double>> components_of(SurfaceMesh& surface) {
  auto component = surface.add_property_map<SurfaceMesh::Face_index, std::size_t>("f:component").first;
  const std::size_t count = PMP::connected_components(surface, component);
  std::vector<std::pair<long long, double>> result(count, {0, 0.0});
  for (auto f : surface.faces()) {
    result[component[f]].first += 1;
    const auto h = surface.halfedge(f);
    const Point& a = surface.point(surface.source(h));
    const Point& b = surface.point(surface.target(h));
    const Point& c = surface.point(surface.target(surface.next(h)));
    result[component[f]].second += CGAL::scalar_product(a - CGAL::ORIGIN, CGAL::cross_product(b - CGAL::ORIGIN, c - CGAL::ORIGIN)) / 6;
  }
  for (auto e : surface.edges()) result[component[surface.face(surface.halfedge(e))]].first -= 1;
  for (auto v : surface.vertices()) result[component[surface.face(surface.halfedge(v))]].first += 1;
  return result;
}

/// Mesh options at `iso`, with facet size and distance if > 0.
MeshOptions options_at(double iso, double size = 0, double distance = 0) {
  MeshOptions options;
  options.iso = iso;
  if (size != 0) options.size = size;
  if (distance != 0) options.distance = distance;
  return options;
}

double bounding_diagonal(const TriangleMesh& mesh) { return bounding_box(mesh.vertices).diagonal(); }

struct TopologyCase {
  std::string skeleton;
  double iso;
  std::vector<long long> euler_per_component;  // in any order
  MeshMethod method = MeshMethod::cgal;
  double size = 0, distance = 0;  // > 0: --size / --distance (else the defaults)
  double grid_size = 0;           // > 0: --size of the grid case (else `size`)
};

void PrintTo(const TopologyCase& c, std::ostream* out) {
  *out << c.skeleton << " at iso " << c.iso << (c.method == MeshMethod::grid ? " (grid)" : " (cgal)");
}

void expect_certified_mesh(const TopologyCase& c, const Skeleton& skeleton, const TriangleMesh& mesh) {
  ASSERT_FALSE(mesh.triangles.empty());
  SurfaceMesh surface = to_surface_mesh(mesh);
  EXPECT_TRUE(CGAL::is_closed(surface)) << "open mesh";
  EXPECT_FALSE(PMP::does_self_intersect(surface)) << "self-intersecting mesh";
  EXPECT_EQ(surface.number_of_vertices(), mesh.vertices.size()) << "isolated vertices";

  std::vector<long long> euler;
  for (const auto& [chi, volume] : components_of(surface)) {
    euler.push_back(chi);
    EXPECT_GT(volume, 0) << "a component is oriented inwards";
  }
  std::vector<long long> expected = c.euler_per_component;
  std::sort(euler.begin(), euler.end());
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(euler, expected) << "Euler characteristics of the components";

  // Every vertex on the surface and its normal exact (independent evaluation).
  const double tolerance = 1e-9 * bounding_diagonal(mesh);
  ASSERT_EQ(mesh.normals.size(), mesh.vertices.size());
  double worst = 0, worst_normal = 0;
  for (std::size_t k = 0; k < mesh.vertices.size(); ++k) {
    const FieldSample s = skeleton.value_and_gradient(mesh.vertices[k]);
    worst = std::max(worst, std::abs(s.value - c.iso) / s.gradient.norm());
    worst_normal = std::max(worst_normal, (mesh.normals[k] + s.gradient.normalized()).norm());
  }
  EXPECT_LE(worst, tolerance) << "largest |f - c|/|grad f| over the vertices";
  EXPECT_LE(worst_normal, 1e-14) << "normal differs from -grad f/|grad f|";
  // The triangles turn the same way as the normals (outwards).
  for (const auto& t : mesh.triangles) {
    const Vec3 face_normal = (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
    ASSERT_GT(face_normal.dot(mesh.normals[t[0]] + mesh.normals[t[1]] + mesh.normals[t[2]]), 0);
  }
}

class MeshTopologyTest : public testing::TestWithParam<TopologyCase> {};

TEST_P(MeshTopologyTest, ClosedManifoldOnTheSurfaceWithTheExpectedTopology) {
  const TopologyCase& c = GetParam();
  const Skeleton skeleton = load(c.skeleton);
  MeshReport report;
  MeshOptions options = options_at(c.iso, c.size, c.distance);
  options.method = c.method;
  const TriangleMesh mesh = mesh_iso_surface(skeleton_field(skeleton), options, &report);
  std::printf("%s: %zu triangles, %zu vertices, %.3f s\n", c.skeleton.c_str(), mesh.triangles.size(),
              mesh.vertices.size(), report.total_seconds);
  expect_certified_mesh(c, skeleton, mesh);
}

// The isos put the surface about a quarter of the segment length from the
// segments (tests/data/mesh/ holds the skeletons; the expected topology is
// that of a tube of that radius around the skeleton).
const std::vector<TopologyCase> topology_cases{
    {"segment", 0.5, {2}},                 // a capsule: a sphere
    {"ring", 0.38, {0}},                   // 8 segments in a circle: a torus
    {"rings_linked", 0.38, {0, 0}},        // two linked tori
    {"rings_side_by_side", 0.38, {0, 0}},  // two separate tori
    {"figure_eight", 0.4, {-2}},           // two loops sharing a segment: genus 2
    {"blobs", 0.5, {2, 2}},                // a blob 30× smaller, 3 units away
    {"polygon", 0.1, {2}},                 // a thickened pentagon
    {"scalis_cone", 0.8, {2}},             // a SCALIS cone (radius 0.5 → 0)
    {"blend_tree", 0.5, {2, 2}},           // union of a summed L of segments and a ball
    {"polygon_inverse", 1.0, {2}},         // p⁴ pentagon: skeleton points on its edges are refused, skipped
    // Point primitives of four kernels (Cauchy, compact with a weight,
    // Wyvill, soft): the first two merge, the others stand alone.
    {"points", 0.5, {2, 2, 2}},
    // A SCALIS triangle of varying radius (the certified numerical path,
    // ~0.2 ms per evaluation): coarse, to keep the case under a second.
    {"scalis_triangle", 0.6, {2}, MeshMethod::cgal, 0.6, 0.15, 0.25},
    // Two Gaussian segments 20 apart, blobs ~0.63 across: the box must not
    // shrink between its face samples onto them. The grid needs a voxel
    // below the blobs' size (the default, diagonal / 50, is 0.44).
    {"gaussians_far_apart", 0.5, {2, 2}, MeshMethod::cgal, 0, 0, 0.1},
};

/// The same cases meshed by the grid method, except `blobs`: its small blob
/// (radius ~0.05) is below the default grid spacing (~0.13) and is lost, as
/// docs/mesh.md says the grid method may.
std::vector<TopologyCase> grid_cases() {
  std::vector<TopologyCase> cases;
  for (TopologyCase c : topology_cases) {
    if (c.skeleton == "blobs") continue;
    c.method = MeshMethod::grid;
    if (c.grid_size > 0) c.size = c.grid_size;
    cases.push_back(c);
  }
  return cases;
}

// The isos put the surface about a quarter of the segment length from the
// segments (tests/data/mesh/ holds the skeletons; the expected topology is
// that of a tube of that radius around the skeleton).
INSTANTIATE_TEST_SUITE_P(Cgal, MeshTopologyTest, testing::ValuesIn(topology_cases),
                         [](const testing::TestParamInfo<TopologyCase>& info) { return info.param.skeleton; });
INSTANTIATE_TEST_SUITE_P(Grid, MeshTopologyTest, testing::ValuesIn(grid_cases()),
                         [](const testing::TestParamInfo<TopologyCase>& info) { return info.param.skeleton; });

/// f(p / α) with skeleton points scaled by α: the same shape at another scale.
ImplicitField scaled(const Skeleton& skeleton, double alpha) {
  ImplicitField field = skeleton_field(skeleton);
  field.value = [&skeleton, alpha](const Vec3& p) { return skeleton.value(p / alpha); };
  field.reaches = [&skeleton, alpha](const Vec3& p, double level) { return skeleton.reaches(p / alpha, level); };
  field.value_and_gradient = [&skeleton, alpha](const Vec3& p) {
    FieldSample s = skeleton.value_and_gradient(p / alpha);
    s.gradient /= alpha;
    return s;
  };
  // skeleton_field's other evaluations are of the unscaled field.
  field.value_near = {};
  field.value_and_gradient_near = {};
  field.coarse = nullptr;
  for (Vec3& p : field.skeleton_points) p *= alpha;
  return field;
}

// A seed ray that meets an evaluation failure is skipped only where the field
// is infinite on its skeleton (an inverse kernel); on a field finite
// everywhere the failure is a real one and must reach the caller.
// Against a torus (one component, χ 0, one handle): a torus and a sphere
// apart (2 components, χ 2) is one defect, a piece; a double torus
// (χ −2) one, a handle; a double torus with a cavity (2 components, χ 0,
// the torus's own χ) two, though neither the χ nor (by one) the component
// count tells them apart from a torus with a piece off; a sphere (χ 2) one.
TEST(MeshTopologyDefects, EachComponentAndEachHandleCountsOne) {
  const auto topology = [](std::size_t components, long long euler) {
    MeshTopology t;
    t.components = components, t.euler_characteristic = euler;
    return t;
  };
  const MeshTopology torus = topology(1, 0);
  EXPECT_EQ(topology_defects(torus, torus), 0);
  EXPECT_EQ(topology_defects(torus, topology(2, 2)), 1);
  EXPECT_EQ(topology_defects(torus, topology(1, -2)), 1);
  EXPECT_EQ(topology_defects(torus, topology(2, 0)), 2);
  EXPECT_EQ(topology_defects(torus, topology(1, 2)), 1);
  EXPECT_EQ(topology_defects(topology(1, 2), topology(4, 4)), 5);  // three pieces more, two handles
}

// Closed surfaces that touch themselves at a vertex, as a union of parts
// meeting at a point may: tetrahedra joined at corners. The readings are
// known by construction: two tetrahedra at one corner (V − E + F = 7 − 12 +
// 8 = 3) are one ball through it (χ 2) or two apart (χ 4); three in a ring,
// each touching the next at a corner (9 − 18 + 12 = 3), a solid torus (χ 0)
// with necks, a ball (χ 2) with one corner apart, and so on up to 6.
TEST(MeshTopologyPinches, EitherReadingOfAVertexWhereTheSurfaceTouchesItselfKeepsIt) {
  const auto tetrahedron = [](TriangleMesh& m, std::int32_t a, std::int32_t b, std::int32_t c, std::int32_t d) {
    m.triangles.push_back({a, c, b});
    m.triangles.push_back({a, b, d});
    m.triangles.push_back({b, c, d});
    m.triangles.push_back({c, a, d});
  };
  const auto surface = [](std::size_t components, long long euler) {
    MeshTopology t;
    t.components = components, t.euler_characteristic = euler;
    return t;
  };
  TriangleMesh two;
  two.vertices.resize(7, Vec3::Zero());
  tetrahedron(two, 0, 1, 2, 3);
  tetrahedron(two, 3, 4, 5, 6);
  const MeshTopology t2 = mesh_topology(two);
  EXPECT_EQ(t2.euler_characteristic, 3);
  EXPECT_EQ(t2.components, 1u);
  EXPECT_EQ(t2.pinches, 1u);
  EXPECT_FALSE(t2.manifold);
  EXPECT_TRUE(same_topology(t2, surface(1, 2)));      // joined by a neck
  EXPECT_EQ(topology_defects(t2, surface(1, 4)), 0);  // apart: χ 4 (the component count aside)
  EXPECT_EQ(topology_defects(t2, surface(1, 0)), 1);  // a handle neither reading has
  EXPECT_EQ(topology_defects(t2, surface(1, 6)), 1);

  TriangleMesh ring;  // corners 0 (shared by A and B), 1 (B and C), 2 (C and A)
  ring.vertices.resize(9, Vec3::Zero());
  tetrahedron(ring, 2, 0, 3, 4);
  tetrahedron(ring, 0, 1, 5, 6);
  tetrahedron(ring, 1, 2, 7, 8);
  const MeshTopology t3 = mesh_topology(ring);
  EXPECT_EQ(t3.euler_characteristic, 3);
  EXPECT_EQ(t3.pinches, 3u);
  for (const long long euler : {0, 2, 4, 6}) EXPECT_TRUE(same_topology(t3, surface(1, euler))) << euler;
  EXPECT_EQ(topology_defects(t3, surface(1, -2)), 1);
  EXPECT_EQ(topology_defects(t3, surface(1, 8)), 1);
  EXPECT_EQ(topology_defects(t3, surface(2, 2)), 1);

  // A manifold surface reads one way only.
  TriangleMesh one;
  one.vertices.resize(4, Vec3::Zero());
  tetrahedron(one, 0, 1, 2, 3);
  const MeshTopology t1 = mesh_topology(one);
  EXPECT_EQ(t1.pinches, 0u);
  EXPECT_TRUE(t1.manifold);
  EXPECT_TRUE(same_topology(t1, surface(1, 2)));
  EXPECT_EQ(topology_defects(t1, surface(1, 0)), 1);
}

TEST(MeshSeeds, EvaluationErrorsSurfaceUnlessTheFieldIsInfiniteOnItsSkeleton) {
  ImplicitField field;
  // A ball of radius 1 (f = 2 − |p|², iso 1) whose evaluation fails on the
  // plane x = 0.5, crossed by the rays from the centre along +x.
  field.value = [](const Vec3& p) {
    if (std::abs(p.x() - 0.5) < 0.3) throw EvaluationError("injected failure");
    return 2.0 - p.squaredNorm();
  };
  field.value_and_gradient = [&field](const Vec3& p) { return FieldSample{field.value(p), -2.0 * p}; };
  field.skeleton_points = {Vec3::Zero()};
  const Box3 box{Vec3::Constant(-2.0), Vec3::Constant(2.0)};
  SurfaceSeedOptions options;
  options.spacing = 0.1;
  EXPECT_THROW(surface_seeds(field, 1.0, box, options), EvaluationError);
  field.infinite_on_skeleton = true;  // the documented excuse: the other rays seed
  EXPECT_FALSE(surface_seeds(field, 1.0, box, options).empty());
}

/// bench/mesh_bench.cpp's walk of unit Cauchy segments (degree 4, s = 4)
/// at its iso, f at 0.3 from the middle of a lone segment, meshed by the
/// grid at `size` with and without the continuation from the seeds (the
/// dense sampling, which needs no seed). Returns the seeded mesh's report.
KernelSpec walk_kernel() {
  KernelSpec kernel;
  kernel.family = KernelFamily::cauchy;
  kernel.degree = 4;
  kernel.s = 4.0;
  return kernel;
}

MeshReport expect_seeded_walk_mesh_is_dense(const Skeleton& skeleton, double size, std::size_t components) {
  const Skeleton lone({Primitive(Segment(Vec3::Zero(), Vec3::UnitX(), walk_kernel(), {1.0}))});
  MeshOptions options = options_at(lone.value(Vec3(0.5, 0.3, 0.0)), size);
  options.method = MeshMethod::grid;
  const ImplicitField field = skeleton_field(skeleton);
  MeshReport report;
  const TriangleMesh seeded = mesh_iso_surface(field, options, &report);
  ImplicitField dense = field;
  dense.enclosure = nullptr;
  options.grid_from_seeds = false;
  const TriangleMesh reference = mesh_iso_surface(dense, options);
  EXPECT_EQ(mesh_topology(seeded).components, components);
  EXPECT_EQ(seeded.triangles, reference.triangles);
  EXPECT_EQ(seeded.vertices, reference.vertices);
  return report;
}

TEST(MeshSeeds, AWalkInsideOneSurfaceIsSeededByTheRaysOfAFewSources) {
  // The grid's continuation meshes a surface from any one seed on it, so
  // the skeleton points joined through grid nodes inside the surface cast
  // the rays of one of them (region_seeds): 60 segments of the bench's
  // walk, one surface, seeded by a few sources' rays (those whose nearest
  // grid node lies outside the tube, 0.35 thick, cast their own), where one
  // source per voxel cast 380 seeds; the mesh is the dense sampling's all
  // the same.
  const Skeleton walk = walk_skeleton({60, 4, 4.0, {1.0}}, bench_walk_seed);
  const MeshReport report = expect_seeded_walk_mesh_is_dense(walk, 0.5, 1);
  EXPECT_LE(report.seeds, 30u);
}

TEST(MeshSeeds, ASmallComponentFarFromAWalkIsStillMeshed) {
  // A Cauchy point of weight 10 six units beyond the walk's box, its blob
  // (f ≥ iso within 0.51 of it: (1 + 16 r²)² = 10 / iso) a region of its
  // own: its rays seed it, and the mesh has it.
  const Skeleton walk = walk_skeleton({60, 4, 4.0, {1.0}}, bench_walk_seed);
  std::vector<Primitive> primitives = walk.primitives();
  primitives.emplace_back(PointPrimitive(Vec3(-6.0, -6.0, -6.0), walk_kernel(), 10.0));
  const MeshReport report = expect_seeded_walk_mesh_is_dense(Skeleton(std::move(primitives)), 0.5, 2);
  EXPECT_LE(report.seeds, 36u);
}

TEST(MeshSeeds, ACavityOnlyADeferredSourcesRaysMeetIsMeshed) {
  // A ball of radius 1 (f = 2 − |p|², iso 1) with a cavity around
  // c = (0.3, 0.3, 0): f − 3 exp(−|p − c|²/0.01) < 1 within ~0.11 of c
  // (3 e^(−d²/0.01) = 1 − |c|² at d = 0.114). The skeleton points along
  // the x axis form one region; the rays of its first, (−0.5, 0, 0), miss
  // the cavity, and the deferred sources, 0.5 or more from the ball's
  // mesh, cast theirs after it: (0.3, 0, 0)'s along +y meets the cavity,
  // whose seed no vertex is near, so the grid is sampled again from it.
  // The mesh is the dense sampling's: the sphere and the cavity.
  const Vec3 c(0.3, 0.3, 0.0);
  ImplicitField field;
  field.value = [c](const Vec3& p) { return 2.0 - p.squaredNorm() - 3.0 * std::exp(-(p - c).squaredNorm() / 0.01); };
  field.value_and_gradient = [c](const Vec3& p) {
    const double bump = 3.0 * std::exp(-(p - c).squaredNorm() / 0.01);
    return FieldSample{2.0 - p.squaredNorm() - bump, -2.0 * p + bump * 2.0 * (p - c) / 0.01};
  };
  for (int k = -10; k <= 10; ++k) field.skeleton_points.push_back(Vec3(0.05 * k, 0.0, 0.0));
  MeshOptions options = options_at(1.0, 0.05);
  options.method = MeshMethod::grid;
  const TriangleMesh seeded = mesh_iso_surface(field, options);
  options.grid_from_seeds = false;
  const TriangleMesh reference = mesh_iso_surface(field, options);
  EXPECT_EQ(mesh_topology(seeded).components, 2u);
  EXPECT_EQ(seeded.triangles, reference.triangles);
  EXPECT_EQ(seeded.vertices, reference.vertices);
}

TEST(MeshScale, TheBoxAndSeedsFollowTheSkeletonScale) {
  // Nothing in the mesher has a length of its own: the box, the seeds and
  // the facet sizes follow the skeleton, so the same shape at scale α gives
  // the same mesh scaled by α (up to rounding, which may change a few
  // refinement decisions).
  const Skeleton skeleton = load("rings_linked");
  const TriangleMesh reference = mesh_iso_surface(skeleton_field(skeleton), options_at(0.38));
  for (const double alpha : {1e-4, 1e4}) {
    const TriangleMesh mesh = mesh_iso_surface(scaled(skeleton, alpha), options_at(0.38));
    SurfaceMesh surface = to_surface_mesh(mesh);
    EXPECT_TRUE(CGAL::is_closed(surface));
    const auto components = components_of(surface);
    ASSERT_EQ(components.size(), 2u) << "alpha = " << alpha;
    for (const auto& [chi, volume] : components) EXPECT_EQ(chi, 0) << "alpha = " << alpha;
    EXPECT_NEAR(bounding_diagonal(mesh) / alpha, bounding_diagonal(reference), 1e-6 * bounding_diagonal(reference));
    EXPECT_NEAR(double(mesh.triangles.size()), double(reference.triangles.size()), 0.05 * double(reference.triangles.size()));
  }
}

TEST(MeshDeterminism, SameInputSameMesh) {
  const Skeleton skeleton = load("figure_eight");
  for (const MeshMethod method : {MeshMethod::cgal, MeshMethod::grid}) {
    MeshOptions options = options_at(0.4);
    options.method = method;
    const TriangleMesh first = mesh_iso_surface(skeleton_field(skeleton), options);
    const TriangleMesh second = mesh_iso_surface(skeleton_field(skeleton), options);
    EXPECT_EQ(first.vertices, second.vertices);
    EXPECT_EQ(first.normals, second.normals);
    EXPECT_EQ(first.triangles, second.triangles);
  }
}

TEST(MeshThreads, EveryThreadCountGivesTheOneThreadMesh) {
  // The seeds' rays, the grid's continuation (a wave of cells at a time)
  // and the projection run on MeshOptions::threads threads, each ray, cell
  // or vertex into its own slot: the mesh must be one thread's to the bit.
  // Zanni's ant (24 Cauchy SCALIS segments) in the tolerance mode, where a
  // grid node's value depends on which cell samples it (value_near's rules
  // are chosen for a ball around that cell), the grid cases (compact and
  // infinite supports, SCALIS, several components) and one CGAL case.
  struct Run {
    std::string name;
    Skeleton skeleton;
    double tolerance;
    MeshOptions options;
  };
  std::vector<Run> runs;
  {
    MeshOptions options = options_at(1.0, 0.12);
    options.method = MeshMethod::grid;
    runs.push_back({"ant", load_skeleton_file(SKELCONV_ANT_SKELETON), Skeleton::default_tolerance, options});
  }
  for (const TopologyCase& c : grid_cases())
    runs.push_back({c.skeleton, load(c.skeleton), 0.0, options_at(c.iso, c.size, c.distance)});
  for (std::size_t k = 1; k < runs.size(); ++k) runs[k].options.method = MeshMethod::grid;
  runs.push_back({"figure_eight (cgal)", load("figure_eight"), 0.0, options_at(0.4)});
  for (Run& run : runs) {
    const ImplicitField field = skeleton_field(run.skeleton, 4, run.tolerance);
    run.options.threads = 1;
    const TriangleMesh one = mesh_iso_surface(field, run.options);
    for (const unsigned threads : {2u, 3u}) {
      run.options.threads = threads;
      const TriangleMesh many = mesh_iso_surface(field, run.options);
      const std::string what = run.name + ", " + std::to_string(threads) + " threads";
      EXPECT_EQ(many.vertices, one.vertices) << what;
      EXPECT_EQ(many.normals, one.normals) << what;
      EXPECT_EQ(many.triangles, one.triangles) << what;
    }
  }
}

TEST(MeshGrid, SkippingBlocksOutsideTheSupportsChangesNothing) {
  // The grid method fills the blocks no support box meets with the level of
  // f = 0 instead of evaluating them: the same node values, so the same mesh.
  EXPECT_FALSE(skeleton_field(load("segment")).support_boxes.has_value());  // Cauchy: infinite support
  for (const auto& [name, iso] : {std::pair{"ring", 0.38}, std::pair{"blend_tree", 0.5}}) {
    const Skeleton skeleton = load(name);
    const ImplicitField field = skeleton_field(skeleton);
    ASSERT_TRUE(field.support_boxes.has_value()) << name;
    ImplicitField dense = field;
    dense.support_boxes.reset();
    dense.enclosure = nullptr;
    ImplicitField skipping_field = field;
    skipping_field.enclosure = nullptr;  // only the support boxes skip here
    MeshOptions options = options_at(iso);
    options.method = MeshMethod::grid;
    options.grid_from_seeds = false;  // the sweep of the whole grid
    MeshReport skipping_report, dense_report;
    const TriangleMesh skipping = mesh_iso_surface(skipping_field, options, &skipping_report);
    const TriangleMesh reference = mesh_iso_surface(dense, options, &dense_report);
    EXPECT_EQ(skipping.vertices, reference.vertices) << name;
    EXPECT_EQ(skipping.normals, reference.normals) << name;
    EXPECT_EQ(skipping.triangles, reference.triangles) << name;
    EXPECT_LT(skipping_report.field_evaluations, dense_report.field_evaluations) << name;
  }
}

TEST(MeshGrid, SkippingBlocksTheEnclosureProvesEmptyChangesNothing) {
  // The grid method samples only the blocks whose interval enclosure holds
  // the iso (a narrow band): on fields of infinite support (Cauchy
  // segments, SCALIS segments and triangles) the same mesh as the dense
  // sampling, with fewer evaluations.
  for (const auto& [name, iso] :
       {std::pair{"segment", 0.5}, std::pair{"scalis_cone", 0.8}, std::pair{"scalis_triangle", 0.6}}) {
    const Skeleton skeleton = load(name);
    const ImplicitField field = skeleton_field(skeleton);
    ASSERT_TRUE(field.enclosure) << name;
    ImplicitField dense = field;
    dense.enclosure = nullptr;
    MeshOptions options = options_at(iso);
    options.method = MeshMethod::grid;
    options.grid_from_seeds = false;  // the sweep of the whole grid
    MeshReport band_report, dense_report;
    const TriangleMesh band = mesh_iso_surface(field, options, &band_report);
    const TriangleMesh reference = mesh_iso_surface(dense, options, &dense_report);
    EXPECT_EQ(band.vertices, reference.vertices) << name;
    EXPECT_EQ(band.normals, reference.normals) << name;
    EXPECT_EQ(band.triangles, reference.triangles) << name;
    EXPECT_LT(band_report.field_evaluations, dense_report.field_evaluations) << name;
  }
  // The blocks really are skipped on the enclosure's word: a false one
  // ("inside" wherever it is asked, i.e. far from the surface) changes the
  // mesh, or leaves vertices that cannot be projected.
  const Skeleton skeleton = load("segment");
  ImplicitField wrong = skeleton_field(skeleton);
  wrong.enclosure = [](const Eigen::AlignedBox3d&) { return std::pair{1.01 * 0.5, 2.0}; };
  ImplicitField dense = skeleton_field(skeleton);
  dense.enclosure = nullptr;
  MeshOptions options = options_at(0.5);
  options.method = MeshMethod::grid;
  options.grid_from_seeds = false;
  const TriangleMesh reference = mesh_iso_surface(dense, options);
  bool differs = false;
  try {
    differs = mesh_iso_surface(wrong, options).triangles != reference.triangles;
  } catch (const EvaluationError&) {
    differs = true;
  }
  EXPECT_TRUE(differs);
}

TEST(MeshGrid, SamplingFromTheSeedsGivesTheDenseSamplingsMesh) {
  // The default grid sampling visits only the cells whose corners change
  // sign, by continuation from the seeds, and infers the sign of every
  // other node: on every topology of the grid cases (two linked tori, genus
  // 2, separate components, compact and infinite supports, SCALIS) the
  // mesh is the dense sampling's, with fewer evaluations.
  for (const TopologyCase& c : grid_cases()) {
    const Skeleton skeleton = load(c.skeleton);
    const ImplicitField field = skeleton_field(skeleton);
    ImplicitField dense = field;
    dense.support_boxes.reset();
    dense.enclosure = nullptr;
    MeshOptions options = options_at(c.iso, c.size, c.distance);
    options.method = MeshMethod::grid;
    MeshReport seeded_report, dense_report;
    const TriangleMesh seeded = mesh_iso_surface(field, options, &seeded_report);
    options.grid_from_seeds = false;
    const TriangleMesh reference = mesh_iso_surface(dense, options, &dense_report);
    EXPECT_EQ(seeded.vertices, reference.vertices) << c.skeleton;
    EXPECT_EQ(seeded.normals, reference.normals) << c.skeleton;
    EXPECT_EQ(seeded.triangles, reference.triangles) << c.skeleton;
    EXPECT_LT(seeded_report.field_evaluations, dense_report.field_evaluations) << c.skeleton;
  }
}

TEST(MeshGrid, UnprojectedMeshHasTheProjectedMeshsTopologyAndProjectsToIt) {
  // MeshOptions::project = false (the medial fit's topology guard): the
  // vertices are left where the grid put them and the triangles are the
  // projected mesh's, so the topology is the table's (the Euler
  // characteristic per component of a tube around each skeleton, not
  // taken from the mesher); project_iso_surface then gives the projected
  // mesh to the bit.
  for (const TopologyCase& c : grid_cases()) {
    const Skeleton skeleton = load(c.skeleton);
    const ImplicitField field = skeleton_field(skeleton);
    MeshOptions options = options_at(c.iso, c.size, c.distance);
    options.method = MeshMethod::grid;
    MeshReport report;
    const TriangleMesh projected = mesh_iso_surface(field, options, &report);
    options.project = false;
    TriangleMesh unprojected = mesh_iso_surface(field, options);
    EXPECT_EQ(unprojected.triangles, projected.triangles) << c.skeleton;
    EXPECT_TRUE(unprojected.normals.empty()) << c.skeleton;
    EXPECT_NE(unprojected.vertices, projected.vertices) << c.skeleton << ": not projected";
    SurfaceMesh surface = to_surface_mesh(unprojected);
    std::vector<long long> euler;
    for (const auto& [chi, volume] : components_of(surface)) euler.push_back(chi);
    std::vector<long long> expected = c.euler_per_component;
    std::sort(euler.begin(), euler.end());
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(euler, expected) << c.skeleton;
    long long chi = 0;
    for (const long long e : expected) chi += e;
    const MeshTopology topology = mesh_topology(unprojected);
    EXPECT_EQ(topology.euler_characteristic, chi) << c.skeleton;
    EXPECT_EQ(topology.components, expected.size()) << c.skeleton;
    project_iso_surface(unprojected, field, options, report.size);
    EXPECT_EQ(unprojected.vertices, projected.vertices) << c.skeleton;
    EXPECT_EQ(unprojected.normals, projected.normals) << c.skeleton;
  }
}

TEST(MeshGrid, ASolidInteriorFilledByTilesGivesTheDenseSamplingsMesh) {
  // A ball of radius 1 (f = 2 − |p|², iso 1) at 1/20 of its radius: most of
  // its interior lies in blocks of 8³ nodes that the continuation from the
  // seeds never reaches, which the sign filling stores as tiles rather than
  // node by node (grid_surface_mesher.cpp, fill_signs). The mesh must be
  // the dense sampling's, which stores every node's own value.
  ImplicitField field;
  field.value = [](const Vec3& p) { return 2.0 - p.squaredNorm(); };
  field.value_and_gradient = [](const Vec3& p) { return FieldSample{2.0 - p.squaredNorm(), -2.0 * p}; };
  field.skeleton_points = {Vec3::Zero()};
  MeshOptions options = options_at(1.0, 0.05);
  options.method = MeshMethod::grid;
  const TriangleMesh seeded = mesh_iso_surface(field, options);
  options.grid_from_seeds = false;
  const TriangleMesh reference = mesh_iso_surface(field, options);
  ASSERT_GT(seeded.triangles.size(), 5000u);
  EXPECT_EQ(seeded.vertices, reference.vertices);
  EXPECT_EQ(seeded.triangles, reference.triangles);
}

// A Cauchy capsule carved by a negative-weight inverse segment (a cavity
// about 0.08 in radius) whose skeleton, on the x axis, holds grid nodes at
// these spacings. f = +inf marks an inverse primitive's skeleton whatever
// its weight (docs/field.md); the grid must not take those nodes as inside
// the surface, which made spurious pieces: 3, 2 (χ 2), 6 and 1 components at
// these four spacings. The surface is the capsule and the cavity: two
// spheres. (Not in the topology table: the cavity's boundary encloses a
// negative volume.)
TEST(MeshGrid, NodesOnACarvingInverseSkeletonAreOutside) {
  const Skeleton skeleton = load("carved_segment");
  for (const double size : {0.05, 0.0625, 0.08, 0.1}) {
    MeshOptions options = options_at(0.5, size, 0);
    options.method = MeshMethod::grid;
    const MeshTopology topology = mesh_topology(mesh_iso_surface(skeleton_field(skeleton), options));
    EXPECT_EQ(topology.components, 2u) << "size " << size;
    EXPECT_EQ(topology.euler_characteristic, 4) << "size " << size;
    EXPECT_TRUE(topology.closed) << "size " << size;
  }
}

TEST(MeshBadInput, NoSurfaceUnboundedAndBadSizes) {
  const Skeleton skeleton = load("segment");
  const ImplicitField field = skeleton_field(skeleton);
  // The field's largest value is 0.643 (middle of the segment, eval): iso 0.7 has no surface.
  EXPECT_THROW(mesh_iso_surface(field, options_at(0.7)), InputError);
  for (const double iso : {0.0, -1.0}) EXPECT_THROW(mesh_iso_surface(field, options_at(iso)), InputError);
  EXPECT_THROW(mesh_iso_surface(field, options_at(0.5, -1.0)), InputError);
  EXPECT_THROW(mesh_iso_surface(field, options_at(0.5, 0.1, -1.0)), InputError);
}

/// Runs `skelconv mesh <arguments>`; returns the exit status and stdout.
std::pair<int, std::string> run_mesh_command(const std::string& arguments) {
  const std::string command = std::string("'") + SKELCONV_BINARY + "' mesh " + arguments + " 2>/dev/null";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) throw std::runtime_error("cannot run " + command);
  std::string output;
  char buffer[4096];
  while (std::size_t count = std::fread(buffer, 1, sizeof buffer, pipe)) output.append(buffer, count);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

/// A fresh empty directory for one test.
std::filesystem::path empty_directory() {
  const auto directory = std::filesystem::path(testing::TempDir()) /
                         ("skelconv_mesh_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()) +
                          "_" + std::to_string(getpid()));
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  return directory;
}

TEST(MeshCommand, FailuresWriteNothing) {
  const auto directory = empty_directory();
  const std::string skeleton = "'" + std::string(SKELCONV_TEST_DATA) + "/mesh/segment.json'";
  for (const std::string options : {"--iso 0.7", "--iso 0", "--iso 0.5 --size 0"}) {
    const auto [status, output] = run_mesh_command(skeleton + " -o '" + (directory / "out.ply").string() + "' " + options);
    EXPECT_EQ(status, 2) << options;
    EXPECT_EQ(output, "") << options;
    EXPECT_TRUE(std::filesystem::is_empty(directory)) << options << ": a file was left in " << directory;
  }
  std::filesystem::remove_all(directory);
}

TEST(MeshCommand, WritesAsciiPlyAndObjWithNormalsAndPrintsTheTopology) {
  const auto directory = empty_directory();
  const std::string skeleton = "'" + std::string(SKELCONV_TEST_DATA) + "/mesh/rings_side_by_side.json'";
  const auto [status, output] =
      run_mesh_command(skeleton + " --iso 0.38 --ascii -o '" + (directory / "rings.ply").string() + "'");
  ASSERT_EQ(status, 0);
  for (const char* line : {"components: 2\n", "euler_characteristic: 0\n", "closed: yes\n", "manifold: yes\n"}) {
    EXPECT_NE(output.find(line), std::string::npos) << line << " not in\n" << output;
  }
  std::ifstream ply(directory / "rings.ply");
  std::stringstream text;
  text << ply.rdbuf();
  EXPECT_EQ(text.str().rfind("ply\nformat ascii 1.0\n", 0), 0u);
  EXPECT_NE(text.str().find("property double nx\n"), std::string::npos);

  ASSERT_EQ(run_mesh_command(skeleton + " --iso 0.38 --quiet -o '" + (directory / "rings.obj").string() + "'").first, 0);
  std::ifstream obj(directory / "rings.obj");
  std::size_t v = 0, vn = 0, f = 0;
  for (std::string line; std::getline(obj, line);) {
    v += line.rfind("v ", 0) == 0;
    vn += line.rfind("vn ", 0) == 0;
    f += line.rfind("f ", 0) == 0;
  }
  EXPECT_GT(f, 0u);
  EXPECT_EQ(v, vn);
  EXPECT_NE(output.find("triangles: " + std::to_string(f) + "\n"), std::string::npos) << output;
  std::filesystem::remove_all(directory);
}

// A field of compact support, f(p) = (1 − |p|²)³ inside the unit ball, 0
// outside: the level 1/2 is the sphere of radius √(1 − 2^(−1/3)).
ImplicitField compact_bump() {
  ImplicitField field;
  field.value_and_gradient = [](const Vec3& p) {
    const double u = 1.0 - p.squaredNorm();
    if (u <= 0.0) return FieldSample{0.0, Vec3::Zero()};
    return FieldSample{u * u * u, -6.0 * u * u * p};
  };
  field.value = [](const Vec3& p) { return std::pow(std::max(0.0, 1.0 - p.squaredNorm()), 3); };
  return field;
}

// A vertex outside every support (f = 0, ∇f = 0: Newton has no direction)
// but within max_step of the surface ends on it, within the tolerance, with
// the outward normal; one farther than max_step is still an error.
TEST(MeshProjection, AVertexOutsideEverySupportReachesTheSurfaceByBisection) {
  const ImplicitField field = compact_bump();
  const double radius = std::sqrt(1.0 - std::cbrt(0.5));
  const ProjectionOptions options{.tolerance = 1e-10, .max_step = 1.0};
  TriangleMesh mesh;
  mesh.vertices = {Vec3(1.2, 0.0, 0.0), Vec3(0.0, -0.3, 1.1)};
  mesh.triangles = {{0, 1, 0}};
  project_to_surface(mesh, field, 0.5, options);
  for (std::size_t k = 0; k < mesh.vertices.size(); ++k) {
    EXPECT_NEAR(mesh.vertices[k].norm(), radius, options.tolerance) << "vertex " << k;
    EXPECT_NEAR(mesh.normals[k].dot(mesh.vertices[k].normalized()), 1.0, 1e-12) << "vertex " << k;
  }
  TriangleMesh far;
  far.vertices = {Vec3(3.0, 0.0, 0.0)};
  far.triangles = {{0, 0, 0}};
  try {
    project_to_surface(far, field, 0.5, options);
    ADD_FAILURE() << "a vertex 2.5 from the surface with max_step 1 was projected";
  } catch (const EvaluationError& error) {
    EXPECT_NE(std::string(error.what()).find("no point on the other side of the level"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace skelconv
