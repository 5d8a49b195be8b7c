// codegen/glsl_writer.hpp — the GLSL target: writes generated/glsl/, the
// segment and point kernels in single precision for shaders (WebGL2 / GLSL ES 3.00 and
// desktop GLSL 4.50), from the same straight-line programs as the C++ files.
#pragma once

#include <filesystem>

#include "kernel_writer.hpp"

namespace skelconv::codegen {

/// Writes generated/glsl/segment_<family>.glsl and
/// scalis_segment_<family>.glsl for every segment and SCALIS segment kernel
/// of `request`, each its definition integral by the rule of glsl_rule.cpp
/// (not the C++ closed forms, which cancel in float). Same request, same
/// bytes. Also writes point.glsl (write_glsl_points).
void write_glsl_folder(const GeneratorRequest& request, const std::filesystem::path& folder);

/// Writes generated/glsl/point.glsl: f = w K(r) and its gradient for every
/// radial kernel family a point takes (codegen/glsl_point_writer.cpp).
void write_glsl_points(const GeneratorRequest& request, const std::filesystem::path& folder);

}  // namespace skelconv::codegen
