// Implementation of skelconv/primitives/polygon.hpp.
#include "skelconv/primitives/polygon.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <fmt/format.h>

#include "../detail/convergence_guard.hpp"
#include "../detail/input_checks.hpp"
#include "planar_polygon.hpp"
#include "skelconv/kernels/kernel_list.hpp"
#include "skelconv/primitives/polygon_field.hpp"
#include "skelconv/detail/scaled_frame.hpp"
#include "skelconv/primitives/segment.hpp"  // Segment::degenerate_length_ratio, shared by the edges
#include "../detail/infinity.hpp"

namespace skelconv {
namespace {

using detail::format_degree_ranges;
using detail::format_point;

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
    const double length = scale_safe_norm(b - a);
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

/// Largest distance between two vertices, without squaring (any scale).
/// O(n²), once per polygon.
double diameter_of(std::span<const Vec3> vertices) {
  double diameter = 0.0;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    for (std::size_t j = i + 1; j < vertices.size(); ++j) {
      diameter = std::max(diameter, scale_safe_norm(vertices[j] - vertices[i]));
    }
  }
  return diameter;
}

/// The vertices in `frame` (scaled_frame.hpp).
std::vector<Vec3> in_frame(std::span<const Vec3> vertices, const ScaledFrame& frame) {
  std::vector<Vec3> local;
  local.reserve(vertices.size());
  for (const Vec3& v : vertices) local.push_back(frame.point(v));
  return local;
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
  // A degree the trait says the closed forms leave out gets its reason.
  const kernels::FamilyFacts facts = kernels::family_facts(kernel.family);
  if (facts.polygon_excluded_degree != 0 && kernel.degree == facts.polygon_excluded_degree) {
    throw InputError(fmt::format("degree {} of the {} family is not available on a polygon: {}; supported: {}",
                                 kernel.degree, family, facts.polygon_excluded_reason,
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

  // The checks run in a frame scaled by a power of two to the diameter
  // (scaled_frame.hpp), so that they are the same at every scale; the
  // messages print the world's numbers.
  const double diameter = diameter_of(vertices);
  if (!std::isfinite(diameter)) {
    throw InputError("polygon too large: its diameter overflows double precision", "vertices");
  }
  const ScaledFrame check_frame(diameter);
  const int e = check_frame.exponent();
  const std::vector<Vec3> local = in_frame(vertices, check_frame);
  const double local_diameter = check_frame.length(diameter);
  const Vec3 centroid = centroid_of(local);
  Vec3 normal = newell_normal(local);
  const double area = normal.norm() / 2;  // in the frame: |N| is about 1 or 0
  if (!(area >= degenerate_area_ratio * local_diameter * local_diameter)) {
    throw InputError(fmt::format("zero area: area {} is below {} times the squared diameter {} (the vertices are "
                                 "collinear, or the boundary crosses itself so that its loops' areas cancel)",
                                 format_scaled(area, 2 * e), degenerate_area_ratio,
                                 format_scaled(local_diameter * local_diameter, 2 * e)),
                     "vertices");
  }
  normal /= 2 * area;

  // Newell's plane: through the centroid, normal `normal`.
  double farthest_distance = 0.0;
  std::size_t farthest = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double distance = std::abs(normal.dot(local[k] - centroid));
    if (distance > farthest_distance) {
      farthest_distance = distance;
      farthest = k;
    }
  }
  if (farthest_distance > coplanarity_tolerance * local_diameter) {
    throw InputError(fmt::format("vertices not coplanar: {} is {} away from the polygon's plane, more than {} "
                                 "times the diameter {}",
                                 vertex_name(farthest), format_scaled(farthest_distance, e), coplanarity_tolerance,
                                 diameter),
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
  // The frame the checks ran in is the evaluation frame too. The exact
  // predicates see the given doubles scaled by a power of two (exact), so
  // that their filters neither overflow nor underflow: a polygon scaled by
  // 2^±400 is still the same simple polygon.
  frame_ = check_frame;
  for (const Vec3& v : vertices_) {
    vertex_arrays_.push_back(to_array(frame_.point(v)));
    projected_vertices_.push_back(project_along_axis(frame_.point(v), axis));
  }
  // Recomputed on the stored order, so that both orientations of the input
  // store bit-identical normals.
  normal_ = newell_normal(in_frame(vertices_, frame_)).normalized();
  area_ = std::ldexp(area, 2 * e);
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
  const kernels::FamilyFacts facts = kernels::family_facts(kernel.family);
  value_power_ = 2 + kernels::scaling_power(kernel);  // f ~ area · K: λ^(2 + p) (radial_kernel.hpp)
  factors_ = frame_.factors(value_power_);
  support_radius_ = kernels::support_radius(kernels::make_radial_kernel(kernel));
  if (std::isfinite(support_radius_)) {
    detail::require_support_radius_in_frame(frame_.scaled(kernel.R, 1), "polygon's diameter");
    // What support_misses_polygon reads at every point, computed once.
    frame_support_radius_ = frame_.scaled(support_radius_, 1);
    for (std::size_t k = 0; k < n; ++k) {
      const Vec3 edge = to_vec3(vertex_arrays_[(k + 1) % n]) - to_vec3(vertex_arrays_[k]);
      frame_edges_.push_back(edge);
      frame_edge_length2_.push_back(edge.squaredNorm());
    }
  }
  singular_at_zero_ = facts.singular_at_zero;
  // Each level's s and R in the frame and its generated kernel, once, rather than at every point.
  const auto in_polygon_frame = [&](KernelSpec level) {
    level.s = frame_.scaled(level.s, -2);
    level.R = frame_.scaled(level.R, 1);
    return level;
  };
  const auto add_level = [&](double coefficient, const KernelSpec& level) {
    require_supported_degree(level);  // for a compact level: the generator's polygon degrees must include it
    levels_.push_back({coefficient, in_polygon_frame(level), &polygon_edge_kernel<double>(level.family, level.degree)});
  };
  if (facts.compact_levels.empty()) {
    add_level(1.0, kernel);
  } else {
    for (const kernels::CompactLevel& level : facts.compact_levels)
      add_level(double(level.numerator) / level.denominator, KernelSpec::compact(level.degree, kernel.R));
  }
}

std::vector<int> Polygon::supported_degrees(KernelFamily family) { return polygon_supported_degrees(family); }

PolygonInput<double> Polygon::closed_form_input(const Level& level) const {
  PolygonInput<double> input;
  input.vertices = vertex_arrays_;
  input.normal = to_array(normal_);
  input.family = level.kernel.family;
  input.degree = level.kernel.degree;
  input.s = level.kernel.s;  // in the frame already (levels_)
  input.R = level.kernel.R;
  input.edge_kernel = level.edge_kernel;
  return input;
}

Polygon::Case Polygon::prepare(const Vec3& p, Vec3& frame_p) const {
  detail::require_finite_query_point(p);
  // One product by 2^−e where that is a normal double: frame_.point's own fast path.
  frame_p = factors_.to_frame != 0.0 ? Vec3(p * factors_.to_frame) : frame_.point(p);
  if (!frame_p.allFinite()) {
    throw EvaluationError(fmt::format("P = {} is too far from the polygon (more than ~2^1000 times its diameter "
                                      "from the origin): the field is outside the range of double precision",
                                      format_point(p)));
  }
  if (singular_at_zero_ && in_closed_polygon(frame_p)) return Case::on_inverse_singularity;
  if (std::isfinite(support_radius_) && support_misses_polygon(frame_p)) return Case::outside_compact_support;
  return Case::call_closed_form;
}

double Polygon::sum_of_levels(const Vec3& frame_p, std::array<double, 3>* gradient) const {
  double f = 0.0;
  if (gradient != nullptr) *gradient = {};
  for (const Level& level : levels_) {
    const double coefficient = level.coefficient;
    const PolygonInput<double> input = closed_form_input(level);
    if (gradient == nullptr) {
      f += coefficient * polygon_f(input, to_array(frame_p));
      continue;
    }
    std::array<double, 3> g{};
    f += coefficient * polygon_f_and_grad(input, to_array(frame_p), g);
    for (int i = 0; i < 3; ++i) (*gradient)[i] += coefficient * g[i];
  }
  return f;
}

bool Polygon::in_closed_polygon(const Vec3& frame_p) const {
  // See the file comment of polygon.hpp: z == 0 on the doubles, then an
  // exact inside-or-on-the-boundary test in the projected plane.
  if (normal_.dot(frame_p - to_vec3(vertex_arrays_.front())) != 0.0) return false;
  return detail::locate_point(projected_vertices_, project_along_axis(frame_p, dropped_axis_)) !=
         detail::PointLocation::outside;
}

bool Polygon::support_misses_polygon(const Vec3& frame_p) const {
  // The ball of radius R around P reaches the closed polygon iff it reaches
  // an edge, or |z| < R and P's foot on the plane lies in the polygon (the
  // distance is then |z|). The answer is that "or", whatever the order of
  // its terms: the edges come first, a few flops each, and the foot's
  // location (exact predicates) only where every edge is out of reach.
  const double R = frame_support_radius_;
  const Vec3 first = to_vec3(vertex_arrays_.front());
  const double z = normal_.dot(frame_p - first);
  if (std::abs(z) >= R) return true;
  for (std::size_t k = 0; k < vertex_arrays_.size(); ++k) {
    const Vec3 a = to_vec3(vertex_arrays_[k]);
    const Vec3& edge = frame_edges_[k];
    const double t = std::clamp(edge.dot(frame_p - a) / frame_edge_length2_[k], 0.0, 1.0);
    if ((frame_p - (a + t * edge)).squaredNorm() < R * R) return false;
  }
  const Vec3 foot = frame_p - z * normal_;
  return detail::locate_point(projected_vertices_, project_along_axis(foot, dropped_axis_)) ==
         detail::PointLocation::outside;
}

double Polygon::restore_value(double f, const char* function, const Vec3& p) const {
  // Inverse and Cauchy fields are positive; only a finite-support one (compact,
  // soft, wyvill) can be 0
  // (grazing its support).
  double world;
  if (restore_value_common(f, factors_.value, world)) return world;  // frame_.restore_value's common case
  return frame_.restore_value(f, value_power_, std::isfinite(support_radius_), function, p);
}

Vec3 Polygon::restore_gradient(const std::array<double, 3>& g, const char* function, const Vec3& p) const {
  Vec3 world;
  if (restore_gradient_common(to_vec3(g), factors_.gradient, world)) return world;  // its common case
  return frame_.restore_gradient(to_vec3(g), value_power_ - 1, std::isfinite(support_radius_), function, p);
}

double Polygon::value(const Vec3& p) const {
  Vec3 q;
  switch (prepare(p, q)) {
    case Case::outside_compact_support: return 0.0;
    case Case::on_inverse_singularity: return infinity;
    case Case::call_closed_form: break;
  }
  const double f = detail::evaluate_converged("polygon_f", p, [&] { return sum_of_levels(q, nullptr); });
  return restore_value(f, "polygon_f", p);
}

Vec3 Polygon::gradient(const Vec3& p) const {
  Vec3 q;
  switch (prepare(p, q)) {
    case Case::outside_compact_support: return Vec3::Zero();
    case Case::on_inverse_singularity: return Vec3::Constant(infinity);
    case Case::call_closed_form: break;
  }
  const std::array<double, 3> g = detail::evaluate_converged("polygon_grad", p, [&] {
    if (levels_.size() == 1) return polygon_grad(closed_form_input(levels_.front()), to_array(q));
    std::array<double, 3> sum{};
    sum_of_levels(q, &sum);
    return sum;
  });
  return restore_gradient(g, "polygon_grad", p);
}

FieldSample Polygon::value_and_gradient(const Vec3& p) const {
  Vec3 q;
  switch (prepare(p, q)) {
    case Case::outside_compact_support: return {0.0, Vec3::Zero()};
    case Case::on_inverse_singularity: return {infinity, Vec3::Constant(infinity)};
    case Case::call_closed_form: break;
  }
  std::array<double, 3> g{};
  const double f = detail::evaluate_converged("polygon_f_and_grad", p, [&] { return sum_of_levels(q, &g); });
  return {restore_value(f, "polygon_f_and_grad", p), restore_gradient(g, "polygon_f_and_grad", p)};
}

}  // namespace skelconv
