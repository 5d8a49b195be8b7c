// uv_sphere: writes a UV sphere with exact per-vertex normals through
// skelconv::write_mesh, the one mesh writer of skelconv, so that the POV-Ray
// renderer (render_mesh.py) is tested on the files `skelconv mesh` will write.
//
//   skelconv_figures_uv_sphere OUT.ply|OUT.obj [--ascii] [--rings N]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>

#include "skelconv/errors.hpp"
#include "skelconv/mesh/triangle_mesh.hpp"

namespace {

// A sphere of radius 1 centred at (0, 0, 0.5): `rings` latitude bands, 2·rings
// longitudes, the poles shared; normals are the unit radial directions.
skelconv::TriangleMesh uv_sphere(int rings) {
  using std::numbers::pi;
  skelconv::TriangleMesh mesh;
  const int sectors = 2 * rings;
  const skelconv::Vec3 centre(0.0, 0.0, 0.5);
  auto add = [&](const skelconv::Vec3& n) {
    mesh.vertices.push_back(centre + n);
    mesh.normals.push_back(n);
  };
  add(skelconv::Vec3(0, 0, 1));  // north pole: index 0
  for (int i = 1; i < rings; ++i) {
    const double theta = pi * i / rings;
    for (int j = 0; j < sectors; ++j) {
      const double phi = 2 * pi * j / sectors;
      add(skelconv::Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)));
    }
  }
  add(skelconv::Vec3(0, 0, -1));  // south pole: the last index
  const int south = static_cast<int>(mesh.vertices.size()) - 1;
  auto ring = [&](int i, int j) { return 1 + (i - 1) * sectors + (j % sectors); };
  for (int j = 0; j < sectors; ++j) {
    mesh.triangles.push_back({0, ring(1, j), ring(1, j + 1)});
    mesh.triangles.push_back({south, ring(rings - 1, j + 1), ring(rings - 1, j)});
    for (int i = 1; i + 1 < rings; ++i) {
      mesh.triangles.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
      mesh.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
    }
  }
  return mesh;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s OUT.ply|OUT.obj [--ascii] [--rings N]\n", argv[0]);
    return 2;
  }
  auto encoding = skelconv::PlyEncoding::binary;
  int rings = 24;  // enough for a smooth silhouette at 640 px
  for (int k = 2; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "--ascii") {
      encoding = skelconv::PlyEncoding::ascii;
    } else if (arg == "--rings" && k + 1 < argc) {
      rings = std::atoi(argv[++k]);
    } else {
      std::fprintf(stderr, "uv_sphere: unknown argument %s\n", arg.c_str());
      return 2;
    }
  }
  if (rings < 2 || rings > 4096) {
    std::fprintf(stderr, "uv_sphere: --rings must be in [2, 4096]\n");
    return 2;
  }
  try {
    skelconv::write_mesh(uv_sphere(rings), argv[1], encoding);
  } catch (const skelconv::InputError& error) {
    std::fprintf(stderr, "uv_sphere: %s\n", error.what());
    return 2;
  }
  return 0;
}
