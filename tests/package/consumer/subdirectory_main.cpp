// The add_subdirectory consumer (tests/package/): f and ∇f of a skeleton file
// at the points on stdin, in the format of `skelconv eval`, through the
// public API only.
#include <skelconv/skelconv.hpp>

#include <cstdio>
#include <vector>

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  std::vector<skelconv::Vec3> points;
  double x = 0, y = 0, z = 0;
  while (std::scanf("%lf %lf %lf", &x, &y, &z) == 3) points.emplace_back(x, y, z);
  try {
    const skelconv::BatchResult result = skelconv::evaluate_batch(skelconv::load_skeleton_file(argv[1]), points);
    if (result.failure) std::rethrow_exception(result.failure->error);
    for (const skelconv::FieldSample& s : result.samples)
      std::printf("%.17g %.17g %.17g %.17g\n", s.value, s.gradient.x(), s.gradient.y(), s.gradient.z());
  } catch (const std::exception& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return 1;
  }
  return 0;
}
