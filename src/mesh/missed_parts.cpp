// Implementation of skelconv/mesh/missed_parts.hpp.
#include "skelconv/mesh/missed_parts.hpp"

#include <cmath>
#include <exception>
#include <limits>
#include <tuple>
#include <variant>

#include <fmt/format.h>

namespace skelconv {
namespace {

/// The primitive whose own field is largest in magnitude at `p` (a point
/// inside a part of the surface, or of a cavity a negative weight carves),
/// as its JSON path, or "" when none can be evaluated there.
std::string strongest_primitive(const Skeleton& skeleton, const Vec3& p) {
  std::string location;
  double largest = -std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < skeleton.size(); ++k) {
    try {
      const double f =
          std::abs(std::visit([&](const auto& primitive) { return primitive.value(p); }, skeleton.primitives()[k]));
      if (f > largest) std::tie(largest, location) = std::make_tuple(f, skeleton.location(k));
    } catch (const std::exception&) {
      // An inverse primitive's own skeleton, say: the others decide.
    }
  }
  return location;
}

}  // namespace

std::string missed_parts_problem(const Skeleton& skeleton, const MeshReport& report) {
  const MissedPart& part = report.missed_parts.front();
  const std::string primitive = strongest_primitive(skeleton, part.centre);
  const double suggested = part.thickness > 0.0 ? part.thickness / 2 : report.size / 4;
  // Two significant digits, rounded down: the printed size is at most the one computed.
  const double unit = std::pow(10.0, std::floor(std::log10(suggested)) - 1);
  const double size = std::floor(suggested / unit) * unit;
  const bool one = report.missed_parts.size() == 1;
  return fmt::format("{} part{} of the surface {} missing from the mesh (no grid node lies inside {}); the "
                     "thickest, {} near ({:.6g}, {:.6g}, {:.6g}){}, needs --size {:.2g} or less (or --method cgal, "
                     "which seeds every part)",
                     report.missed_parts.size(), one ? "" : "s", one ? "is" : "are", one ? "it" : "them",
                     part.thickness > 0.0 ? fmt::format("about {:.2g} thick", part.thickness)
                                          : fmt::format("thinner than {:g}", report.size),
                     part.centre.x(), part.centre.y(), part.centre.z(),
                     primitive.empty() ? "" : ", from " + primitive, size);
}

}  // namespace skelconv
