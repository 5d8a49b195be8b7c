// Implementation of mesh_preview.hpp.
#include "mesh_preview.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "embedded_text.hpp"
#include "page_text.hpp"
#include "skelconv/errors.hpp"
#include "skelconv/mesh/bounding_region.hpp"
#include "skelconv/mesh/implicit_field.hpp"
#include "skelconv/mesh/mesh_iso_surface.hpp"

namespace skelconv::detail {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the page reads the arrays as little-endian (JavaScript typed arrays on every browser platform)");

/// RFC 4648 base64 of the bytes of `values`.
template <class T>
std::string base64(const std::vector<T>& values) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<unsigned char> bytes(values.size() * sizeof(T));
  if (!bytes.empty()) std::memcpy(bytes.data(), values.data(), bytes.size());
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t k = 0; k < bytes.size(); k += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - k);
    std::uint32_t chunk = std::uint32_t(bytes[k]) << 16;
    if (n > 1) chunk |= std::uint32_t(bytes[k + 1]) << 8;
    if (n > 2) chunk |= bytes[k + 2];
    for (std::size_t j = 0; j < 4; ++j) out += j <= n ? kAlphabet[(chunk >> (18 - 6 * j)) & 63] : '=';
  }
  return out;
}

/// Facet size: the surface's box diagonal over this. Twice as fine as
/// skelconv mesh's default (1/50), about four times its triangles: at the
/// first camera a facet then spans a few pixels of a 480-pixel-wide window,
/// and the silhouette's chords no longer show as corners.
constexpr double preview_facets_per_diagonal = 100.0;

Frame mesh_frame(const TriangleMesh& mesh) {
  Vec3 low = Vec3::Constant(HUGE_VAL), high = Vec3::Constant(-HUGE_VAL);
  for (const Vec3& v : mesh.vertices) low = low.cwiseMin(v), high = high.cwiseMax(v);
  Frame frame;
  frame.centre = 0.5 * (low + high);
  frame.scale = std::exp2(std::round(std::log2(std::max(0.5 * (high - low).norm(), 1e-300))));
  return frame;
}

}  // namespace

std::string mesh_preview_page(const Skeleton& skeleton, const ViewPageOptions& options, ViewPageReport& report) {
  const ImplicitField field = skeleton_field(skeleton);
  MeshOptions mesh_options;
  mesh_options.iso = skeleton.iso();
  TriangleMesh mesh;
  try {
    mesh_options.size = bounding_region(field, skeleton.iso()).diagonal() / preview_facets_per_diagonal;
    mesh = mesh_iso_surface(field, mesh_options);
  } catch (const InputError& error) {
    // The mesher's errors name its command-line option (--iso); here the
    // iso is the file's.
    throw InputError(fmt::format("{} (no mesh preview; the ray marcher: {})", error.problem(), report.reason), "iso");
  }
  if (mesh.triangles.empty()) {
    throw InputError(fmt::format("no surface f = {} to preview (the mesher found none; {})", skeleton.iso(),
                                 report.reason),
                     "iso");
  }
  report.triangles = mesh.triangles.size();
  const Frame frame = mesh_frame(mesh);
  std::vector<float> positions, normals;
  std::vector<std::uint32_t> indices;
  double radius = 0.0;
  for (std::size_t k = 0; k < mesh.vertices.size(); ++k) {
    const Vec3 p = frame.to_page(mesh.vertices[k]);
    radius = std::max(radius, p.norm());
    for (int j = 0; j < 3; ++j) positions.push_back(float(p[j]));
    const Vec3 n = k < mesh.normals.size() ? mesh.normals[k] : Vec3::Zero();
    for (int j = 0; j < 3; ++j) normals.push_back(float(n[j]));
  }
  for (const auto& t : mesh.triangles)
    for (int j = 0; j < 3; ++j) indices.push_back(std::uint32_t(t[j]));
  nlohmann::json primitives = nlohmann::json::array();
  for (std::size_t k = 0; k < skeleton.primitives().size(); ++k) {
    static constexpr const char* kNames[] = {"segment", "polygon", "scalis_segment", "scalis_triangle", "point"};
    primitives.push_back({{"location", fmt::format("primitive {}", k)},
                          {"kernel", kNames[skeleton.primitives()[k].index()]}});
  }
  const nlohmann::json data = {{"name", options.name},
                               {"mode", "mesh preview"},
                               {"reason", report.reason},
                               {"frame", {{"centre", vec_json(frame.centre)}, {"scale", frame.scale}}},
                               {"iso", skeleton.iso()},
                               {"centre", {0.0, 0.0, 0.0}},
                               {"radius", radius},
                               {"fov", field_of_view},
                               {"distance", 1.25 * radius / std::sin(0.5 * field_of_view)},
                               {"overlay", overlay_lines(skeleton, frame, 0.02 * radius)},
                               {"mesh",
                                {{"vertices", mesh.vertices.size()},
                                 {"triangles", mesh.triangles.size()},
                                 {"positions", base64(positions)},
                                 {"normals", base64(normals)},
                                 {"indices", base64(indices)}}},
                               {"primitives", primitives}};
  std::string page = detail::view_template_html;
  page = fill(page, "/*@@FRAGMENT_SHADER@@*/", "");
  return fill(page, "/*@@SKELETON_DATA@@*/", script_safe(data.dump(1)));
}

}  // namespace skelconv::detail
