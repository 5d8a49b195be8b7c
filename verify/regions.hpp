// verify/regions.hpp — the named regions of the accuracy sweep.
//
// Each region stresses one way a closed form can lose digits (docs/mathematics.md §2): the
// discriminant ac − b² → 0 near the segment's line, large cancellations in
// the far field, the end points, and for the compact family the places where
// the support sphere cuts the segment.
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "skelconv/kernels/kernel_list.hpp"

namespace skelconv::verify {

enum class Region {
  generic,           ///< P at distance 0.1–3 |AB| from the segment, anywhere
  near_line_beside,  ///< 1e-6–1e-2 |AB| from the line, projecting inside the segment
  near_line_beyond,  ///< same distances, projecting 0.05–2 |AB| beyond an end
  near_ends,         ///< 1e-4–0.05 |AB| from A or B
  far,               ///< 10–1e4 |AB| from the segment
  support_boundary,  ///< finite support only: the support sphere cuts the segment, or P is just outside the support
  support_grazing,   ///< finite support only: P just inside the support, the ball barely reaches the segment (f → 0)
};

inline constexpr std::array<Region, 7> all_regions{
    Region::generic, Region::near_line_beside, Region::near_line_beyond, Region::near_ends,
    Region::far,     Region::support_boundary, Region::support_grazing};

constexpr std::string_view region_name(Region region) {
  switch (region) {
    case Region::generic: return "generic";
    case Region::near_line_beside: return "near_line_beside";
    case Region::near_line_beyond: return "near_line_beyond";
    case Region::near_ends: return "near_ends";
    case Region::far: return "far";
    case Region::support_boundary: return "support_boundary";
    case Region::support_grazing: return "support_grazing";
  }
  return "?";
}

/// Short column titles for the report table.
constexpr std::string_view region_short_name(Region region) {
  switch (region) {
    case Region::generic: return "generic";
    case Region::near_line_beside: return "line-beside";
    case Region::near_line_beyond: return "line-beyond";
    case Region::near_ends: return "ends";
    case Region::far: return "far";
    case Region::support_boundary: return "support";
    case Region::support_grazing: return "grazing";
  }
  return "?";
}

inline std::optional<Region> region_from_name(std::string_view name) {
  for (Region region : all_regions)
    if (region_name(region) == name) return region;
  return std::nullopt;
}

/// The support regions apply to the families with a finite support
/// (compact, soft, wyvill: their traits' support radius).
inline bool region_applies(Region region, KernelFamily family) {
  const bool support_only = region == Region::support_boundary || region == Region::support_grazing;
  return !support_only || kernels::family_facts(family).finite_support;
}

/// Points per (family, degree, region); every weight degree reuses them.
struct PointCounts {
  int generic = 2000;
  int other = 200;
  int for_region(Region region) const { return region == Region::generic ? generic : other; }
};

inline constexpr PointCounts default_point_counts{2000, 200};
inline constexpr PointCounts full_point_counts{20000, 2000};

}  // namespace skelconv::verify
