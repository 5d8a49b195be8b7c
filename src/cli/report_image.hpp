// src/cli/report_image.hpp — the picture `skelconv skeletonize
// --report-image` writes: the input mesh coloured by its distance to the
// result | the skeleton | the skeleton's surface coloured by its distance to
// the input, side by side under one camera, with the measured numbers
// underneath.
#pragma once

#include <string>

#include "skelconv/mesh/triangle_mesh.hpp"
#include "skelconv/reconstruct/reconstruct.hpp"

namespace skelconv::cli {

/// PNG bytes of the report picture of `stage` (the reconstruction's result)
/// against `input`, with `measure` the stage's measure (its meshed surface,
/// distances and topology). Each vertex of either surface is coloured by its
/// distance to the other (0 dark blue up to the largest of both ways,
/// yellow; the colour bar gives that largest distance in % of the input's
/// diagonal).
std::string report_image_png(const TriangleMesh& input, const reconstruct::Stage& stage,
                             const reconstruct::StageMeasure& measure, const reconstruct::ReconstructOptions& options);

}  // namespace skelconv::cli
