// src/view/page_text.hpp — what both pages of `skelconv view` (the ray
// marcher, view_page.cpp, and the mesh preview, mesh_preview.cpp) share:
// filling the template's markers, the camera's field of view, JSON helpers
// and the skeleton overlay's lines.
#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "skelconv/geometry.hpp"
#include "skelconv/skeleton/skeleton.hpp"

namespace skelconv::detail {

/// The camera's vertical field of view, radians (about 40 degrees: little
/// perspective distortion, the object large in the window).
inline constexpr double field_of_view = 0.7;

/// Replaces the one occurrence of `marker` in `text` (the templates hold
/// each marker once; a missing one is a build mistake, not user input).
std::string fill(std::string text, std::string_view marker, const std::string& value);

/// "</" would end the <script> element that holds the text.
std::string script_safe(std::string text);

inline nlohmann::json vec_json(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

/// The page's frame: the skeleton translated by −centre and divided by
/// scale (a power of two, so the division is exact; view_page.hpp).
struct Frame {
  Vec3 centre = Vec3::Zero();
  double scale = 1.0;
  Vec3 to_page(const Vec3& p) const { return (p - centre) / scale; }
};

/// The skeleton overlay in the page's frame, as a flat list of line ends
/// (x, y, z of A, then of B, per line): segments, polygon and triangle
/// edges, and for a point three short axis-parallel lines of half-length
/// `cross` through its centre.
nlohmann::json overlay_lines(const Skeleton& skeleton, const Frame& frame, double cross);

}  // namespace skelconv::detail
