// The tolerance mode where users meet it: `skelconv mesh` meshes with
// Skeleton's tolerance mode (skeleton_field's default, docs/field.md
// "Tolerance"); at every vertex of such a mesh of a random walk of Cauchy 4
// segments, f and ∇f of the mode must be within the stated tolerance of the
// direct sum of the exact segment fields (the generated functions, which
// verify/ checks against float128 quadrature). The 1,000-segment walk of
// bench/mesh_bench.cpp takes ~10 s (label long); CI meshes 100 segments.
// Part of skelconv_mesh_test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "skelconv/mesh/implicit_field.hpp"
#include "skelconv/mesh/mesh_iso_surface.hpp"
#include "walk_skeleton.hpp"

namespace skelconv {
namespace {

void check_mesh_vertices(int count, double size) {
  const Skeleton skeleton = walk_skeleton({count, 4, 4.0, {1.0}}, bench_walk_seed);
  KernelSpec kernel;
  kernel.family = KernelFamily::cauchy;
  kernel.degree = 4;
  kernel.s = 4.0;
  MeshOptions options;
  // As bench/mesh_bench.cpp: f at 0.3 from the middle of one segment.
  options.iso = Segment(Vec3(0, 0, 0), Vec3(1, 0, 0), kernel).value(Vec3(0.5, 0.3, 0));
  options.method = MeshMethod::grid;
  options.size = size;
  const double tolerance = Skeleton::default_tolerance;
  const TriangleMesh mesh = mesh_iso_surface(skeleton_field(skeleton), options);
  ASSERT_GT(mesh.vertices.size(), 2000u);
  const double gradient_scale = 2.0 * std::sqrt(4.0);  // (i/2) √s
  double worst_f = 0, worst_gradient = 0;
  int approximated = 0;
  for (const Vec3& v : mesh.vertices) {
    const FieldSample exact = skeleton.value_and_gradient(v);
    const FieldSample within = skeleton.value_and_gradient(v, tolerance);
    worst_f = std::max(worst_f, std::abs(within.value - exact.value) / (tolerance * exact.value));
    worst_gradient = std::max(worst_gradient, (within.gradient - exact.gradient).cwiseAbs().maxCoeff() /
                                                  (tolerance * gradient_scale * exact.value));
    approximated += within.value != exact.value;
  }
  std::printf("%d segments: %zu vertices, worst error / allowance %.2e (f), %.2e (grad f); %d vertices differ "
              "from the direct sum\n",
              count, mesh.vertices.size(), worst_f, worst_gradient, approximated);
  EXPECT_LE(worst_f, 1.0);
  EXPECT_LE(worst_gradient, 1.0);
  EXPECT_GT(approximated, 0);  // the mode is in use
}

TEST(FarSegmentRuleMesh, HundredSegmentWalk) { check_mesh_vertices(100, 0.25); }

// Disabled in CI (~10 s): ctest runs it as mesh.far_rule_vertices_long (label long).
TEST(FarSegmentRuleMesh, DISABLED_ThousandSegmentWalk) { check_mesh_vertices(1000, 0.5); }  // the bench's size

}  // namespace
}  // namespace skelconv
