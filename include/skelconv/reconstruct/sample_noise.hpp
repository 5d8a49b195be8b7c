// skelconv/reconstruct/sample_noise.hpp — noisy samples for testing the
// reconstruction (docs/reconstruction.md, "Noise"): every vertex of a mesh
// moved by an independent offset uniform in the cube [−a, a]³, a =
// `amplitude` × the mesh's bounding-box diagonal. The triangles are kept,
// so the noisy mesh still encloses a volume (for a small a: below half the
// sample spacing it does not fold). Deterministic and portable: SplitMix64
// from `seed`, not <random>'s distributions (their output differs between
// standard libraries).
#pragma once

#include <cstdint>

#include "skelconv/mesh/triangle_mesh.hpp"

namespace skelconv::reconstruct {

/// Throws InputError ("--noise") unless 0 ≤ amplitude < 0.1.
TriangleMesh with_sample_noise(const TriangleMesh& mesh, double amplitude, std::uint64_t seed = 0);

}  // namespace skelconv::reconstruct
