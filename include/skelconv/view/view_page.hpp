// skelconv/view/view_page.hpp — the self-contained HTML page of `skelconv view`
// (docs/view.md): a WebGL2 ray marcher of the surface f = iso of a skeleton.
//
// The page holds everything it needs (no network when it is opened): the
// fragment shader (src/view/view_march.glsl with the kernels of
// generated/glsl/ the skeleton uses; beyond an end of a segment it
// integrates inverse and Cauchy terms itself) and the skeleton's data as
// JSON. The
// GLSL target has segment kernels only, so the page can show a skeleton of
//   - segments of the inverse and Cauchy families (every degree and weight
//     the GLSL files hold) and of the compact family (the odd degrees: the
//     even ones call a Gauss rule, which has no GLSL version),
//   - under sum blend nodes with weights ≥ 0 (the step bound of the ray
//     marcher needs every term of the sum to be ≥ 0, docs/view.md), and
//   - with weight polynomials w(t) ≥ 0 on [0, 1] for inverse and Cauchy
//     kernels (same reason),
// at most max_view_primitives of them. Anything else is refused with an
// InputError located at its JSON path, e.g. `primitives[2]: ...`.
//
// The page's frame: the skeleton translated by −centre (its box centre) and
// divided by scale (a power of two near half the box diagonal), so that the
// shader's float coordinates are of order 1; each term's weight c absorbs
// the kernel's homogeneity (inverse f scales as length^(1−i), Cauchy and
// compact as length), so the field is the same number in both frames.
#pragma once

#include <cstddef>
#include <string>

#include "skelconv/skeleton/skeleton.hpp"

namespace skelconv {

/// The shader loops over every primitive per marching step, so a frame costs
/// in proportion to their number; beyond this many the page is refused (use
/// skelconv mesh): a bound on the page's work, not a measured threshold of
/// interactivity (docs/view.md).
inline constexpr std::size_t max_view_primitives = 256;

struct ViewPageOptions {
  /// Shown in the page's title line (the skeleton file's name).
  std::string name = "skeleton";
  /// The iso slider spans [iso / iso_range, iso · iso_range] (logarithmic),
  /// and the bounding sphere holds the surface of every iso of that range.
  double iso_range = 4.0;
};

/// The whole page. Throws InputError (located at the JSON path of the
/// culprit) when the skeleton holds something the page cannot show.
std::string make_view_page(const Skeleton& skeleton, const ViewPageOptions& options = {});

}  // namespace skelconv
