// The whole reconstruction on small meshes of known skeletons
// (tests/data/reconstruct/NAME.json meshed by `skelconv mesh --size 0.1`):
// the recovered skeleton has the known number of branches, ends and
// junctions, the junction is where the known skeleton says, and the fitted
// stage's surface is within the documented goal of the input
// (docs/reconstruction_results.md: noise-free, H ≤ 2%, RMS ≤ 0.5% of the
// diagonal), measured both ways, surface to surface.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <gtest/gtest.h>

#include "skelconv/errors.hpp"
#include "skelconv/mesh/mesh_reader.hpp"
#include "skelconv/reconstruct/reconstruct.hpp"

namespace skelconv::reconstruct {
namespace {

Reconstruction run(const char* name) {
  const TriangleMesh mesh = read_mesh(std::filesystem::path(SKELCONV_TEST_DATA) / "reconstruct" / name);
  ReconstructOptions options;
  options.method = SkeletonMethod::curve;  // the known branches are the curve path's
  return reconstruct(mesh, options);
}

/// The documented goal for the fitted stage of a noise-free shape
/// (docs/reconstruction_results.md): two-sided Hausdorff distance at most 2%
/// and RMS distance at most 0.5% of the input's bounding-box diagonal. The
/// whole shape is measured, ends and caps included.
void expect_fitted_surface_within_goal(const char* name, const Reconstruction& r) {
  const TriangleMesh mesh = read_mesh(std::filesystem::path(SKELCONV_TEST_DATA) / "reconstruct" / name);
  const Stage& fitted = r.stages.back();
  ASSERT_EQ(fitted.name, "fitted");
  const SurfaceDistance d = measure_stage(mesh, fitted, ReconstructOptions{});
  ASSERT_GT(d.diagonal, 0.0);
  std::printf("%s fitted: Hausdorff %.3f%%, RMS %.3f%% of the diagonal\n", name, 100 * d.hausdorff / d.diagonal,
              100 * d.rms / d.diagonal);
  EXPECT_LE(d.hausdorff / d.diagonal, 0.02) << name;
  EXPECT_LE(d.rms / d.diagonal, 0.005) << name;
}

void expect_counts(const Stage& stage, std::size_t branches, std::size_t ends, std::size_t junctions) {
  EXPECT_EQ(stage.branches.size(), branches) << stage.name;
  EXPECT_EQ(stage.ends, ends) << stage.name;
  EXPECT_EQ(stage.junctions, junctions) << stage.name;
}

// segment.json: one SCALIS segment (0,0,0)–(3,0,0) of radius 0.5.
TEST(Shapes, SegmentIsOneBranchWithinTheGoal) {
  const Reconstruction r = run("segment.ply");
  for (std::size_t k = 1; k < r.stages.size(); ++k) expect_counts(r.stages[k], 1, 2, 0);
  expect_fitted_surface_within_goal("segment.ply", r);
}

// tripod.json: three SCALIS segments from the origin, 120° apart.
TEST(Shapes, TripodHasOneJunctionNearTheOrigin) {
  const Reconstruction r = run("tripod.ply");
  for (std::size_t k = 1; k < r.stages.size(); ++k) expect_counts(r.stages[k], 3, 3, 1);
  const Branch& b = r.stages.back().branches[0];  // every branch starts or ends at the junction
  const Vec4 junction = b.points.front().head<3>().norm() < b.points.back().head<3>().norm() ? b.points.front()
                                                                                             : b.points.back();
  EXPECT_LT(junction.head<3>().norm(), 0.45) << junction.transpose();  // within the junction's radius 0.45
  expect_fitted_surface_within_goal("tripod.ply", r);
}

// torus.json: a ring of 16 SCALIS segments, radius 2 about the z axis.
TEST(Shapes, TorusIsOneClosedBranch) {
  const Reconstruction r = run("torus.ply");
  for (std::size_t k = 1; k < r.stages.size(); ++k) expect_counts(r.stages[k], 1, 0, 0);
  // The pruned level-set graph's points lie on the ring (within 0.1, a
  // quarter of the tube radius 0.4). No axis-position goal is documented for
  // the later stages (the smoothed one runs up to 0.102 off the ring): the
  // output is judged by the documented goal on the surface it gives, below.
  for (const Vec4& p : r.stages[1].branches[0].points) {
    EXPECT_NEAR(p.head<2>().norm(), 2.0, 0.1) << p.transpose();  // on the ring
  }
  expect_fitted_surface_within_goal("torus.ply", r);
}

// The measuring budget (measure_work): the nodes of the mesh's bounding box
// at spacing h = diagonal / 100 with one voxel of margin each side,
// ⌊extent / h⌋ + 3 per axis, times the stage's primitives (2 segments).
// Within the budget the stage is measured; above it, over_measure_budget
// says why and measure_stage refuses with that message, at the stage.
TEST(Shapes, MeasuringBudget) {
  const TriangleMesh mesh = read_mesh(std::filesystem::path(SKELCONV_TEST_DATA) / "reconstruct" / "segment.ply");
  Vec3 lo = mesh.vertices.front(), hi = lo;
  for (const Vec3& v : mesh.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  const double h = (hi - lo).norm() / 100;
  double nodes = 1;
  for (int axis = 0; axis < 3; ++axis) nodes *= std::floor((hi[axis] - lo[axis]) / h) + 3;
  Stage stage;
  stage.name = "two";
  Branch b;
  b.points = {Vec4(0, 0, 0, 0.5), Vec4(1.5, 0, 0, 0.5), Vec4(3, 0, 0, 0.5)};
  stage.branches = {b};
  ReconstructOptions options;
  options.end_extension = 0.0;  // exactly the two segments
  const MeasureWork work = measure_work(mesh, stage, options);
  EXPECT_EQ(work.primitives, 2u);
  EXPECT_DOUBLE_EQ(work.grid_nodes, nodes);
  EXPECT_TRUE(over_measure_budget(work, 2 * nodes).empty());
  const std::string refused = over_measure_budget(work, 2 * nodes - 1);
  EXPECT_NE(refused.find("not measured: meshing its 2 primitives"), std::string::npos) << refused;
  options.measure_budget = 2 * nodes - 1;
  try {
    measure_stage(mesh, stage, options);
    ADD_FAILURE() << "measured over the budget";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), "stage two");
    EXPECT_EQ(error.problem(), refused);
  }
  options.measure_budget = 2 * nodes;
  const SurfaceDistance d = measure_stage(mesh, stage, options);
  EXPECT_GT(d.diagonal, 0.0);
}

// A compact primitive (the medial mesh's) is evaluated only at the grid
// nodes inside its support box: one compact SCALIS segment of radius ρ
// (σ = 1.5, support σ ρ about the segment) costs the nodes of the segment's
// box grown by σ ρ, counted here node by node over the whole grid, not the
// whole grid (which every Cauchy primitive costs, MeasuringBudget above).
TEST(Shapes, MeasuringBudgetOfCompactPrimitives) {
  const TriangleMesh mesh = read_mesh(std::filesystem::path(SKELCONV_TEST_DATA) / "reconstruct" / "segment.ply");
  Vec3 lo = mesh.vertices.front(), hi = lo;
  for (const Vec3& v : mesh.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  const double h = (hi - lo).norm() / 100;
  const Vec3 a = 0.5 * (lo + hi), b = a + Vec3(0.3 * (hi.x() - lo.x()), 0, 0);
  const double radius = 0.031 * (hi - lo).norm();
  ReconstructOptions options;
  const double support = options.medial.kernel_sigma * radius;
  // Nodes at lo − h + k h, ⌊extent / h⌋ + 3 per axis.
  const auto nodes_inside = [&](double grow) {
    double count = 0;
    int n[3];
    for (int axis = 0; axis < 3; ++axis) n[axis] = int(std::floor((hi[axis] - lo[axis]) / h)) + 3;
    for (int i = 0; i < n[0]; ++i)
      for (int j = 0; j < n[1]; ++j)
        for (int k = 0; k < n[2]; ++k) {
          const Vec3 p = lo + Vec3(i - 1, j - 1, k - 1) * h;
          bool in = true;
          for (int axis = 0; axis < 3; ++axis)
            in = in && p[axis] >= std::min(a[axis], b[axis]) - grow && p[axis] <= std::max(a[axis], b[axis]) + grow;
          count += in;
        }
    return count;
  };
  const double expected = nodes_inside(support);
  // No node within a hundred-thousandth of the support of the box's faces:
  // the box's own margin (support_box.hpp, 1e-6 of it) decides none.
  ASSERT_EQ(nodes_inside(support * (1 - 1e-5)), expected);
  ASSERT_EQ(nodes_inside(support * (1 + 1e-5)), expected);
  Stage stage;
  stage.name = "medial";
  stage.medial.spheres = {Vec4(a.x(), a.y(), a.z(), radius), Vec4(b.x(), b.y(), b.z(), radius)};
  stage.medial.edges = {{0, 1}};
  const MeasureWork work = measure_work(mesh, stage, options);
  EXPECT_EQ(work.primitives, 1u);
  EXPECT_GT(expected, 0.0);
  EXPECT_LT(expected, work.grid_nodes / 10);
  EXPECT_DOUBLE_EQ(work.evaluations, expected);
}

// `auto` never returns more primitives than the budget: the tripod's curve
// skeleton (39 segments, ends extended: the curve path's result by
// default) is over a budget of 20, so it is not fitted and the result is
// the medial mesh, within the budget.
TEST(Shapes, AutoKeepsTheBudget) {
  const TriangleMesh mesh = read_mesh(std::filesystem::path(SKELCONV_TEST_DATA) / "reconstruct" / "tripod.ply");
  ReconstructOptions options;
  options.method = SkeletonMethod::automatic;
  options.medial.budget = 20;
  const Reconstruction r = reconstruct(mesh, options);
  EXPECT_EQ(r.stages.back().name, "medial");
  EXPECT_LE(primitive_counts(r.stages.back(), options).total(), 20u);
  EXPECT_GT(r.curve_over_budget, 20u);
  for (const Stage& s : r.stages) EXPECT_NE(s.name, "fitted");
}

}  // namespace
}  // namespace skelconv::reconstruct
