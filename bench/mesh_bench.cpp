// bench/mesh_bench.cpp — `skelconv mesh` throughput (docs/mesh.md).
//
// For skeletons of 10, 100 and 1,000 primitives of one kind (segments,
// SCALIS segments, polygons; compact and Cauchy kernels), laid along a
// deterministic random walk of unit steps, meshes the surface with
// mesh_iso_surface (the code `skelconv mesh` runs) and prints one Markdown
// table row per run: triangles, total time, time inside the field (and the
// number of evaluations and µs per evaluation), the rest (CGAL Mesh_3, the
// box search, seeding and projection bookkeeping: "mesher"), and triangles
// per second. The field is skeleton_field's, as `skelconv mesh` evaluates
// it: Skeleton::value with the support index (docs/field.md: compact
// primitives cost only where their support holds the point, infinite-support
// ones everywhere) and the default tolerance (lists of 16 or more Cauchy
// segments: docs/field.md, "Tolerance").
//
// Usage: skelconv_bench_mesh [--smoke] [--min-primitives N] [--max-primitives N]
//                            [--size H] [--kind "segment compact"] [--method cgal|grid]
//   --smoke: 10 primitives, segments only (ctest smoke run).
//   --kind: the kinds whose name contains this text ("compact": all compact).
// Times are CPU seconds of the process (the machine may be shared), the
// field's part estimated by its share of the wall-clock time.
// The facet size defaults to 0.12 (unit segments, tubes of radius ~0.3):
// about 100 triangles per primitive.
#include <chrono>
#include <cmath>
#include <ctime>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "skelconv/mesh/implicit_field.hpp"
#include "skelconv/mesh/mesh_iso_surface.hpp"
#include "skelconv/skeleton/skeleton.hpp"
#include "skelconv/skeleton/skeleton_file.hpp"

namespace {

using skelconv::Vec3;

struct Kind {
  const char* name;
  const char* type;    // JSON primitive type
  const char* kernel;  // JSON kernel object
  bool scalis;         // iso 1 by definition (SCALIS); else from a single primitive
};

const Kind kinds[] = {
    {"segment compact", "segment", R"({"family": "compact", "degree": 4, "R": 0.6})", false},
    {"segment cauchy", "segment", R"({"family": "cauchy", "degree": 4, "s": 4})", false},
    {"scalis_segment compact", "scalis_segment", R"({"family": "compact", "degree": 4, "sigma": 2})", true},
    {"scalis_segment cauchy", "scalis_segment", R"({"family": "cauchy", "degree": 4, "sigma": 1})", true},
    {"polygon compact", "polygon", R"({"family": "compact", "degree": 4, "R": 0.6})", false},
    {"polygon cauchy", "polygon", R"({"family": "cauchy", "degree": 4, "s": 16})", false},
};

std::string point(const Vec3& p) { return fmt::format("[{:.17g}, {:.17g}, {:.17g}]", p.x(), p.y(), p.z()); }

/// One primitive of `kind` starting at `a` in unit direction `d`.
std::string primitive(const Kind& kind, const Vec3& a, const Vec3& d) {
  const Vec3 b = a + d;
  if (std::strcmp(kind.type, "polygon") == 0) {
    // A triangle with one unit edge along d, the third vertex 0.6 off it.
    const Vec3 n = d.unitOrthogonal();
    return fmt::format(R"({{"type": "polygon", "vertices": [{}, {}, {}], "kernel": {}}})", point(a), point(b),
                       point(a + 0.5 * d + 0.6 * n), kind.kernel);
  }
  const std::string radius = kind.scalis ? R"(, "radius": [0.25, 0.25])" : "";
  return fmt::format(R"({{"type": "{}", "a": {}, "b": {}{}, "kernel": {}}})", kind.type, point(a), point(b), radius,
                     kind.kernel);
}

/// `count` primitives along a random walk of unit steps in a cube of side
/// 2 count^(1/3) + 2 (reflected at its faces), from a fixed seed.
std::string walk_skeleton(const Kind& kind, int count) {
  std::mt19937_64 random(20131);  // fixed: the same skeleton every run
  const auto uniform = [&random] { return double(random() >> 11) * 0x1.0p-53; };
  const double side = 2 * std::cbrt(double(count)) + 2;
  Vec3 p = Vec3::Constant(side / 2);
  std::string json = R"({"primitives": [)";
  for (int k = 0; k < count; ++k) {
    const double z = 2 * uniform() - 1, phi = 2 * M_PI * uniform();
    Vec3 d(std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z);
    for (int i = 0; i < 3; ++i) {
      if (p[i] + d[i] < 0 || p[i] + d[i] > side) d[i] = -d[i];
    }
    json += (k ? ",\n" : "\n") + primitive(kind, p, d);
    p += d;
  }
  return json + "]}";
}

/// The iso: f at 0.3 from the middle of a single primitive of this kind
/// (SCALIS: 1, f at distance τ by its normalisation).
double iso_for(const Kind& kind) {
  if (kind.scalis) return 1.0;
  const skelconv::Skeleton one = skelconv::parse_skeleton_json(
      R"({"primitives": [)" + primitive(kind, Vec3::Zero(), Vec3::UnitX()) + "]}");
  const bool polygon = std::strcmp(kind.type, "polygon") == 0;
  return one.value(polygon ? Vec3(0.5, 0.2, 0.3) : Vec3(0.5, 0.3, 0));
}

void run(const Kind& kind, int count, double size, skelconv::MeshMethod method) {
  const skelconv::Skeleton skeleton = skelconv::parse_skeleton_json(walk_skeleton(kind, count));
  skelconv::MeshOptions options;
  options.iso = iso_for(kind);
  options.size = size;
  options.method = method;
  skelconv::MeshReport report;
  const std::clock_t cpu_start = std::clock();
  const skelconv::TriangleMesh mesh = skelconv::mesh_iso_surface(skelconv::skeleton_field(skeleton), options, &report);
  // CPU seconds of this process (one thread): robust to other load on the
  // machine. The field's share of them is its share of the wall time.
  const double cpu = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  const double field = cpu * report.field_seconds / report.total_seconds;
  const double triangles = double(mesh.triangles.size());
  std::printf("| %s | %d | %.0f | %.2f | %.2f | %.2f | %zu | %.2f | %.2f | %.0f | %.0f |\n", kind.name, count,
              triangles, report.total_seconds, cpu, field, report.field_evaluations,
              1e6 * field / double(report.field_evaluations), cpu - field, triangles / cpu, triangles / (cpu - field));
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  bool smoke = false;
  int max_primitives = 1000;
  double size = 0.12;
  int min_primitives = 10;
  std::string only_kind;  // empty: every kind
  skelconv::MeshMethod method = skelconv::MeshMethod::cgal;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--smoke") == 0) smoke = true;
    if (std::strcmp(argv[i], "--max-primitives") == 0 && i + 1 < argc) max_primitives = std::atoi(argv[++i]);
    if (std::strcmp(argv[i], "--size") == 0 && i + 1 < argc) size = std::atof(argv[++i]);
    if (std::strcmp(argv[i], "--min-primitives") == 0 && i + 1 < argc) min_primitives = std::atoi(argv[++i]);
    if (std::strcmp(argv[i], "--kind") == 0 && i + 1 < argc) only_kind = argv[++i];
    if (std::strcmp(argv[i], "--method") == 0 && i + 1 < argc) {
      method = std::strcmp(argv[++i], "grid") == 0 ? skelconv::MeshMethod::grid : skelconv::MeshMethod::cgal;
    }
  }
  std::printf("| primitives | count | triangles | wall s | CPU s | field CPU s | evaluations | µs/eval | "
              "mesher CPU s | triangles/s (CPU) | triangles/s without field |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Kind& kind : kinds) {
    for (const int count : {10, 100, 1000}) {
      if (count > max_primitives || count < min_primitives || (smoke && (count > 10 || &kind != &kinds[0]))) continue;
      if (std::string(kind.name).find(only_kind) == std::string::npos) continue;
      run(kind, count, size, method);
    }
  }
}
