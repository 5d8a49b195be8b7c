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
// The reader is as strict as the skeleton reader (skelconv/skeleton/skeleton_file.hpp):
// unknown or duplicate fields, wrong types, numbers that overflow double are
// InputErrors located at their JSON path ("spheres[2].radius").
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "skelconv/canal/canal_family.hpp"

namespace skelconv::canal {

enum class Interpolation { lorentz, linear };

/// The pole of the Lorentz interpolation: a sphere or a plane.
using Pole = std::variant<Sphere<double>, Plane<double>>;

struct CanalInput {
  std::vector<Sphere<double>> spheres;
  Interpolation interpolation = Interpolation::lorentz;
  std::optional<Pole> pole;  ///< lorentz only, as written in the file
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
/// The family is computed in a frame centred on the spheres and scaled by a
/// power of two to unit size, so that the result does not depend on where
/// the spheres are or on their size but by rounding.
std::vector<FamilySample<double>> sample_canal(const CanalInput& input);

/// The output document, one sample per line.
std::string canal_samples_json(const std::vector<FamilySample<double>>& samples);

}  // namespace skelconv::canal
