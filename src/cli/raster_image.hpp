// src/cli/raster_image.hpp — a small software rasterizer for the pictures
// the command writes (`skeletonize --report-image`): shaded triangles and
// lines through an orthographic camera with a depth buffer, block-letter
// text, and PNG output. No window, no GPU, no fonts: the same input gives
// the same bytes on every machine.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "skelconv/geometry.hpp"

namespace skelconv::cli {

/// A colour, each channel in [0, 1].
using Rgb = std::array<double, 3>;

/// An orthographic view: world point p lands on pixel
/// ((p − centre)·right, −(p − centre)·up) × pixels_per_unit + the image
/// centre, at depth (p − centre)·forward (smaller is nearer the viewer).
struct OrthographicCamera {
  Vec3 centre = Vec3::Zero();
  Vec3 right = Vec3::UnitX(), up = Vec3::UnitY(), forward = -Vec3::UnitZ();
  double pixels_per_unit = 1.0;
};

/// The camera that shows `points` whole in a `width` × `height` image with
/// `margin` pixels on each side: looking along the points' direction of
/// least spread (principal axes of their covariance), turned 30° about the
/// direction of largest spread, which points up. The axes' signs are fixed
/// (largest component positive), so the view does not depend on the order
/// of the points.
OrthographicCamera camera_for(const std::vector<Vec3>& points, int width, int height, int margin);
/// `camera` looking the same way, recentred and rescaled to show `points`
/// whole in a `width` × `height` image with `margin` pixels on each side.
OrthographicCamera fitted(OrthographicCamera camera, const std::vector<Vec3>& points, int width, int height,
                          int margin);
/// The box of `points` in the camera's frame (right, up, forward
/// coordinates): its first two extents are the picture's width and height.
std::pair<Vec3, Vec3> projected_box(const OrthographicCamera& camera, const std::vector<Vec3>& points);
/// `camera` turned a quarter round its viewing direction: what pointed up
/// points right (a long shape laid across a wide picture).
OrthographicCamera turned_quarter(OrthographicCamera camera);

class RasterImage {
 public:
  RasterImage(int width, int height, const Rgb& background);

  int width() const { return width_; }
  int height() const { return height_; }

  /// A triangle with a colour per vertex, lit by a light over the viewer's
  /// left shoulder (both sides lit alike: the meshes' orientation does not
  /// matter for a picture), hidden where something nearer was drawn.
  void triangle(const OrthographicCamera& camera, const std::array<Vec3, 3>& corners,
                const std::array<Rgb, 3>& colours);
  /// A flat triangle behind everything: neither lit nor depth-tested, it
  /// only colours the pixels nothing else has been drawn on yet (a
  /// silhouette for context).
  void backdrop_triangle(const OrthographicCamera& camera, const std::array<Vec3, 3>& corners, const Rgb& colour);
  /// A line `thickness` pixels wide, in front of the triangles it passes
  /// (drawn with a small depth bias) and hidden behind the others.
  void line(const OrthographicCamera& camera, const Vec3& a, const Vec3& b, const Rgb& colour, double thickness);
  /// A filled axis-aligned rectangle (no depth), pixels [x0, x1) × [y0, y1).
  void rectangle(int x0, int y0, int x1, int y1, const Rgb& colour);
  /// Text in 5 × 7 block letters scaled by `scale`, top-left corner at
  /// (x, y). Letters are shown in upper case; characters without a glyph
  /// are drawn as a blank.
  void text(int x, int y, std::string_view text, int scale, const Rgb& colour);
  /// The width in pixels text() takes for `text` at `scale`.
  static int text_width(std::string_view text, int scale);

  /// This image shrunk by an integer `factor` (each output pixel the mean of
  /// factor × factor input pixels): supersampling's smoothing of edges.
  RasterImage downsampled(int factor) const;
  /// Copies `image` into this one with its top-left corner at (x, y).
  void paste(const RasterImage& image, int x, int y);

  /// The image as PNG bytes (8-bit RGB, no time stamp or other metadata).
  std::string png() const;

 private:
  Rgb& at(int x, int y) { return pixels_[std::size_t(y) * std::size_t(width_) + std::size_t(x)]; }
  const Rgb& at(int x, int y) const { return pixels_[std::size_t(y) * std::size_t(width_) + std::size_t(x)]; }

  int width_, height_;
  std::vector<Rgb> pixels_;
  std::vector<double> depth_;
};

/// The colour of `t` ∈ [0, 1] (clamped) on a perceptually ordered map from
/// dark blue through green to yellow (five stops of matplotlib's viridis,
/// interpolated linearly).
Rgb sequential_colour(double t);

}  // namespace skelconv::cli
