// The canal-surface sweep (skelconv/canal/canal_mesh.hpp): watertight,
// consistently oriented, the topology of a sphere when capped, and the
// volume of the union of the balls.
#include <cmath>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "skelconv/canal/canal_family.hpp"
#include "skelconv/canal/canal_mesh.hpp"

namespace skelconv::canal {
namespace {

/// Directed edge → how many triangles use it.
std::map<std::pair<int, int>, int> directed_edges(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> edges;
  for (const auto& triangle : mesh.triangles) {
    for (int k = 0; k < 3; ++k) ++edges[{triangle[k], triangle[(k + 1) % 3]}];
  }
  return edges;
}

/// Every edge in exactly two triangles, once in each direction (consistent
/// orientation); returns the number of undirected edges.
int expect_closed_and_oriented(const TriangleMesh& mesh) {
  int undirected = 0;
  const auto edges = directed_edges(mesh);
  for (const auto& [edge, count] : edges) {
    EXPECT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second << " used twice in one direction";
    const auto reverse = edges.count({edge.second, edge.first});
    EXPECT_EQ(reverse, 1u) << "edge " << edge.first << "-" << edge.second << " has no opposite";
    ++undirected;
  }
  return undirected / 2;
}

/// Signed volume (divergence theorem): > 0 when triangles face outwards.
double signed_volume(const TriangleMesh& mesh) {
  double volume = 0;
  for (const auto& t : mesh.triangles) {
    volume += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]])) / 6;
  }
  return volume;
}

std::vector<FamilySample<double>> linear_samples(const std::vector<Sphere<double>>& spheres, int count) {
  const LinearSphereFamily<double> family(spheres);
  std::vector<FamilySample<double>> samples;
  for (int j = 0; j < count; ++j) samples.push_back(family.sample(double(j) / (count - 1)));
  return samples;
}

TEST(CanalMesh, CappedCylinderIsWatertightWithTheVolumeOfACapsule) {
  const double r = 0.5, length = 3;
  const TriangleMesh mesh = mesh_canal_surface(linear_samples({{Vec3(0, 0, 0), r}, {Vec3(length, 0, 0), r}}, 9));
  const int edges = expect_closed_and_oriented(mesh);
  EXPECT_EQ(int(mesh.vertices.size()) - edges + int(mesh.triangles.size()), 2) << "Euler characteristic";
  // Inscribed polygons of 64 sides lose 1 − sin(2π/64)·64/(2π) = 0.16% of the
  // area of a section; the capsule's volume is π r² L + 4/3 π r³.
  const double capsule = std::numbers::pi * r * r * length + 4.0 / 3 * std::numbers::pi * r * r * r;
  EXPECT_NEAR(signed_volume(mesh) / capsule, 1.0, 0.004);
  EXPECT_LT(signed_volume(mesh), capsule);
  ASSERT_EQ(mesh.normals.size(), mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) EXPECT_NEAR(mesh.normals[i].norm(), 1.0, 1e-14);
}

TEST(CanalMesh, ConeFrustumVerticesLieOnTheCone) {
  // Spheres (0, 0.2) and (2, 0.6): r = 0.2 + 0.2 x along the axis, so the
  // envelope is the cone of apex x = −1 and half-angle asin(0.2).
  const TriangleMesh mesh = mesh_canal_surface(linear_samples({{Vec3(0, 0, 0), 0.2}, {Vec3(2, 0, 0), 0.6}}, 5),
                                               CanalMeshOptions{.ring_points = 32, .caps = false});
  const double half_angle = std::asin(0.2);
  for (const Vec3& p : mesh.vertices) {
    EXPECT_NEAR(std::hypot(p.y(), p.z()), (p.x() + 1) * std::tan(half_angle), 1e-13);
  }
  // Open tube: V − E + F = 0, and 2 × 32 boundary edges with no opposite.
  int boundary = 0;
  const auto edges = directed_edges(mesh);
  for (const auto& [edge, count] : edges) boundary += edges.count({edge.second, edge.first}) == 0;
  EXPECT_EQ(boundary, 64);
  EXPECT_EQ(int(mesh.vertices.size()) - int(edges.size() + boundary) / 2 + int(mesh.triangles.size()), 0);
}

TEST(CanalMesh, LorentzFamilyIsWatertightAndFacesOutwards) {
  std::vector<Vector5<double>> spheres;
  for (int k = 0; k < 5; ++k) {
    const double s = k / 4.0;
    spheres.push_back(sphere_vector(Sphere<double>{Vec3(3 * s, std::sin(2 * s), 0.3 * s), 0.4 + 0.2 * s * (1 - s)}));
  }
  const SphereInterpolation<double> family(spheres, sphere_vector(Sphere<double>{Vec3(-6, 5, 4), 1.0}));
  std::vector<FamilySample<double>> samples;
  for (int j = 0; j < 41; ++j) samples.push_back(sample_family(family, j / 40.0));
  const TriangleMesh mesh = mesh_canal_surface(samples);
  const int edges = expect_closed_and_oriented(mesh);
  EXPECT_EQ(int(mesh.vertices.size()) - edges + int(mesh.triangles.size()), 2);
  EXPECT_GT(signed_volume(mesh), 0);
}

TEST(CanalMesh, RefusesSamplesWithoutCirclesOrWithAChangeOfOrientation) {
  std::vector<FamilySample<double>> samples = linear_samples({{Vec3(0, 0, 0), 0.5}, {Vec3(2, 0, 0), 0.5}}, 3);
  samples[1].circle.reset();
  EXPECT_THROW(mesh_canal_surface(samples), EvaluationError);
  // Radii 0.5 and −0.5 three apart: a double cone through a point at x = 1.5.
  EXPECT_THROW(mesh_canal_surface(linear_samples({{Vec3(0, 0, 0), 0.5}, {Vec3(3, 0, 0), -0.5}}, 4)), EvaluationError);
  EXPECT_THROW(mesh_canal_surface({samples[0]}), InputError);
}

}  // namespace
}  // namespace skelconv::canal
