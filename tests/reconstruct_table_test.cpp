// The shape table of docs/reconstruction.md as a test (ctest label `long`:
// minutes, not run by CI): every test shape, noise-free and with noise
// 0.005 × the diagonal on its samples, through the whole reconstruction;
// the recovered skeleton has the known numbers of branches, ends and
// junctions, and, noise-free, the fitted surface is within the targets of
// docs/reconstruction_results.md: two-sided Hausdorff ≤ 2% and RMS ≤ 0.5%
// of the bounding-box diagonal. Every stage's distances are printed (the table).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "skelconv/mesh/mesh_iso_surface.hpp"
#include "skelconv/mesh/mesh_reader.hpp"
#include "skelconv/reconstruct/reconstruct.hpp"
#include "skelconv/reconstruct/sample_noise.hpp"
#include "skelconv/reconstruct/skeleton_comparison.hpp"
#include "skelconv/skeleton/skeleton_file.hpp"

namespace skelconv::reconstruct {
namespace {

const std::filesystem::path data = std::filesystem::path(SKELCONV_TEST_DATA) / "reconstruct";

/// The stored mesh, or (the tree: 63 k triangles, not stored) the mesh of
/// NAME.json as `skelconv mesh NAME.json --size 0.1 --distance 0.02` makes it.
Skeleton known_skeleton(const std::string& name) {
  std::ifstream in(data / (name + ".json"));
  std::stringstream text;
  text << in.rdbuf();
  return parse_skeleton_json(text.str());
}

TriangleMesh shape_mesh(const std::string& name) {
  if (std::filesystem::exists(data / (name + ".ply"))) return read_mesh(data / (name + ".ply"));
  const Skeleton skeleton = known_skeleton(name);
  MeshOptions options;
  options.iso = skeleton.iso();
  options.size = 0.1;
  options.distance = 0.02;
  return mesh_iso_surface(skeleton_field(skeleton), options);
}

struct Known {
  const char* name;
  std::size_t branches, ends, junctions;
};

class Table : public testing::TestWithParam<std::tuple<Known, double>> {};

TEST_P(Table, CountsAndDistances) {
  const auto& [known, noise] = GetParam();
  const TriangleMesh input = shape_mesh(known.name);
  ReconstructOptions options;
  options.method = SkeletonMethod::curve;  // the known branches are the curve path's
  // With noise of amplitude a, balls whose contacts span less than 4a are
  // pruned too (ReconstructOptions::prune_span: the noise moves a sample
  // by up to a√3, a span by twice that).
  options.prune_span = 4.0 * noise;
  const Reconstruction r = reconstruct(with_sample_noise(input, noise), options);
  // Against the known skeleton (skeleton_comparison.hpp), % of the diagonal.
  const std::vector<KnownSegment> known_skeleton_segments = known_segments(known_skeleton(known.name));
  Vec3 lo = input.vertices.front(), hi = lo;
  for (const Vec3& v : input.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  const double diagonal = (hi - lo).norm();
  const auto pct = [diagonal](double x) { return 100 * x / diagonal; };
  for (const Stage& stage : {r.stages[1], r.stages.back()}) {
    const SkeletonComparison c = compare_with_known(stage.branches, known_skeleton_segments, 1e-9 * diagonal);
    std::printf("| %s | %g | %s | %zu/%zu | %.2f / %.2f | %.2f / %.2f | %.2f / %.2f |\n", known.name, noise,
                stage.name.c_str(), c.junction.count, c.known_junctions, pct(c.junction.max), pct(c.junction.mean),
                pct(c.axis.max), pct(c.axis.mean), pct(c.radius.max), pct(c.radius.mean));
  }
  for (const Stage& stage : r.stages) {
    // A stage whose meshing would exceed the measuring budget (the raw
    // stage of noisy samples) is listed unmeasured; the fitted one never is.
    const std::string refused = over_measure_budget(measure_work(input, stage, options), options.measure_budget);
    if (!refused.empty()) {
      std::printf("| %s | %g | %zu | %s | %zu/%zu/%zu | %zu | — | — |\n", known.name, noise, r.samples,
                  stage.name.c_str(), stage.branches.size(), stage.ends, stage.junctions, stage.points);
      EXPECT_EQ(stage.name, "raw") << refused;
      continue;
    }
    const SurfaceDistance d = measure_stage(input, stage, options);
    std::printf("| %s | %g | %zu | %s | %zu/%zu/%zu | %zu | %.2f | %.2f |\n", known.name, noise, r.samples,
                stage.name.c_str(), stage.branches.size(), stage.ends, stage.junctions, stage.points,
                100 * d.hausdorff / d.diagonal, 100 * d.rms / d.diagonal);
    std::fflush(stdout);
    if (stage.name == "raw") continue;
    EXPECT_EQ(stage.branches.size(), known.branches) << stage.name;
    EXPECT_EQ(stage.ends, known.ends) << stage.name;
    EXPECT_EQ(stage.junctions, known.junctions) << stage.name;
    if (stage.name == "fitted" && noise == 0.0) {
      EXPECT_LE(d.hausdorff / d.diagonal, 0.02);
      EXPECT_LE(d.rms / d.diagonal, 0.005);
    }
  }
}

/// Readable, stable test names (tree_noisy), not the parameter's bytes
/// (gtest's default, which hold a pointer).
std::string shape_test_name(const testing::TestParamInfo<Table::ParamType>& info) {
  return std::string(std::get<0>(info.param).name) + (std::get<1>(info.param) == 0.0 ? "_clean" : "_noisy");
}

// Known skeletons (tests/data/reconstruct/*.json): a segment, a tripod, a
// ring of 16 segments, a binary tree of depth 3 (15 segments, 8 leaves + the
// root's foot = 9 ends, 7 junctions).
INSTANTIATE_TEST_SUITE_P(Shapes, Table,
                         testing::Combine(testing::Values(Known{"segment", 1, 2, 0}, Known{"tripod", 3, 3, 1},
                                                          Known{"torus", 1, 0, 0}, Known{"tree", 15, 9, 7}),
                                          testing::Values(0.0, 0.005)),
                         shape_test_name);

}  // namespace
}  // namespace skelconv::reconstruct
