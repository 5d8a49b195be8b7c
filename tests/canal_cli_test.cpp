// End to end: `skelconv canal` prints the documented JSON, with the input
// spheres exactly at the knots, circles that lie on their spheres and match
// the closed form of item 3 for linear families, "circle": null where the
// family has no real circle, and writes the mesh.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "skelconv/canal/canal_file.hpp"
#include "skelconv/geometry.hpp"

#ifndef SKELCONV_BINARY
#error "SKELCONV_BINARY (path of the skelconv executable) is set by tests/CMakeLists.txt"
#endif
#ifndef SKELCONV_TEST_DATA
#error "SKELCONV_TEST_DATA (tests/data) is set by tests/CMakeLists.txt"
#endif

namespace skelconv::canal {
namespace {

const std::string data = std::string(SKELCONV_TEST_DATA) + "/canal/good/";

/// Runs `skelconv canal FILE extra`; returns stdout parsed, expecting exit 0.
nlohmann::json run_canal(const std::string& file, const std::string& extra = "") {
  const std::string command = std::string("'") + SKELCONV_BINARY + "' canal '" + data + file + "' " + extra;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) throw std::runtime_error("cannot run " + command);
  std::string output;
  char buffer[4096];
  while (std::size_t count = std::fread(buffer, 1, sizeof buffer, pipe)) output.append(buffer, count);
  EXPECT_EQ(pclose(pipe), 0) << command;
  return nlohmann::json::parse(output);
}

Vec3 point(const nlohmann::json& value) { return {value[0].get<double>(), value[1].get<double>(), value[2].get<double>()}; }

TEST(CanalCli, LorentzOutputHitsTheKnotsAndItsCirclesLieOnTheSpheres) {
  const std::string mesh = testing::TempDir() + "skelconv_canal_cli_" + std::to_string(getpid()) + ".ply";
  const nlohmann::json output = run_canal("lorentz_sphere_pole.json", "--mesh '" + mesh + "'");
  const CanalInput input = load_canal_file(data + "lorentz_sphere_pole.json");
  const nlohmann::json& samples = output.at("samples");
  ASSERT_EQ(samples.size(), 41u);
  for (std::size_t j = 0; j < samples.size(); ++j) {
    const nlohmann::json& sample = samples[j];
    EXPECT_EQ(sample.at("t").get<double>(), double(j) / 40);
    const Vec3 center = point(sample.at("sphere").at("center"));
    const double radius = sample.at("sphere").at("radius").get<double>();
    if (j % 10 == 0) {  // knots: 5 spheres, t = k/4
      EXPECT_EQ(center, input.spheres[j / 10].center);
      EXPECT_EQ(radius, input.spheres[j / 10].radius);
    }
    const nlohmann::json& circle = sample.at("circle");
    ASSERT_TRUE(circle.is_object()) << j;
    const Vec3 normal = point(circle.at("normal"));
    const Vec3 offset = point(circle.at("center")) - center;
    const double rho = circle.at("radius").get<double>();
    EXPECT_NEAR(normal.norm(), 1.0, 1e-15);
    // The circle is on the sphere: its centre moved along the normal and ρ² + δ² = r².
    EXPECT_LT((offset - offset.dot(normal) * normal).norm(), 1e-13) << j;
    EXPECT_NEAR(offset.squaredNorm() + rho * rho, radius * radius, 1e-13) << j;
  }
  EXPECT_GT(std::filesystem::file_size(mesh), 1000u);
  std::filesystem::remove(mesh);
}

TEST(CanalCli, APlanePoleKeepsTheMirrorSymmetryOfTheInput) {
  // Spheres symmetric under x ↦ 2 − x and a pole (the plane z = −3) that the
  // mirror leaves alone: the interpolated family is symmetric, sample j
  // mirrors sample N − 1 − j (centres, radii and circles; normals reversed in
  // x, then flipped, since t runs the other way).
  const std::string mesh = testing::TempDir() + "skelconv_canal_plane_" + std::to_string(getpid()) + ".obj";
  const nlohmann::json samples = run_canal("lorentz_plane_pole.json", "--mesh '" + mesh + "'").at("samples");
  ASSERT_EQ(samples.size(), 9u);
  const auto mirrored = [](Vec3 p) { return Vec3(2 - p.x(), p.y(), p.z()); };
  for (std::size_t j = 0; j < samples.size(); ++j) {
    const nlohmann::json& a = samples[j];
    const nlohmann::json& b = samples[samples.size() - 1 - j];
    EXPECT_LT((mirrored(point(a.at("sphere").at("center"))) - point(b.at("sphere").at("center"))).norm(), 1e-14);
    EXPECT_NEAR(a.at("sphere").at("radius").get<double>(), b.at("sphere").at("radius").get<double>(), 1e-14);
    EXPECT_LT((mirrored(point(a.at("circle").at("center"))) - point(b.at("circle").at("center"))).norm(), 1e-14);
    const Vec3 na = point(a.at("circle").at("normal")), nb = point(b.at("circle").at("normal"));
    EXPECT_LT((Vec3(na.x(), -na.y(), -na.z()) - nb).norm(), 1e-14) << j;
  }
  EXPECT_TRUE(std::filesystem::exists(mesh));
  std::filesystem::remove(mesh);
}

// Translations and homotheties are Möbius maps (docs/canal.md): the family
// of moved spheres about the moved pole is the moved family. Far from the
// origin (1e4, spheres of radius ~0.3) the pole was once refused as tangent;
// a sphere and a plane pole, the Lorentz and the linear families, at 1e4,
// and scaled by 2^±20. The bound is the input's rounding in the unit frame:
// ulp(1e4) / scale, with room for the conditioning of the family.
TEST(CanalCli, MovedAndScaledInputsGiveTheMovedFamily) {
  const auto json_of = [](const std::vector<Sphere<double>>& spheres, const std::string& pole) {
    std::string text = "{\"spheres\": [";
    for (std::size_t k = 0; k < spheres.size(); ++k) {
      const Sphere<double>& s = spheres[k];
      text += fmt::format("{}{{\"center\": [{:.17g}, {:.17g}, {:.17g}], \"radius\": {:.17g}}}", k ? ", " : "",
                          s.center.x(), s.center.y(), s.center.z(), s.radius);
    }
    return text + "], " + pole + "\"samples\": 17}";
  };
  const std::vector<Sphere<double>> spheres{{{0, 0, 0}, 0.3}, {{0.5, 0.4, 0}, 0.35}, {{1, 0.5, 0.1}, 0.4},
                                            {{1.5, 0.3, 0.2}, 0.35}, {{2, 0, 0.2}, 0.3}};
  const auto pole_text = [](int kind, const Vec3& shift, double scale) {
    if (kind == 0) {
      const Vec3 c = scale * Vec3(-5, 4, 3) + shift;
      return fmt::format("\"interpolation\": \"lorentz\", \"pole\": {{\"center\": [{:.17g}, {:.17g}, {:.17g}], "
                         "\"radius\": {:.17g}}}, ", c.x(), c.y(), c.z(), scale);
    }
    if (kind == 1) {  // the plane z = −3, moved: z = −3 scale + shift.z
      return fmt::format("\"interpolation\": \"lorentz\", \"pole\": {{\"normal\": [0, 0, 1], \"offset\": {:.17g}}}, ",
                         -3 * scale + shift.z());
    }
    return std::string("\"interpolation\": \"linear\", ");
  };
  for (int kind = 0; kind < 3; ++kind) {
    const std::vector<FamilySample<double>> reference = sample_canal(parse_canal_json(json_of(spheres, pole_text(kind, Vec3::Zero(), 1))));
    using Move = std::pair<Vec3, double>;  // shift, scale
    for (const auto& [shift, scale] : {Move{Vec3(1e4, -1e4, 1e4), 1.0}, Move{Vec3::Zero(), std::ldexp(1.0, 20)},
                                       Move{Vec3::Zero(), std::ldexp(1.0, -20)}}) {
      std::vector<Sphere<double>> moved;
      for (const Sphere<double>& s : spheres) moved.push_back(Sphere<double>{Vec3(scale * s.center + shift), scale * s.radius});
      const std::vector<FamilySample<double>> samples = sample_canal(parse_canal_json(json_of(moved, pole_text(kind, shift, scale))));
      ASSERT_EQ(samples.size(), reference.size());
      const double bound = shift.norm() > 0 ? 1e-10 : 1e-13;
      for (std::size_t j = 0; j < samples.size(); ++j) {
        const std::string where = fmt::format("pole kind {}, shift {}, scale {}, sample {}", kind, shift.x(), scale, j);
        EXPECT_LT(((samples[j].sphere.center - shift) / scale - reference[j].sphere.center).norm(), bound) << where;
        EXPECT_NEAR(samples[j].sphere.radius / scale, reference[j].sphere.radius, bound) << where;
        ASSERT_EQ(samples[j].circle.has_value(), reference[j].circle.has_value()) << where;
        if (!samples[j].circle) continue;
        EXPECT_LT(((samples[j].circle->center - shift) / scale - reference[j].circle->center).norm(), bound) << where;
        EXPECT_NEAR(samples[j].circle->radius / scale, reference[j].circle->radius, bound) << where;
        EXPECT_LT((samples[j].circle->normal - reference[j].circle->normal).norm(), bound) << where;
      }
    }
  }
}

TEST(CanalCli, LinearCirclesAreTheClosedFormAndNullAtAPoint) {
  // Radii 0.5 → −0.5 over a distance 3: r(t) = 0.5 − t, c(t) = (3t, 0, 0),
  // so the circle is at x = 3t − r r′·3/9 = 3t + r/3 with radius |r| √(1 − 1/9),
  // and at t = ½ the sphere is a point: no circle.
  const nlohmann::json samples = run_canal("linear_through_point.json").at("samples");
  ASSERT_EQ(samples.size(), 3u);
  for (int j : {0, 2}) {
    const double t = j / 2.0, r = 0.5 - t;
    const nlohmann::json& circle = samples[j].at("circle");
    EXPECT_NEAR(point(circle.at("center")).x(), 3 * t + r / 3, 1e-15);
    EXPECT_NEAR(circle.at("radius").get<double>(), std::abs(r) * std::sqrt(8.0 / 9), 1e-15);
    EXPECT_EQ(point(circle.at("normal")), Vec3(1, 0, 0));
  }
  EXPECT_TRUE(samples[1].at("circle").is_null());
  EXPECT_EQ(samples[1].at("sphere").at("radius").get<double>(), 0.0);
}

}  // namespace
}  // namespace skelconv::canal
