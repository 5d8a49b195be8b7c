// Implementation of raster_image.hpp.
#include "raster_image.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Eigenvalues>
#include <png.h>

namespace skelconv::cli {
namespace {

/// Direction towards the light, in camera coordinates (right, up, towards
/// the viewer): from above, left and in front.
const Vec3 light_in_camera = Vec3(-0.4, 0.6, 0.7).normalized();

/// Lit fraction of a surface colour: a floor of ambient light so that faces
/// turned away stay readable, the rest diffuse (Lambert).
constexpr double ambient = 0.3;

/// Depth bias of lines, in units of the camera's depth: enough for a line
/// lying on a triangle to win against it, far less than the skeleton's
/// features.
constexpr double line_depth_bias = 1e-6;

/// A glyph: 7 rows of 5 pixels, '#' set.
struct Glyph {
  char c;
  std::array<const char*, 7> rows;
};

// clang-format off
constexpr Glyph glyphs[] = {
    {'0', {".###.", "#...#", "#..##", "#.#.#", "##..#", "#...#", ".###."}},
    {'1', {"..#..", ".##..", "..#..", "..#..", "..#..", "..#..", ".###."}},
    {'2', {".###.", "#...#", "....#", "...#.", "..#..", ".#...", "#####"}},
    {'3', {"#####", "...#.", "..#..", "...#.", "....#", "#...#", ".###."}},
    {'4', {"...#.", "..##.", ".#.#.", "#..#.", "#####", "...#.", "...#."}},
    {'5', {"#####", "#....", "####.", "....#", "....#", "#...#", ".###."}},
    {'6', {"..##.", ".#...", "#....", "####.", "#...#", "#...#", ".###."}},
    {'7', {"#####", "....#", "...#.", "..#..", ".#...", ".#...", ".#..."}},
    {'8', {".###.", "#...#", "#...#", ".###.", "#...#", "#...#", ".###."}},
    {'9', {".###.", "#...#", "#...#", ".####", "....#", "...#.", ".##.."}},
    {'.', {".....", ".....", ".....", ".....", ".....", ".##..", ".##.."}},
    {',', {".....", ".....", ".....", ".....", ".##..", "..#..", ".#..."}},
    {':', {".....", ".##..", ".##..", ".....", ".##..", ".##..", "....."}},
    {'%', {"##...", "##..#", "...#.", "..#..", ".#...", "#..##", "...##"}},
    {'-', {".....", ".....", ".....", "#####", ".....", ".....", "....."}},
    {'+', {".....", "..#..", "..#..", "#####", "..#..", "..#..", "....."}},
    {'/', {".....", "....#", "...#.", "..#..", ".#...", "#....", "....."}},
    {'=', {".....", ".....", "#####", ".....", "#####", ".....", "....."}},
    {'>', {".#...", "..#..", "...#.", "....#", "...#.", "..#..", ".#..."}},
    {'(', {"...#.", "..#..", ".#...", ".#...", ".#...", "..#..", "...#."}},
    {')', {".#...", "..#..", "...#.", "...#.", "...#.", "..#..", ".#..."}},
    {'A', {".###.", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"}},
    {'B', {"####.", "#...#", "#...#", "####.", "#...#", "#...#", "####."}},
    {'C', {".###.", "#...#", "#....", "#....", "#....", "#...#", ".###."}},
    {'D', {"###..", "#..#.", "#...#", "#...#", "#...#", "#..#.", "###.."}},
    {'E', {"#####", "#....", "#....", "####.", "#....", "#....", "#####"}},
    {'F', {"#####", "#....", "#....", "####.", "#....", "#....", "#...."}},
    {'G', {".###.", "#...#", "#....", "#.###", "#...#", "#...#", ".####"}},
    {'H', {"#...#", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"}},
    {'I', {".###.", "..#..", "..#..", "..#..", "..#..", "..#..", ".###."}},
    {'J', {"..###", "...#.", "...#.", "...#.", "...#.", "#..#.", ".##.."}},
    {'K', {"#...#", "#..#.", "#.#..", "##...", "#.#..", "#..#.", "#...#"}},
    {'L', {"#....", "#....", "#....", "#....", "#....", "#....", "#####"}},
    {'M', {"#...#", "##.##", "#.#.#", "#.#.#", "#...#", "#...#", "#...#"}},
    {'N', {"#...#", "#...#", "##..#", "#.#.#", "#..##", "#...#", "#...#"}},
    {'O', {".###.", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."}},
    {'P', {"####.", "#...#", "#...#", "####.", "#....", "#....", "#...."}},
    {'Q', {".###.", "#...#", "#...#", "#...#", "#.#.#", "#..#.", ".##.#"}},
    {'R', {"####.", "#...#", "#...#", "####.", "#.#..", "#..#.", "#...#"}},
    {'S', {".####", "#....", "#....", ".###.", "....#", "....#", "####."}},
    {'T', {"#####", "..#..", "..#..", "..#..", "..#..", "..#..", "..#.."}},
    {'U', {"#...#", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."}},
    {'V', {"#...#", "#...#", "#...#", "#...#", "#...#", ".#.#.", "..#.."}},
    {'W', {"#...#", "#...#", "#...#", "#.#.#", "#.#.#", "#.#.#", ".#.#."}},
    {'X', {"#...#", "#...#", ".#.#.", "..#..", ".#.#.", "#...#", "#...#"}},
    {'Y', {"#...#", "#...#", ".#.#.", "..#..", "..#..", "..#..", "..#.."}},
    {'Z', {"#####", "....#", "...#.", "..#..", ".#...", "#....", "#####"}},
};
// clang-format on

const Glyph* glyph_of(char c) {
  if (c >= 'a' && c <= 'z') c = char(c - 'a' + 'A');
  for (const Glyph& g : glyphs)
    if (g.c == c) return &g;
  return nullptr;
}

/// Signs fixed so that the largest component is positive: principal axes
/// do not have a sign of their own.
Vec3 with_fixed_sign(const Vec3& v) {
  int largest = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(v[i]) > std::abs(v[largest])) largest = i;
  return v[largest] < 0 ? Vec3(-v) : v;
}

/// Pixel coordinates (x, y) and depth of a world point.
Vec3 project(const OrthographicCamera& camera, const Vec3& p, int width, int height) {
  const Vec3 d = p - camera.centre;
  return {0.5 * width + d.dot(camera.right) * camera.pixels_per_unit,
          0.5 * height - d.dot(camera.up) * camera.pixels_per_unit, d.dot(camera.forward)};
}

std::uint8_t to_byte(double channel) { return std::uint8_t(std::lround(255.0 * std::clamp(channel, 0.0, 1.0))); }

}  // namespace

OrthographicCamera camera_for(const std::vector<Vec3>& points, int width, int height, int margin) {
  if (points.empty()) throw std::invalid_argument("camera_for: no points to show");
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : points) mean += p;
  mean /= double(points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Vec3& p : points) covariance += (p - mean) * (p - mean).transpose();
  // Eigenvalues in increasing order: column 0 the least spread, 2 the most.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(covariance);
  const Vec3 least = with_fixed_sign(axes.eigenvectors().col(0));
  const Vec3 most = with_fixed_sign(axes.eigenvectors().col(2));
  const double turn = 30.0 * M_PI / 180.0;
  OrthographicCamera camera;
  camera.up = most;
  const Vec3 middle = most.cross(least);
  camera.forward = -(std::cos(turn) * least + std::sin(turn) * middle).normalized();
  camera.right = camera.forward.cross(camera.up).normalized();
  return fitted(camera, points, width, height, margin);
}

OrthographicCamera fitted(OrthographicCamera camera, const std::vector<Vec3>& points, int width, int height,
                          int margin) {
  if (points.empty()) throw std::invalid_argument("fitted: no points to show");
  // Centre on the middle of the projected extent, and scale it to fit.
  const auto [lo, hi] = projected_box(camera, points);
  const Vec3 mid = 0.5 * (lo + hi);
  camera.centre = mid.x() * camera.right + mid.y() * camera.up + mid.z() * camera.forward;
  const double extent_x = std::max(hi.x() - lo.x(), 1e-300), extent_y = std::max(hi.y() - lo.y(), 1e-300);
  camera.pixels_per_unit = std::min((width - 2.0 * margin) / extent_x, (height - 2.0 * margin) / extent_y);
  return camera;
}

std::pair<Vec3, Vec3> projected_box(const OrthographicCamera& camera, const std::vector<Vec3>& points) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Vec3& p : points) {
    const Vec3 q(p.dot(camera.right), p.dot(camera.up), p.dot(camera.forward));
    lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  }
  return {lo, hi};
}

OrthographicCamera turned_quarter(OrthographicCamera camera) {
  const Vec3 right = camera.right;
  camera.right = camera.up;
  camera.up = -right;
  return camera;
}

RasterImage::RasterImage(int width, int height, const Rgb& background)
    : width_(width), height_(height), pixels_(std::size_t(width) * std::size_t(height), background),
      depth_(pixels_.size(), std::numeric_limits<double>::infinity()) {
  if (width <= 0 || height <= 0) throw std::invalid_argument("RasterImage: empty image");
}

namespace {

/// Calls visit(x, y, w) for every pixel whose centre lies in the projected
/// triangle `s` (pixel coordinates and depth), w its barycentric
/// coordinates there.
template <class Visit>
void for_each_pixel(const std::array<Vec3, 3>& s, int width, int height, Visit&& visit) {
  const double area = (s[1].x() - s[0].x()) * (s[2].y() - s[0].y()) - (s[2].x() - s[0].x()) * (s[1].y() - s[0].y());
  if (area == 0.0) return;  // seen edge-on
  const int x0 = std::max(0, int(std::floor(std::min({s[0].x(), s[1].x(), s[2].x()}))));
  const int x1 = std::min(width - 1, int(std::ceil(std::max({s[0].x(), s[1].x(), s[2].x()}))));
  const int y0 = std::max(0, int(std::floor(std::min({s[0].y(), s[1].y(), s[2].y()}))));
  const int y1 = std::min(height - 1, int(std::ceil(std::max({s[0].y(), s[1].y(), s[2].y()}))));
  for (int y = y0; y <= y1; ++y) {
    // The row's pixels inside the triangle, with a pixel to spare each
    // side: each side's test is linear in x, zero at x = root; pixels more
    // than a pixel beyond it fail that test by far more than its rounding,
    // so skipping them changes no pixel (a long thin triangle's box is
    // mostly empty: the silhouette of a CAD part's slivers). A side nearly
    // along the row bounds nothing here.
    const double py = y + 0.5;
    int first = x0, last = x1;
    for (int k = 0; k < 3; ++k) {
      const Vec3& a = s[(k + 1) % 3];
      const Vec3& b = s[(k + 2) % 3];
      const double slope = b.y() - a.y();
      if (!(std::abs(slope) > 1e-6)) continue;
      const double root = a.x() + (b.x() - a.x()) * (py - a.y()) / slope;  // where the side crosses the row
      if (!std::isfinite(root)) continue;
      // w ≥ 0 on the side of the root where −slope / area ≥ 0.
      if ((slope > 0) == (area > 0)) {
        if (root + 1.5 < double(last)) last = std::max(first - 1, int(std::floor(root + 1.5)));
      } else if (root - 1.5 > double(first)) {
        first = std::min(last + 1, int(std::ceil(root - 1.5)));
      }
    }
    for (int x = first; x <= last; ++x) {
      const double px = x + 0.5;
      std::array<double, 3> w;
      for (int k = 0; k < 3; ++k) {
        const Vec3& a = s[(k + 1) % 3];
        const Vec3& b = s[(k + 2) % 3];
        w[k] = ((b.x() - a.x()) * (py - a.y()) - (px - a.x()) * (b.y() - a.y())) / area;
      }
      if (w[0] >= 0.0 && w[1] >= 0.0 && w[2] >= 0.0) visit(x, y, w);
    }
  }
}

}  // namespace

void RasterImage::triangle(const OrthographicCamera& camera, const std::array<Vec3, 3>& corners,
                           const std::array<Rgb, 3>& colours) {
  const Vec3 normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
  const double length = normal.norm();
  if (!(length > 0.0)) return;  // a degenerate triangle covers no pixel
  const Vec3 n(normal.dot(camera.right), normal.dot(camera.up), -normal.dot(camera.forward));
  const double light = ambient + (1.0 - ambient) * std::abs(n.dot(light_in_camera)) / length;
  std::array<Vec3, 3> s;
  for (int k = 0; k < 3; ++k) s[k] = project(camera, corners[k], width_, height_);
  for_each_pixel(s, width_, height_, [&](int x, int y, const std::array<double, 3>& w) {
    const double depth = w[0] * s[0].z() + w[1] * s[1].z() + w[2] * s[2].z();
    double& nearest = depth_[std::size_t(y) * std::size_t(width_) + std::size_t(x)];
    if (depth >= nearest) return;
    nearest = depth;
    Rgb& pixel = at(x, y);
    for (int c = 0; c < 3; ++c)
      pixel[c] = light * (w[0] * colours[0][c] + w[1] * colours[1][c] + w[2] * colours[2][c]);
  });
}

void RasterImage::backdrop_triangle(const OrthographicCamera& camera, const std::array<Vec3, 3>& corners,
                                    const Rgb& colour) {
  std::array<Vec3, 3> s;
  for (int k = 0; k < 3; ++k) s[k] = project(camera, corners[k], width_, height_);
  for_each_pixel(s, width_, height_, [&](int x, int y, const std::array<double, 3>&) {
    if (depth_[std::size_t(y) * std::size_t(width_) + std::size_t(x)] == std::numeric_limits<double>::infinity())
      at(x, y) = colour;
  });
}

void RasterImage::line(const OrthographicCamera& camera, const Vec3& a, const Vec3& b, const Rgb& colour,
                       double thickness) {
  const Vec3 sa = project(camera, a, width_, height_), sb = project(camera, b, width_, height_);
  const double length = std::hypot(sb.x() - sa.x(), sb.y() - sa.y());
  const int steps = std::max(1, int(std::ceil(2.0 * length)));
  const double radius = 0.5 * thickness;
  const double bias = line_depth_bias * std::max(1.0, std::abs(sa.z()) + std::abs(sb.z()));
  for (int k = 0; k <= steps; ++k) {
    const double t = double(k) / steps;
    const Vec3 p = (1.0 - t) * sa + t * sb;
    for (int y = int(std::floor(p.y() - radius)); y <= int(std::ceil(p.y() + radius)); ++y) {
      for (int x = int(std::floor(p.x() - radius)); x <= int(std::ceil(p.x() + radius)); ++x) {
        if (x < 0 || y < 0 || x >= width_ || y >= height_) continue;
        if (std::hypot(x + 0.5 - p.x(), y + 0.5 - p.y()) > radius) continue;
        double& nearest = depth_[std::size_t(y) * std::size_t(width_) + std::size_t(x)];
        if (p.z() - bias >= nearest) continue;
        nearest = p.z() - bias;
        at(x, y) = colour;
      }
    }
  }
}

void RasterImage::rectangle(int x0, int y0, int x1, int y1, const Rgb& colour) {
  for (int y = std::max(0, y0); y < std::min(height_, y1); ++y)
    for (int x = std::max(0, x0); x < std::min(width_, x1); ++x) at(x, y) = colour;
}

void RasterImage::text(int x, int y, std::string_view text, int scale, const Rgb& colour) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const Glyph* g = glyph_of(text[i]);
    if (g == nullptr) continue;
    const int left = x + int(i) * 6 * scale;  // 5 pixels and a space
    for (int row = 0; row < 7; ++row)
      for (int column = 0; column < 5; ++column)
        if (g->rows[row][column] == '#')
          rectangle(left + column * scale, y + row * scale, left + (column + 1) * scale, y + (row + 1) * scale,
                    colour);
  }
}

int RasterImage::text_width(std::string_view text, int scale) {
  return text.empty() ? 0 : (int(text.size()) * 6 - 1) * scale;
}

RasterImage RasterImage::downsampled(int factor) const {
  RasterImage out(width_ / factor, height_ / factor, Rgb{0, 0, 0});
  for (int y = 0; y < out.height_; ++y) {
    for (int x = 0; x < out.width_; ++x) {
      Rgb sum{0, 0, 0};
      for (int dy = 0; dy < factor; ++dy)
        for (int dx = 0; dx < factor; ++dx)
          for (int c = 0; c < 3; ++c) sum[c] += at(x * factor + dx, y * factor + dy)[c];
      for (int c = 0; c < 3; ++c) out.at(x, y)[c] = sum[c] / (factor * factor);
    }
  }
  return out;
}

void RasterImage::paste(const RasterImage& image, int x, int y) {
  for (int j = 0; j < image.height_; ++j)
    for (int i = 0; i < image.width_; ++i)
      if (x + i >= 0 && y + j >= 0 && x + i < width_ && y + j < height_) at(x + i, y + j) = image.at(i, j);
}

std::string RasterImage::png() const {
  png_structp writer = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = writer != nullptr ? png_create_info_struct(writer) : nullptr;
  if (info == nullptr) {
    png_destroy_write_struct(&writer, nullptr);
    throw std::runtime_error("PNG: out of memory");
  }
  std::string bytes;
  std::vector<std::uint8_t> row(std::size_t(width_) * 3);
  // libpng reports errors by longjmp: nothing with a destructor may be
  // created between here and the end of the writing.
  if (setjmp(png_jmpbuf(writer))) {
    png_destroy_write_struct(&writer, &info);
    throw std::runtime_error("PNG: cannot encode the image");
  }
  png_set_write_fn(
      writer, &bytes,
      [](png_structp p, png_bytep data, png_size_t size) {
        static_cast<std::string*>(png_get_io_ptr(p))->append(reinterpret_cast<const char*>(data), size);
      },
      nullptr);
  png_set_IHDR(writer, info, png_uint_32(width_), png_uint_32(height_), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(writer, info);
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x)
      for (int c = 0; c < 3; ++c) row[std::size_t(x) * 3 + std::size_t(c)] = to_byte(at(x, y)[c]);
    png_write_row(writer, row.data());
  }
  png_write_end(writer, nullptr);
  png_destroy_write_struct(&writer, &info);
  return bytes;
}

Rgb sequential_colour(double t) {
  // Five samples of matplotlib's viridis at 0, ¼, ½, ¾, 1.
  static constexpr std::array<Rgb, 5> stops = {
      Rgb{0.267, 0.005, 0.329}, Rgb{0.229, 0.322, 0.545}, Rgb{0.128, 0.567, 0.551}, Rgb{0.369, 0.789, 0.383},
      Rgb{0.993, 0.906, 0.144}};
  const double u = 4.0 * std::clamp(std::isfinite(t) ? t : 1.0, 0.0, 1.0);
  const int k = std::min(3, int(u));
  const double f = u - k;
  Rgb out;
  for (int c = 0; c < 3; ++c) out[c] = (1.0 - f) * stops[std::size_t(k)][c] + f * stops[std::size_t(k) + 1][c];
  return out;
}

}  // namespace skelconv::cli
