// Implementation of report_image.hpp.
#include "report_image.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "raster_image.hpp"
#include "skelconv/mesh/mesh_topology.hpp"
#include "skelconv/reconstruct/surface_distance.hpp"
#include "skelconv/reconstruct/surface_query.hpp"

namespace skelconv::cli {
namespace {

/// Final size of each of the three panels, in pixels, and how much finer
/// they are drawn before being shrunk to it (smooth edges).
constexpr int panel_size = 420;
constexpr int supersampling = 3;
constexpr int gap = 12;             ///< between panels and around the picture
constexpr int title_height = 36;    ///< above the panels
constexpr int footer_height = 76;   ///< below: the numbers and the colour bar
constexpr int text_scale = 2;       ///< block letters 10 × 14 pixels

const Rgb background{1.0, 1.0, 1.0};
const Rgb ink{0.1, 0.1, 0.1};
const Rgb sheet_colour{0.95, 0.62, 0.25};
const Rgb tube_colour{0.70, 0.12, 0.10};
const Rgb silhouette_colour{0.93, 0.94, 0.96};

std::array<Vec3, 3> corners_of(const TriangleMesh& mesh, const std::array<std::int32_t, 3>& t) {
  return {mesh.vertices[std::size_t(t[0])], mesh.vertices[std::size_t(t[1])], mesh.vertices[std::size_t(t[2])]};
}

/// The skeleton as its primitives lie: medial sheets as shaded triangles,
/// tubes and branches as lines, isolated spheres and balls as their
/// outlines (circles of their radius in the view plane); the input's
/// silhouette behind them, for where they lie.
RasterImage skeleton_panel(const reconstruct::Stage& stage, const TriangleMesh& input,
                           const OrthographicCamera& camera) {
  RasterImage panel(panel_size * supersampling, panel_size * supersampling, background);
  const double width = 2.0 * supersampling;
  const auto circle = [&](const Vec3& centre, double radius) {
    constexpr int pieces = 48;
    for (int k = 0; k < pieces; ++k) {
      const double a = 2 * M_PI * k / pieces, b = 2 * M_PI * (k + 1) / pieces;
      panel.line(camera, centre + radius * (std::cos(a) * camera.right + std::sin(a) * camera.up),
                 centre + radius * (std::cos(b) * camera.right + std::sin(b) * camera.up), tube_colour, width);
    }
  };
  const reconstruct::MedialMesh& m = stage.medial;
  const auto sphere = [&m](std::int32_t i) { return Vec3(m.spheres[std::size_t(i)].head<3>()); };
  for (const auto& t : m.triangles)
    panel.triangle(camera, {sphere(t[0]), sphere(t[1]), sphere(t[2])}, {sheet_colour, sheet_colour, sheet_colour});
  for (const auto& e : m.edges) panel.line(camera, sphere(e[0]), sphere(e[1]), tube_colour, width);
  for (const std::int32_t i : m.isolated) circle(sphere(i), m.spheres[std::size_t(i)].w());
  for (const reconstruct::Branch& b : stage.branches)
    for (std::size_t k = 0; k + 1 < b.points.size(); ++k)
      panel.line(camera, b.points[k].head<3>(), b.points[k + 1].head<3>(), tube_colour, width);
  for (const reconstruct::Facet& f : stage.facets)
    panel.triangle(camera, {f[0].head<3>(), f[1].head<3>(), f[2].head<3>()}, {sheet_colour, sheet_colour, sheet_colour});
  for (const reconstruct::Vec4& ball : stage.balls) circle(ball.head<3>(), ball.w());
  for (const auto& t : input.triangles) panel.backdrop_triangle(camera, corners_of(input, t), silhouette_colour);
  return panel.downsampled(supersampling);
}

/// Each vertex's distance to the nearest point of `other`.
std::vector<double> distances_to(const TriangleMesh& mesh, const TriangleMesh& other) {
  const reconstruct::SurfaceQuery query(other);
  std::vector<double> distance(mesh.vertices.size());
  for (std::size_t v = 0; v < distance.size(); ++v) distance[v] = query.distance(mesh.vertices[v]);
  return distance;
}

/// `surface` shaded, each vertex coloured by distance[v] / largest.
RasterImage distance_panel(const TriangleMesh& surface, const std::vector<double>& distance, double largest,
                           const OrthographicCamera& camera) {
  RasterImage panel(panel_size * supersampling, panel_size * supersampling, background);
  const auto colour = [&](std::int32_t v) { return sequential_colour(distance[std::size_t(v)] / largest); };
  for (const auto& t : surface.triangles)
    panel.triangle(camera, corners_of(surface, t), {colour(t[0]), colour(t[1]), colour(t[2])});
  return panel.downsampled(supersampling);
}

/// Text centred in the band [x0, x0 + width).
void centred_text(RasterImage& image, int x0, int width, int y, const std::string& text) {
  image.text(x0 + (width - RasterImage::text_width(text, text_scale)) / 2, y, text, text_scale, ink);
}

}  // namespace

std::string report_image_png(const TriangleMesh& input, const reconstruct::Stage& stage,
                             const reconstruct::StageMeasure& measure, const reconstruct::ReconstructOptions& options) {
  // One camera for the three panels, fitted to the input and the result
  // together (a result that overshoots stays in the picture).
  std::vector<Vec3> shown = input.vertices;
  shown.insert(shown.end(), measure.surface.vertices.begin(), measure.surface.vertices.end());
  const OrthographicCamera camera =
      camera_for(shown, panel_size * supersampling, panel_size * supersampling, gap * supersampling);

  // Both ways: where the result misses a part of the input (a finger
  // lost) shows on the input, where it bulges out on the result; one colour
  // scale for both, up to the larger of the largest distances.
  const TriangleMesh& result = measure.surface;
  const double diagonal = measure.distance.diagonal;
  // The input drawn finer than the result is meshed (diagonal / 100).
  const TriangleMesh fine_input = reconstruct::split_to_edge_length(input, reconstruct::dense_sample_spacing * diagonal);
  const std::vector<double> input_distance = distances_to(fine_input, result);
  const std::vector<double> result_distance = distances_to(result, input);
  double largest = 0.0;
  for (const double d : input_distance) largest = std::max(largest, d);
  for (const double d : result_distance) largest = std::max(largest, d);
  // The scale ends at the reported Hausdorff distance, which measures
  // these same vertices (and random samples besides), so the picture and
  // the numbers under it agree. A surface that lies on the input (a
  // sphere's one ball) still gets a scale: 0.01% of the diagonal at least.
  largest = std::max({largest, measure.distance.hausdorff, 1e-4 * diagonal});

  // Two rows: the front, and the back (the camera turned half round its up
  // direction), so that no part of either surface is out of sight.
  OrthographicCamera back = camera;
  back.forward = -camera.forward;
  back.right = -camera.right;
  const int width = 3 * panel_size + 4 * gap;
  const int height = title_height + 2 * panel_size + footer_height;
  RasterImage image(width, height, background);
  const int x[3] = {gap, 2 * gap + panel_size, 3 * gap + 2 * panel_size};
  for (int row = 0; row < 2; ++row) {
    const OrthographicCamera& view = row == 0 ? camera : back;
    const int y = title_height + row * panel_size;
    image.paste(distance_panel(fine_input, input_distance, largest, view), x[0], y);
    image.paste(skeleton_panel(stage, input, view), x[1], y);
    image.paste(distance_panel(result, result_distance, largest, view), x[2], y);
    image.text(x[0], y + 4, row == 0 ? "front" : "back", text_scale, ink);
  }
  const int top = title_height + panel_size;  // the footer goes below the second row

  const MeshTopology in = mesh_topology(input);
  const reconstruct::PrimitiveCounts n = reconstruct::primitive_counts(stage, options);
  const int title_y = (title_height - 7 * text_scale) / 2;
  centred_text(image, x[0], panel_size, title_y, fmt::format("input: distance to the result"));
  centred_text(image, x[1], panel_size, title_y, fmt::format("skeleton ({}): {} primitives", stage.name, n.total()));
  centred_text(image, x[2], panel_size, title_y, "result: distance to the input");

  // Under the first two panels, the measured numbers; under the third, the
  // colour bar from 0 to the largest distance.
  const int line1 = top + panel_size + 10, line2 = line1 + 7 * text_scale + 10;
  const int left_width = 2 * panel_size + gap;
  centred_text(image, x[0], left_width, line1,
               fmt::format("hausdorff {:.2f}%  rms {:.3f}%  of the diagonal", 100 * measure.distance.hausdorff / diagonal,
                           100 * measure.distance.rms / diagonal));
  centred_text(image, x[0], left_width, line2,
               fmt::format("euler characteristic {}{} > {}, components {} > {}", in.euler_characteristic,
                           in.pinches > 0 ? fmt::format(" ({} {})", in.pinches, in.pinches == 1 ? "pinch" : "pinches") : std::string(),
                           measure.euler_characteristic, in.components, measure.components));
  const int bar_left = x[2] + 20, bar_right = x[2] + panel_size - 20;
  for (int px = bar_left; px < bar_right; ++px)
    image.rectangle(px, line1, px + 1, line1 + 14, sequential_colour(double(px - bar_left) / (bar_right - bar_left - 1)));
  image.text(bar_left, line2, "0", text_scale, ink);
  const std::string high = fmt::format("{:.2f}% of the diagonal", 100 * largest / diagonal);
  image.text(bar_right - RasterImage::text_width(high, text_scale), line2, high, text_scale, ink);
  return image.png();
}

}  // namespace skelconv::cli
