// src/view/mesh_preview.hpp — the mesh preview page of `skelconv view`
// (docs/view.md): what the page shows where the ray marcher cannot draw.
#pragma once

#include <string>

#include "skelconv/view/view_page.hpp"

namespace skelconv::detail {

/// A triangle mesh of f = iso (mesh_iso_surface, default size and distance)
/// embedded in the page (base64 float32 positions and normals, uint32
/// indices) and drawn by rasterisation with the ray marcher's shading and
/// camera. Fills report.triangles. Throws InputError when the mesh is empty.
std::string mesh_preview_page(const Skeleton& skeleton, const ViewPageOptions& options, ViewPageReport& report);

}  // namespace skelconv::detail
