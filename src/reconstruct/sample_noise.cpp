// Implementation of skelconv/reconstruct/sample_noise.hpp.
#include "skelconv/reconstruct/sample_noise.hpp"

#include <fmt/format.h>

#include "skelconv/errors.hpp"

namespace skelconv::reconstruct {
namespace {

/// SplitMix64 (Steele, Lea & Flood 2014): the state advances by the golden
/// ratio constant and is mixed by two multiply-xorshift rounds.
std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/// Uniform in [−1, 1): the top 53 bits as a double in [0, 1), doubled, −1.
double symmetric_unit(std::uint64_t& state) { return double(splitmix64(state) >> 11) * 0x1.0p-52 - 1.0; }

}  // namespace

TriangleMesh with_sample_noise(const TriangleMesh& mesh, double amplitude, std::uint64_t seed) {
  if (!(amplitude >= 0.0 && amplitude < 0.1))
    throw InputError(fmt::format("must be in [0, 0.1) (× the bounding-box diagonal), got {}", amplitude), "--noise");
  TriangleMesh noisy = mesh;
  if (mesh.vertices.empty() || amplitude == 0.0) return noisy;
  Vec3 lo = mesh.vertices.front(), hi = lo;
  for (const Vec3& v : mesh.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  const double a = amplitude * (hi - lo).norm();
  std::uint64_t state = seed;
  for (Vec3& v : noisy.vertices) {
    const double x = symmetric_unit(state), y = symmetric_unit(state), z = symmetric_unit(state);
    v += a * Vec3(x, y, z);
  }
  noisy.normals.clear();
  return noisy;
}

}  // namespace skelconv::reconstruct
