// Implementation of skelconv/polygon.hpp.
#include "skelconv/polygon.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <fmt/format.h>

#include "convergence_guard.hpp"
#include "input_checks.hpp"
#include "planar_polygon.hpp"
#include "skelconv/polygon_field.hpp"
#include "skelconv/segment.hpp"  // Segment::degenerate_length_ratio, shared by the edges

namespace skelconv {
namespace {

using detail::format_degree_ranges;
using detail::format_point;

constexpr double infinity = std::numeric_limits<double>::infinity();

std::string vertex_name(std::size_t k) { return fmt::format("vertices[{}]", k); }

/// Each vertex finite, no vertex equal to the next, and every edge long
/// enough to be represented at its position (Segment::degenerate_length_ratio).
void require_distinct_consecutive_vertices(std::span<const Vec3> vertices) {
  const std::size_t n = vertices.size();
  for (std::size_t k = 0; k < n; ++k) detail::require_finite_point(vertices[k], vertex_name(k));
  // The closing repeat first: it is the common case, and deserves its reason.
  if (vertices[n - 1] == vertices[0]) {
    throw InputError(fmt::format("the last vertex repeats the first one {}: the boundary closes by itself "
                                 "(from the last vertex back to the first), list each vertex once",
                                 format_point(vertices[0])),
                     vertex_name(n - 1));
  }
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t next = (k + 1) % n;
    const Vec3& a = vertices[k];
    const Vec3& b = vertices[next];
    if (a == b) {
      throw InputError(fmt::format("repeats the previous vertex {}: consecutive vertices must differ", format_point(a)),
                       vertex_name(next));
    }
    const double length = (b - a).norm();
    const double largest_coordinate = std::max(a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff());
    if (length < Segment::degenerate_length_ratio * largest_coordinate) {
      throw InputError(fmt::format("degenerate edge from vertices[{}] to vertices[{}]: length {} is below {} times "
                                   "the largest coordinate magnitude {}, too short to be represented accurately "
                                   "at that position",
                                   k, next, length, Segment::degenerate_length_ratio, largest_coordinate),
                       "vertices");
    }
  }
}

/// Largest distance between two vertices. O(n²), once per polygon.
double diameter_of(std::span<const Vec3> vertices) {
  double squared = 0.0;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    for (std::size_t j = i + 1; j < vertices.size(); ++j) {
      squared = std::max(squared, (vertices[j] - vertices[i]).squaredNorm());
    }
  }
  return std::sqrt(squared);
}

Vec3 centroid_of(std::span<const Vec3> vertices) {
  Vec3 sum = Vec3::Zero();
  for (const Vec3& v : vertices) sum += v;
  return sum / double(vertices.size());
}

/// Newell's normal N = Σ_k (Q_k − O) × (Q_{k+1} − O), twice the vector area,
/// pointing the way the boundary order turns (right-hand rule). Taken about
/// the first vertex O, not the origin, so that large coordinates do not
/// cancel; a vertex rather than the centroid, so that a polygon in an
/// axis-aligned plane gets an exactly axis-aligned N (its differences along
/// that axis are exactly 0), which the exact on-polygon test relies on.
Vec3 newell_normal(std::span<const Vec3> vertices) {
  Vec3 normal = Vec3::Zero();
  const std::size_t n = vertices.size();
  const Vec3& origin = vertices[0];
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3 a = vertices[k] - origin;
    const Vec3 b = vertices[(k + 1) % n] - origin;
    // Newell's form of a × b: each component from the difference and sum of
    // the other two coordinates.
    normal.x() += (a.y() - b.y()) * (a.z() + b.z());
    normal.y() += (a.z() - b.z()) * (a.x() + b.x());
    normal.z() += (a.x() - b.x()) * (a.y() + b.y());
  }
  return normal;
}

/// Index of the largest |coordinate| (the first on a tie).
int largest_axis(const Vec3& v) {
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(v[k]) > std::abs(v[axis])) axis = k;
  }
  return axis;
}

/// v without coordinate `dropped`, the other two in cyclic order (an
/// orientation-preserving view of the plane when v's normal has a positive
/// `dropped` coordinate).
detail::Point2 project_along_axis(const Vec3& v, int dropped) {
  return {v[(dropped + 1) % 3], v[(dropped + 2) % 3]};
}

void require_supported_degree(const KernelSpec& kernel) {
  const std::vector<int> supported = polygon_supported_degrees(kernel.family);
  if (std::find(supported.begin(), supported.end(), kernel.degree) != supported.end()) return;
  const std::string family = std::string(family_name(kernel.family));
  if (kernel.family == KernelFamily::inverse && kernel.degree == 2) {
    throw InputError(fmt::format("degree 2 of the inverse family is not available on a polygon: the contour "
                                 "formula of the polygon closed forms (SPEC §3, Hubert 2012 §6) excludes it; "
                                 "supported: {}",
                                 format_degree_ranges(supported)),
                     "kernel.degree");
  }
  throw InputError(fmt::format("unsupported degree {} for the {} family on a polygon; supported: {}", kernel.degree,
                               family, format_degree_ranges(supported)),
                   "kernel.degree");
}

}  // namespace

Polygon::Polygon(std::span<const Vec3> vertices, const KernelSpec& kernel) : kernel_(kernel) {
  const std::size_t n = vertices.size();
  if (n < 3) throw InputError(fmt::format("a polygon needs at least 3 vertices, got {}", n), "vertices");
  require_distinct_consecutive_vertices(vertices);

  const double diameter = diameter_of(vertices);
  const Vec3 centroid = centroid_of(vertices);
  Vec3 normal = newell_normal(vertices);
  if (!std::isfinite(diameter * diameter) || !normal.allFinite()) {
    throw InputError("polygon too large: its squared diameter overflows double precision", "vertices");
  }
  const double area = normal.norm() / 2;
  const double smallest_area = degenerate_area_ratio * diameter * diameter;
  if (!(area >= smallest_area) || area < std::numeric_limits<double>::min()) {
    throw InputError(fmt::format("zero area: area {} is below {} times the squared diameter {} (the vertices are "
                                 "collinear, or the boundary crosses itself so that its loops' areas cancel)",
                                 area, degenerate_area_ratio, diameter * diameter),
                     "vertices");
  }
  normal /= 2 * area;

  // Newell's plane: through the centroid, normal `normal`.
  double farthest_distance = 0.0;
  std::size_t farthest = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double distance = std::abs(normal.dot(vertices[k] - centroid));
    if (distance > farthest_distance) {
      farthest_distance = distance;
      farthest = k;
    }
  }
  if (farthest_distance > coplanarity_tolerance * diameter) {
    throw InputError(fmt::format("vertices not coplanar: {} is {} away from the polygon's plane, more than {} "
                                 "times the diameter {}",
                                 vertex_name(farthest), farthest_distance, coplanarity_tolerance, diameter),
                     "vertices");
  }

  // Canonical orientation (see the file comment): Newell's normal already
  // turns with the given order; flip both if its largest coordinate is
  // negative, then start at the smallest vertex.
  const int axis = largest_axis(normal);
  const bool reversed = normal[axis] < 0;
  std::vector<std::size_t> order(n);  // order[stored index] = given index
  for (std::size_t k = 0; k < n; ++k) order[k] = reversed ? n - 1 - k : k;
  const auto lexicographically_less = [&](std::size_t i, std::size_t j) {
    return std::lexicographical_compare(vertices[i].begin(), vertices[i].end(), vertices[j].begin(),
                                        vertices[j].end());
  };
  std::rotate(order.begin(), std::min_element(order.begin(), order.end(), lexicographically_less), order.end());

  for (std::size_t k : order) vertices_.push_back(vertices[k]);
  for (const Vec3& v : vertices_) {
    vertex_arrays_.push_back(to_array(v));
    projected_vertices_.push_back(project_along_axis(v, axis));
  }
  // Recomputed on the stored order, so that both orientations of the input
  // store bit-identical normals.
  normal_ = newell_normal(vertices_).normalized();
  area_ = area;
  dropped_axis_ = axis;

  if (const auto crossing = detail::find_crossing_edges(projected_vertices_)) {
    // Name the edges by the indices and the direction the user gave.
    const auto edge_name = [&](std::size_t stored_edge) {
      std::size_t from = order[stored_edge], to = order[(stored_edge + 1) % n];
      if (reversed) std::swap(from, to);
      return fmt::format("vertices[{}]-vertices[{}]", from, to);
    };
    std::string first = edge_name(crossing->first), second = edge_name(crossing->second);
    if (reversed) std::swap(first, second);  // the edge met first in the given order first
    throw InputError(fmt::format("self-intersecting boundary: edges {} and {} meet (a polygon must be simple: "
                                 "edges meet only at the vertex two consecutive edges share)",
                                 first, second),
                     "vertices");
  }

  detail::require_convolution_family(kernel.family, "polygon");
  detail::require_valid_kernel_parameter(kernel);
  require_supported_degree(kernel);
}

std::vector<int> Polygon::supported_degrees(KernelFamily family) { return polygon_supported_degrees(family); }

PolygonInput<double> Polygon::closed_form_input() const {
  PolygonInput<double> input;
  input.vertices = vertex_arrays_;
  input.normal = to_array(normal_);
  input.family = kernel_.family;
  input.degree = kernel_.degree;
  input.s = kernel_.s;
  input.R = kernel_.R;
  return input;
}

Polygon::Case Polygon::prepare(const Vec3& p) const {
  detail::require_finite_query_point(p);
  switch (kernel_.family) {
    case KernelFamily::inverse:
      return in_closed_polygon(p) ? Case::on_inverse_singularity : Case::call_closed_form;
    case KernelFamily::cauchy:
      return Case::call_closed_form;
    case KernelFamily::compact:
      return support_misses_polygon(p) ? Case::outside_compact_support : Case::call_closed_form;
  }
  return Case::call_closed_form;  // unreachable: every family is handled above
}

bool Polygon::in_closed_polygon(const Vec3& p) const {
  // See the file comment of polygon.hpp: z == 0 on the doubles, then an
  // exact inside-or-on-the-boundary test in the projected plane.
  if (normal_.dot(p - vertices_.front()) != 0.0) return false;
  return detail::locate_point(projected_vertices_, project_along_axis(p, dropped_axis_)) !=
         detail::PointLocation::outside;
}

bool Polygon::support_misses_polygon(const Vec3& p) const {
  const double R = kernel_.R;
  const double z = normal_.dot(p - vertices_.front());
  if (std::abs(z) >= R) return true;
  const Vec3 foot = p - z * normal_;
  if (detail::locate_point(projected_vertices_, project_along_axis(foot, dropped_axis_)) !=
      detail::PointLocation::outside) {
    return false;  // distance |z| < R
  }
  for (std::size_t k = 0; k < vertices_.size(); ++k) {
    const Vec3& a = vertices_[k];
    const Vec3 edge = vertices_[(k + 1) % vertices_.size()] - a;
    const double t = std::clamp(edge.dot(p - a) / edge.squaredNorm(), 0.0, 1.0);
    if ((p - (a + t * edge)).squaredNorm() < R * R) return false;
  }
  return true;
}

void Polygon::require_finite(std::initializer_list<double> results, const char* function, const Vec3& p) const {
  for (double x : results) {
    if (!std::isfinite(x)) {
      throw EvaluationError(fmt::format("{} ({} kernel of degree {}) returned {} at P = {}, where the field is "
                                        "finite: the closed form failed in double precision (the point may be too "
                                        "close to the polygon or its plane, or the coordinates too large)",
                                        function, family_name(kernel_.family), kernel_.degree, x, format_point(p)));
    }
  }
}

double Polygon::value(const Vec3& p) const {
  switch (prepare(p)) {
    case Case::outside_compact_support: return 0.0;
    case Case::on_inverse_singularity: return infinity;
    case Case::call_closed_form: break;
  }
  const double f = detail::evaluate_converged("polygon_f", p, [&] { return polygon_f(closed_form_input(), to_array(p)); });
  require_finite({f}, "polygon_f", p);
  return f;
}

Vec3 Polygon::gradient(const Vec3& p) const {
  switch (prepare(p)) {
    case Case::outside_compact_support: return Vec3::Zero();
    case Case::on_inverse_singularity: return Vec3::Constant(infinity);
    case Case::call_closed_form: break;
  }
  const std::array<double, 3> g =
      detail::evaluate_converged("polygon_grad", p, [&] { return polygon_grad(closed_form_input(), to_array(p)); });
  require_finite({g[0], g[1], g[2]}, "polygon_grad", p);
  return to_vec3(g);
}

FieldSample Polygon::value_and_gradient(const Vec3& p) const {
  switch (prepare(p)) {
    case Case::outside_compact_support: return {0.0, Vec3::Zero()};
    case Case::on_inverse_singularity: return {infinity, Vec3::Constant(infinity)};
    case Case::call_closed_form: break;
  }
  std::array<double, 3> g{};
  const double f = detail::evaluate_converged("polygon_f_and_grad", p,
                                             [&] { return polygon_f_and_grad(closed_form_input(), to_array(p), g); });
  require_finite({f, g[0], g[1], g[2]}, "polygon_f_and_grad", p);
  return {f, to_vec3(g)};
}

}  // namespace skelconv
