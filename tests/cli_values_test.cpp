// End to end: `skelconv eval` on the schema example prints the field of the
// definition integral (checked against quadrature, reference_quadrature.hpp)
// and prints the runtime's doubles exactly (%.17g round-trips).
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "reference_quadrature.hpp"
#include "skelconv/skeleton_file.hpp"

#ifndef SKELCONV_BINARY
#error "SKELCONV_BINARY (path of the skelconv executable) is set by tests/CMakeLists.txt"
#endif
#ifndef SKELCONV_TEST_DATA
#error "SKELCONV_TEST_DATA (tests/data) is set by tests/CMakeLists.txt"
#endif

namespace skelconv {
namespace {

const std::string example_file = std::string(SKELCONV_TEST_DATA) + "/good/three_primitives.json";

const std::vector<Vec3> points{Vec3(0.5, 0.5, 0.5), Vec3(-0.7, 1.2, 0.9), Vec3(2.0, 2.5, -0.4),
                               Vec3(0.25, 1.75, 0.5), Vec3(1.5, -0.5, 0.3)};

/// Runs `skelconv eval example_file` with `points` on stdin; returns the
/// output lines parsed as "f gx gy gz".
std::vector<FieldSample> run_eval() {
  // One file per test and process: ctest runs the tests of this file in
  // parallel, and a shared name let one test delete the other's input.
  const std::string input_file = testing::TempDir() + "skelconv_cli_values_" +
                                 testing::UnitTest::GetInstance()->current_test_info()->name() + "_" +
                                 std::to_string(getpid()) + ".txt";
  {
    std::ofstream input(input_file);
    input.precision(17);
    for (const Vec3& p : points) input << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  }
  const std::string command = std::string("'") + SKELCONV_BINARY + "' eval '" + example_file + "' < '" + input_file + "'";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) throw std::runtime_error("cannot run " + command);
  std::string output;
  char buffer[4096];
  while (std::size_t count = std::fread(buffer, 1, sizeof buffer, pipe)) output.append(buffer, count);
  const int status = pclose(pipe);
  std::remove(input_file.c_str());
  EXPECT_EQ(status, 0) << command;

  std::vector<FieldSample> samples;
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    FieldSample sample;
    double gx = 0, gy = 0, gz = 0;
    EXPECT_EQ(std::sscanf(line.c_str(), "%lf %lf %lf %lf", &sample.value, &gx, &gy, &gz), 4) << line;
    sample.gradient = Vec3(gx, gy, gz);
    samples.push_back(sample);
  }
  return samples;
}

/// The schema example (tests/data/good/three_primitives.json), restated for
/// the reference quadrature.
std::vector<test::ReferenceSegment> example_reference() {
  std::vector<test::ReferenceSegment> segments(3);
  segments[0] = {{0, 0, 0}, {1, 0, 0}, {1, 0.5}, test::ReferenceFamily::inverse, 3, 1, 1};
  segments[1] = {{0, 1, 0}, {1, 1, 0}, {1}, test::ReferenceFamily::cauchy, 4, 2.0, 1};
  segments[2] = {{0, 2, 0}, {1, 2, 1}, {1}, test::ReferenceFamily::compact, 6, 1, 1.5};
  return segments;
}

TEST(CliEval, PrintsTheDefinitionIntegral) {
  // About ten times the worst relative error measured: 4.5e-16 for
  // ∇f, 4.0e-16 for f, through the CLI's %.17g output, against the long
  // double reference; a regression of a few digits fails.
  constexpr double tolerance = 5e-15;
  const std::vector<FieldSample> samples = run_eval();
  ASSERT_EQ(samples.size(), points.size());
  double worst_value = 0, worst_gradient = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    test::Real value = 0;
    test::Point gradient{0, 0, 0};
    for (const test::ReferenceSegment& segment : example_reference()) {
      const test::ReferenceSample term =
          test::integrate_definition(segment, {points[k].x(), points[k].y(), points[k].z()});
      value += term.value;
      for (int c = 0; c < 3; ++c) gradient[c] += term.gradient[c];
    }
    const Vec3 expected_gradient(static_cast<double>(gradient[0]), static_cast<double>(gradient[1]),
                                 static_cast<double>(gradient[2]));
    SCOPED_TRACE(testing::Message() << "P = " << points[k].transpose());
    worst_value = std::max(worst_value, std::abs(samples[k].value - double(value)) / std::abs(double(value)));
    worst_gradient =
        std::max(worst_gradient, (samples[k].gradient - expected_gradient).norm() / expected_gradient.norm());
    EXPECT_NEAR(samples[k].value, double(value), tolerance * std::abs(double(value)));
    EXPECT_LE((samples[k].gradient - expected_gradient).norm(), tolerance * expected_gradient.norm());
  }
  std::printf("CLI vs the definition: worst relative error of f %.1e, of grad f %.1e\n", worst_value, worst_gradient);
}

TEST(CliEval, PrintsTheRuntimeDoublesExactly) {
  const std::vector<FieldSample> samples = run_eval();
  ASSERT_EQ(samples.size(), points.size());
  const Skeleton skeleton = load_skeleton_file(example_file);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const FieldSample expected = skeleton.value_and_gradient(points[k]);
    EXPECT_EQ(samples[k].value, expected.value);
    EXPECT_EQ(samples[k].gradient, expected.gradient);
  }
}

}  // namespace
}  // namespace skelconv
