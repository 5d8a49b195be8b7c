// skelconv/mesh/missed_parts.hpp — the parts of a surface a grid mesh lost
// (MeshReport::missed_parts), in words: `skelconv mesh --method grid` prints
// them as a warning, the Python module's Skeleton.mesh(method="grid") emits
// them as a Python warning. The mesh is still made: a blob thinner than the
// spacing must not vanish without a word.
#pragma once

#include <string>

#include "skelconv/mesh/mesh_iso_surface.hpp"
#include "skelconv/skeleton/skeleton.hpp"

namespace skelconv {

/// "N part(s) of the surface is/are missing from the mesh (no grid node lies
/// inside it/them); the thickest, about T thick near (x, y, z), from
/// primitives[k], needs --size h or less (or --method cgal, which seeds
/// every part)": the thickest missed part, the primitive whose own field is
/// largest in magnitude there, and a --size with a grid node inside it (a
/// grid of spacing h has a node inside every ball of diameter above √3 h;
/// half the thickness leaves a margin). `report.missed_parts` must not be
/// empty. Without the grid spacing, which the caller names its own way.
std::string missed_parts_problem(const Skeleton& skeleton, const MeshReport& report);

}  // namespace skelconv
