// The installed skelconv::canal and skelconv::reconstruct, used together as
// a program of the user's would: a canal surface (a cylinder swept between
// two spheres, capped) is meshed, then accepted as the closed input mesh of
// a reconstruction. Prints "canal mesh: T triangles, closed" when both
// libraries link and work; run_consumer.cmake checks the line.
#include <cstdio>
#include <exception>

#include "skelconv/canal/canal_file.hpp"
#include "skelconv/canal/canal_mesh.hpp"
#include "skelconv/reconstruct/mesh_check.hpp"

int main() {
  try {
    const skelconv::canal::CanalInput input = skelconv::canal::parse_canal_json(
        R"({"spheres": [{"center": [0, 0, 0], "radius": 1}, {"center": [2, 0, 0], "radius": 1}],
            "interpolation": "linear", "samples": 3})");
    const skelconv::TriangleMesh mesh = skelconv::canal::mesh_canal_surface(skelconv::canal::sample_canal(input));
    skelconv::reconstruct::check_closed_mesh(mesh);  // throws unless closed, oriented, not self-intersecting
    std::printf("canal mesh: %zu triangles, closed\n", mesh.triangles.size());
  } catch (const std::exception& error) {
    std::fprintf(stderr, "%s\n", error.what());
    return 1;
  }
}
