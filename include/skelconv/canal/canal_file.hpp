// skelconv/canal/canal_file.hpp — the input and output of `skelconv canal`
// (docs/cli_commands.md "skelconv canal"; docs/canal.md).
//
// Input (JSON):
//   {"spheres": [{"center": [x, y, z], "radius": r}, ...],      at least 2, r ≠ 0
//    "interpolation": "lorentz" | "linear",
//    "pole": {"center": [x, y, z], "radius": r}                 lorentz only: a sphere
//         or {"normal": [nx, ny, nz], "offset": d},              or the plane n·x = d
//    "samples": N}                                               N ≥ 2
// Output (JSON), at t = j/(N − 1), numbers with 17 significant digits:
//   {"samples": [
//     {"t": t, "sphere": {"center": [...], "radius": r},
//      "circle": {"center": [...], "radius": ρ, "normal": [...]} or null}, ...]}
//
// The reader is as strict as the skeleton reader (skelconv/skeleton_file.hpp):
// unknown or duplicate fields, wrong types, numbers that overflow double are
// InputErrors located at their JSON path ("spheres[2].radius").
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "skelconv/canal/canal_family.hpp"

namespace skelconv::canal {

enum class Interpolation { lorentz, linear };

struct CanalInput {
  std::vector<Sphere<double>> spheres;
  Interpolation interpolation = Interpolation::lorentz;
  std::optional<Vector5<double>> pole;  ///< on Λ⁴ (sphere_vector or plane_vector); lorentz only
  int samples = 2;
};

/// Largest "samples" accepted: the output holds one line per sample and a
/// mesh 64 vertices per sample (6.4 million vertices, ~0.5 GB, at most).
inline constexpr int max_canal_samples = 100'000;

/// Parses the JSON text of a canal input. Throws InputError.
CanalInput parse_canal_json(std::string_view json_text);

/// Reads and parses a canal file; InputError messages start with the file name.
CanalInput load_canal_file(const std::filesystem::path& path);

/// Builds the family (InputError located at "spheres[k]" or "pole" for the
/// refusals of SphereInterpolation and LinearSphereFamily) and samples it at
/// t = j/(N − 1) (EvaluationError where a sample is a point or a plane).
std::vector<FamilySample<double>> sample_canal(const CanalInput& input);

/// The output document, one sample per line.
std::string canal_samples_json(const std::vector<FamilySample<double>>& samples);

}  // namespace skelconv::canal
