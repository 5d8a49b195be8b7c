// The mesher's use of a field's coarse version (ImplicitField::coarse;
// docs/mesh.md, "Coarse samples"): the grid takes its samples' signs from
// it only where they cannot differ from the field's, and Newton's first
// step of each vertex from it, every step after it and the final check on
// the field.
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "skelconv/mesh/implicit_field.hpp"
#include "skelconv/mesh/mesh_iso_surface.hpp"

namespace skelconv {
namespace {

/// A ball of radius 1: f = 2 − |p|², iso 1, |∇f| = 2 on the surface.
double ball(const Vec3& p) { return 2.0 - p.squaredNorm(); }

/// What the ball's field was asked: the count of `value` calls and of
/// `value_and_gradient` calls, and how many `value` calls came before the
/// coarse field's first `value` call (the grid's first sample: the box and
/// the seeds ask the field alone, before).
struct Calls {
  std::mutex mutex;
  std::size_t values = 0;
  std::size_t samples = 0;
  std::optional<std::size_t> values_before_coarse;
};

/// The ball's field, its calls recorded in `calls`; with a coarse field
/// whose error is as large as its bound `coarse_tolerance` allows (0.999 of
/// it) and always towards and across the iso: every point within that
/// error of the surface is on the wrong side of it in the coarse field.
ImplicitField ball_field(Calls& calls, double coarse_tolerance) {
  ImplicitField field;
  field.value = [&calls](const Vec3& p) {
    const std::lock_guard lock(calls.mutex);
    ++calls.values;
    return ball(p);
  };
  field.value_and_gradient = [&calls](const Vec3& p) {
    const std::lock_guard lock(calls.mutex);
    ++calls.samples;
    return FieldSample{ball(p), -2.0 * p};
  };
  field.skeleton_points = {Vec3::Zero()};
  if (coarse_tolerance > 0) {
    const auto wrong = [coarse_tolerance](const Vec3& p) {
      const double f = ball(p);
      return f + (f < 1.0 ? 1.0 : -1.0) * 0.999 * coarse_tolerance * std::abs(f);
    };
    auto coarse = std::make_shared<ImplicitField>();
    coarse->value = [&calls, wrong](const Vec3& p) {
      const std::lock_guard lock(calls.mutex);
      if (!calls.values_before_coarse) calls.values_before_coarse = calls.values;
      return wrong(p);
    };
    coarse->value_and_gradient = [wrong](const Vec3& p) { return FieldSample{wrong(p), -2.0 * p}; };
    field.coarse = std::move(coarse);
    field.coarse_tolerance = coarse_tolerance;
  }
  return field;
}

MeshOptions grid_options(double size) {
  MeshOptions options;
  options.iso = 1.0;
  options.size = size;
  options.method = MeshMethod::grid;
  options.threads = 1;
  return options;
}

/// |f − iso| / |∇f| at each vertex, within the projection's tolerance.
void expect_on_the_ball(const TriangleMesh& mesh, const MeshOptions& options) {
  const double tolerance = options.projection_tolerance * bounding_box(mesh.vertices).diagonal();
  for (const Vec3& v : mesh.vertices) {
    ASSERT_LE(std::abs(ball(v) - 1.0) / (2.0 * v.norm()), tolerance) << v.transpose();
  }
}

// A coarse field 5% off, wrong-sided in a band about a voxel thick around
// the sphere at a voxel of 0.05: had the grid taken its signs there, the
// cells it crosses, and so the triangles, would differ (with the sign test
// dropped, coarse_sign_margin 0, they do). The triangles must be those of
// the field alone, and the vertices on the surface.
TEST(MeshCoarse, TheGridsSignsAreTheFieldsWhereverTheCoarseFieldErrs) {
  const MeshOptions options = grid_options(0.05);
  Calls plain_calls, coarse_calls;
  const TriangleMesh plain = mesh_iso_surface(ball_field(plain_calls, 0), options);
  const TriangleMesh coarse = mesh_iso_surface(ball_field(coarse_calls, 0.05), options);
  ASSERT_GT(plain.triangles.size(), 5000u);
  EXPECT_EQ(coarse.triangles, plain.triangles);
  ASSERT_EQ(coarse.vertices.size(), plain.vertices.size());
  expect_on_the_ball(coarse, options);
}

// Counts from Newton's convergence on the ball, at a voxel of 0.05: a grid
// vertex starts at most ~1% of a voxel (5e-4) from the sphere; a Newton
// step on f = 2 − |p|² leaves d²/(2r) (r ≈ 1), ~1.3e-7, and the coarse
// field's error (1e-6 f, ≤ 5e-7 along ∇f) at most adds that much; the next
// step leaves ~1e-13, far below the tolerance (1e-9 × 3.5 / 2). So after
// the coarse step the field is sampled twice per vertex (the step's end,
// then the next, which stops), against three times from the grid vertex
// itself (start, ~1e-7, stop). And the grid's nodes take their values from
// the coarse field: the field is asked at a node only where the coarse
// value lies within 4 × 1e-6 of the iso: |r − 1| ≲ 2.5e-6, where the only
// nodes of a 0.05 grid are those exactly on the sphere, the 30 integer
// solutions of a² + b² + c² = 20² if the box's corner lies on that lattice
// (the next nodes, a² + b² + c² = 399 or 401, are 1.25e-3 away). Without
// the coarse field the field is asked at every node sampled, thousands.
TEST(MeshCoarse, NewtonSamplesTheFieldTwiceAVertexAfterACoarseStepAndTheGridNotAtAll) {
  const MeshOptions options = grid_options(0.05);
  Calls plain_calls, coarse_calls;
  const TriangleMesh plain = mesh_iso_surface(ball_field(plain_calls, 0), options);
  const TriangleMesh coarse = mesh_iso_surface(ball_field(coarse_calls, 1e-6), options);
  const double vertices = double(coarse.vertices.size());
  ASSERT_GT(vertices, 2000);
  EXPECT_GE(double(plain_calls.samples), 2.9 * vertices);
  EXPECT_LE(double(coarse_calls.samples), 2.1 * vertices);
  ASSERT_TRUE(coarse_calls.values_before_coarse.has_value());
  EXPECT_LE(coarse_calls.values - *coarse_calls.values_before_coarse, 30u);
  EXPECT_EQ(coarse.triangles, plain.triangles);
  expect_on_the_ball(coarse, options);
}

}  // namespace
}  // namespace skelconv
