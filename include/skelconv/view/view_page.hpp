// skelconv/view/view_page.hpp — the self-contained HTML page of `skelconv view`
// (docs/view.md): a WebGL2 ray marcher of the surface f = iso of a skeleton.
//
// The page holds everything it needs (no network when it is opened): the
// fragment shader (src/view/view_march.glsl with the kernels of
// generated/glsl/ the skeleton uses; beyond an end of a segment it
// integrates inverse and Cauchy terms, plain or SCALIS, itself) and the
// skeleton's data as JSON. The ray marcher shows a skeleton of
//   - segments of the inverse and Cauchy families (every degree and weight
//     the GLSL files hold) and of the compact family (the odd degrees: the
//     even ones call a Gauss rule, which has no GLSL version),
//   - points of every kernel family, with a weight > 0,
//   - SCALIS segments of the inverse and Cauchy families,
//   - under sum blend nodes with weights ≥ 0 (the step bound of the ray
//     marcher needs every term of the sum to be ≥ 0, docs/view.md), and
//   - with weight polynomials w(t) ≥ 0 on [0, 1] for inverse and Cauchy
//     segments (same reason),
// at most max_view_primitives of them. Anything else gets the mesh
// preview instead (unless ViewPageOptions::mesh_preview is off, when it is
// refused with an InputError located at its JSON path, e.g.
// `primitives[2]: ...`): the page then holds a triangle mesh of f = iso
// (skelconv mesh's mesher, facets of 1/100 of the box diagonal) drawn by
// WebGL rasterisation, with the reason shown. An invalid skeleton is
// refused either way, and so is one without a surface (InputError at "iso").
//
// The page's frame: the skeleton translated by −centre (its box centre) and
// divided by scale (a power of two near half the box diagonal), so that the
// shader's float coordinates are of order 1; each term's weight c absorbs
// the kernel's homogeneity (inverse segment f scales as length^(1−i),
// inverse point as length^(−i), Cauchy and compact segments as length, the
// other points and SCALIS segments not at all), so the field is the same
// number in both frames.
#pragma once

#include <cstddef>
#include <string>

#include "skelconv/skeleton/skeleton.hpp"

namespace skelconv {

/// The shader loops over every primitive per marching step, so a frame costs
/// in proportion to their number; beyond this many the page is the mesh
/// preview: a bound on the page's work, not a measured threshold of
/// interactivity (docs/view.md).
inline constexpr std::size_t max_view_primitives = 256;

struct ViewPageOptions {
  /// Shown in the page's title line (the skeleton file's name).
  std::string name = "skeleton";
  /// The iso slider spans [iso / iso_range, iso · iso_range] (logarithmic),
  /// and the bounding sphere holds the surface of every iso of that range.
  double iso_range = 4.0;
  /// Fall back to the mesh preview where the ray marcher cannot draw.
  bool mesh_preview = true;
  /// The mesh preview whatever the skeleton (a slow GPU, a large skeleton).
  bool force_mesh_preview = false;
};

/// What make_view_page made.
struct ViewPageReport {
  bool mesh_preview = false;  ///< the mesh preview rather than the ray marcher
  std::string reason;         ///< why not the ray marcher (its refusal, located)
  std::size_t triangles = 0;  ///< of the mesh preview
};

/// The whole page: the ray marcher, or the mesh preview when the shader
/// cannot evaluate the skeleton (file comment). Throws InputError for an
/// invalid skeleton, for a refusal when options.mesh_preview is off, and
/// when the preview's mesh is empty (no surface f = iso).
std::string make_view_page(const Skeleton& skeleton, const ViewPageOptions& options = {},
                           ViewPageReport* report = nullptr);

}  // namespace skelconv
