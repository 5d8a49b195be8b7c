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
constexpr int text_height = 7 * text_scale;
/// A shape whose picture would be this many times higher than wide (its
/// largest spread points up) is laid across the picture instead: in square
/// panels it would be a sliver (a femur, a rod, a snake).
constexpr double long_shape = 1.8;
/// Long shapes: panels as wide as one and a half squares, and no higher
/// than the shape needs (but not under `wide_panel_min_height`: room for
/// the colours of a thin rod's surface).
constexpr int wide_panel_width = 3 * panel_size / 2;
constexpr int wide_panel_min_height = 140;
constexpr int label_height = 24;    ///< long shapes: a panel's name above it

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
                           const OrthographicCamera& camera, int panel_width, int panel_height) {
  RasterImage panel(panel_width * supersampling, panel_height * supersampling, background);
  const double width = 2.0 * supersampling;  // of the lines
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
                           const OrthographicCamera& camera, int panel_width, int panel_height) {
  RasterImage panel(panel_width * supersampling, panel_height * supersampling, background);
  const auto colour = [&](std::int32_t v) { return sequential_colour(distance[std::size_t(v)] / largest); };
  for (const auto& t : surface.triangles)
    panel.triangle(camera, corners_of(surface, t), {colour(t[0]), colour(t[1]), colour(t[2])});
  return panel.downsampled(supersampling);
}

/// Text centred in the band [x0, x0 + width).
void centred_text(RasterImage& image, int x0, int width, int y, const std::string& text) {
  image.text(x0 + (width - RasterImage::text_width(text, text_scale)) / 2, y, text, text_scale, ink);
}

/// Where the six panels go: three kinds (0 the input, 1 the skeleton, 2
/// the result), each seen from the front and from the back.
///   * square: the kinds side by side (their names above them) and the
///     views one under the other, in square panels;
///   * wide, for a long shape turned to lie across: the views side by side
///     (their names above them) and the kinds one under the other, each
///     under its name, in panels as wide as 1.5 squares and as high as the
///     shape needs.
struct Layout {
  bool wide = false;
  int panel_width = panel_size, panel_height = panel_size;
  int width = 0, height = 0;
  int footer_top = 0;

  static Layout square() {
    Layout l;
    l.width = 3 * panel_size + 4 * gap;
    l.footer_top = title_height + 2 * panel_size;
    l.height = l.footer_top + footer_height;
    return l;
  }
  /// `aspect`: the shape's projected length over its width, turned across.
  static Layout across(double aspect) {
    Layout l;
    l.wide = true;
    l.panel_width = wide_panel_width;
    const double drawn = (wide_panel_width - 2.0 * gap) / aspect + 2.0 * gap;
    l.panel_height = std::clamp(int(std::ceil(drawn)), wide_panel_min_height, panel_size);
    l.width = 2 * wide_panel_width + 3 * gap;
    l.footer_top = title_height + 3 * (label_height + l.panel_height);
    l.height = l.footer_top + footer_height + text_height + 10;  // a third line: the bar under the numbers
    return l;
  }
  /// The top-left corner of the panel of `kind` seen from `view` (0 front, 1 back).
  std::pair<int, int> corner(int kind, int view) const {
    if (wide) return {gap + view * (panel_width + gap), title_height + kind * (label_height + panel_height) + label_height};
    return {gap + kind * (panel_width + gap), title_height + view * panel_height};
  }
};

}  // namespace

std::string report_image_png(const TriangleMesh& input, const reconstruct::Stage& stage,
                             const reconstruct::StageMeasure& measure, const reconstruct::ReconstructOptions& options) {
  // One camera for the three panels, fitted to the input and the result
  // together (a result that overshoots stays in the picture).
  std::vector<Vec3> shown = input.vertices;
  shown.insert(shown.end(), measure.surface.vertices.begin(), measure.surface.vertices.end());
  OrthographicCamera camera =
      camera_for(shown, panel_size * supersampling, panel_size * supersampling, gap * supersampling);
  const auto [lo, hi] = projected_box(camera, shown);
  const double across = hi.x() - lo.x(), along = hi.y() - lo.y();  // along the largest spread, which points up
  const Layout layout =
      along > long_shape * across ? Layout::across(along / std::max(across, 1e-3 * along)) : Layout::square();
  if (layout.wide)
    camera = fitted(turned_quarter(camera), shown, layout.panel_width * supersampling,
                    layout.panel_height * supersampling, gap * supersampling);

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

  // Two views: the front, and the back (the camera turned half round its up
  // direction), so that no part of either surface is out of sight.
  OrthographicCamera back = camera;
  back.forward = -camera.forward;
  back.right = -camera.right;
  RasterImage image(layout.width, layout.height, background);
  const int pw = layout.panel_width, ph = layout.panel_height;
  for (int view = 0; view < 2; ++view) {
    const OrthographicCamera& seen = view == 0 ? camera : back;
    const auto at = [&](int kind) { return layout.corner(kind, view); };
    image.paste(distance_panel(fine_input, input_distance, largest, seen, pw, ph), at(0).first, at(0).second);
    image.paste(skeleton_panel(stage, input, seen, pw, ph), at(1).first, at(1).second);
    image.paste(distance_panel(result, result_distance, largest, seen, pw, ph), at(2).first, at(2).second);
    if (!layout.wide) image.text(at(0).first, at(0).second + 4, view == 0 ? "front" : "back", text_scale, ink);
  }

  const MeshTopology in = mesh_topology(input);
  const reconstruct::PrimitiveCounts n = reconstruct::primitive_counts(stage, options);
  const int title_y = (title_height - text_height) / 2;
  const std::string kind_names[3] = {"input: distance to the result",
                                     fmt::format("skeleton ({}): {} primitives", stage.name, n.total()),
                                     "result: distance to the input"};
  if (layout.wide) {
    for (int view = 0; view < 2; ++view)
      centred_text(image, layout.corner(0, view).first, pw, title_y, view == 0 ? "front" : "back");
    for (int kind = 0; kind < 3; ++kind) {
      const auto [x, y] = layout.corner(kind, 0);
      centred_text(image, x, layout.width - 2 * gap, y - label_height + (label_height - text_height) / 2, kind_names[kind]);
    }
  } else {
    for (int kind = 0; kind < 3; ++kind) centred_text(image, layout.corner(kind, 0).first, pw, title_y, kind_names[kind]);
  }

  // The measured numbers; beside them (square) or under them (wide), the
  // colour bar from 0 to the largest distance.
  const int line1 = layout.footer_top + 10, line2 = line1 + text_height + 10;
  const int numbers_width = layout.wide ? layout.width - 2 * gap : 2 * pw + gap;
  centred_text(image, gap, numbers_width, line1,
               fmt::format("hausdorff {:.2f}%  rms {:.3f}%  of the diagonal", 100 * measure.distance.hausdorff / diagonal,
                           100 * measure.distance.rms / diagonal));
  centred_text(image, gap, numbers_width, line2,
               fmt::format("euler characteristic {}{} > {}, components {} > {}", in.euler_characteristic,
                           in.pinches > 0 ? fmt::format(" ({} {})", in.pinches, in.pinches == 1 ? "pinch" : "pinches") : std::string(),
                           measure.euler_characteristic, in.components, measure.components));
  const int bar_top = layout.wide ? line2 + text_height + 10 : line1;
  const int bar_x = layout.wide ? (layout.width - panel_size) / 2 : layout.corner(2, 0).first;
  const int bar_left = bar_x + 20, bar_right = bar_x + panel_size - 20;
  for (int px = bar_left; px < bar_right; ++px)
    image.rectangle(px, bar_top, px + 1, bar_top + 14, sequential_colour(double(px - bar_left) / (bar_right - bar_left - 1)));
  const int bar_labels = layout.wide ? bar_top + 2 : line2;
  const std::string high = fmt::format("{:.2f}% of the diagonal", 100 * largest / diagonal);
  if (layout.wide) {
    image.text(bar_left - 10 - RasterImage::text_width("0", text_scale), bar_labels, "0", text_scale, ink);
    image.text(bar_right + 10, bar_labels, high, text_scale, ink);
  } else {
    image.text(bar_left, bar_labels, "0", text_scale, ink);
    image.text(bar_right - RasterImage::text_width(high, text_scale), bar_labels, high, text_scale, ink);
  }
  return image.png();
}

}  // namespace skelconv::cli
