// Implementation of input_checks.hpp.
#include "input_checks.hpp"

#include "skelconv/kernels/kernel_list.hpp"
#include "skelconv/detail/scaled_frame.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace skelconv::detail {

void require_positive_parameter(double value, const char* where) {
  if (!std::isfinite(value)) throw InputError(fmt::format("must be finite, got {}", value), where);
  if (!(value > 0.0)) throw InputError(fmt::format("must be > 0, got {}", value), where);
}

void require_normal_in_frame(double value, const char* name, const char* where) {
  if (std::isnormal(value)) return;
  throw InputError(fmt::format("{} is {} in the primitive's own frame (lengths scaled by a power of two to about "
                               "1), outside the normal range of double precision: the kernel is too {} for the "
                               "primitive's size",
                               name, value, value == 0.0 || std::abs(value) < 1.0 ? "small" : "large"),
                   where);
}

void require_json_nesting(std::size_t depth, const std::string& where) {
  if (depth < max_json_nesting) return;
  throw InputError(fmt::format("objects and arrays nested more than {} deep: the file is refused before it is "
                               "read (a deeper document would exhaust the reader's stack)",
                               max_json_nesting),
                   where);
}

void require_no_nul_byte(std::string_view text) {
  const std::size_t nul = text.find('\0');
  if (nul == std::string_view::npos) return;
  const std::string_view before = text.substr(0, nul);
  const std::size_t line_start = before.rfind('\n');
  const std::size_t line = 1 + std::size_t(std::count(before.begin(), before.end(), '\n'));
  const std::size_t column = line_start == std::string_view::npos ? nul + 1 : nul - line_start;
  throw InputError(fmt::format("malformed JSON: a NUL byte at line {}, column {} (JSON text holds none: is this a "
                               "binary file?)",
                               line, column));
}

void require_support_radius_in_frame(double R_in_frame, const char* unit) {
  if (R_in_frame >= min_support_in_frame && R_in_frame <= max_support_in_frame) return;
  const bool small = R_in_frame < min_support_in_frame;
  throw InputError(fmt::format("R in units of the {} is {} in the primitive's own frame (lengths scaled by a power "
                               "of two to about 1), {} {}: the support is too {} for the primitive's size to be "
                               "evaluated in double precision",
                               unit, R_in_frame, small ? "below" : "above",
                               small ? "2^-48 (3.6e-15)" : "2^500 (3.3e150)", small ? "small" : "large"),
                   "kernel.R");
}

void require_scalis_radius(double tau, int k) {
  const std::string where = fmt::format("radius[{}]", k);
  if (!std::isfinite(tau)) throw InputError(fmt::format("must be finite, got {}", tau), where);
  if (tau < 0.0) throw InputError(fmt::format("must be >= 0, got {}", tau), where);
}

void require_scalis_sigma(KernelFamily family, double sigma) {
  if (!kernels::family_facts(family).scalis_sigma_above_one) return require_positive_parameter(sigma, "kernel.sigma");
  if (!std::isfinite(sigma)) throw InputError(fmt::format("must be finite, got {}", sigma), "kernel.sigma");
  if (!(sigma > 1.0)) {
    throw InputError(fmt::format("must be > 1 for the {} family, got {}: the kernel vanishes at distance "
                                 "sigma·tau, so with sigma <= 1 the thickness tau is unreachable",
                                 family_name(family), sigma),
                     "kernel.sigma");
  }
}

void require_non_degenerate(const Vec3& a, const Vec3& b, double degenerate_length_ratio) {
  if (a == b) throw InputError(fmt::format("degenerate segment: a and b are the same point {}", format_point(a)));
  // |b − a| by std::hypot: no square over- or underflows, so the check and
  // its message are the same at every scale.
  const double length = scale_safe_norm(b - a);
  if (!std::isfinite(length)) throw InputError("segment too long: |b - a| overflows double precision");
  const double largest_coordinate = std::max(a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff());
  if (length < degenerate_length_ratio * largest_coordinate) {
    throw InputError(fmt::format(
        "degenerate segment: length |b - a| = {} is below {} times the largest coordinate magnitude {}, "
        "too short to be represented accurately at that position",
        length, degenerate_length_ratio, largest_coordinate));
  }
  if (length < std::numeric_limits<double>::min()) {
    throw InputError(fmt::format("degenerate segment: length {} is below the normal range of double precision",
                                 length));
  }
}

std::string format_point(const Vec3& p) { return fmt::format("({}, {}, {})", p.x(), p.y(), p.z()); }

std::string format_degree_ranges(const std::vector<int>& degrees) {
  std::string text;
  for (std::size_t first = 0; first < degrees.size();) {
    std::size_t last = first;
    while (last + 1 < degrees.size() && degrees[last + 1] == degrees[last] + 1) ++last;
    if (!text.empty()) text += ", ";
    text += first == last ? fmt::format("{}", degrees[first])
                          : fmt::format("{}..{}", degrees[first], degrees[last]);
    first = last + 1;
  }
  return text.empty() ? "none" : text;
}

void require_finite_point(const Vec3& v, const std::string& where) {
  if (!v.allFinite()) throw InputError(fmt::format("must be finite, got {}", format_point(v)), where);
}

void throw_non_finite_query_point(const Vec3& p) {
  throw InputError(fmt::format("query point must be finite, got {}", format_point(p)));
}

namespace {
/// The trait bit of a primitive named by its JSON type.
kernels::PrimitiveKind primitive_kind(std::string_view what) {
  if (what == "segment") return kernels::on_segments;
  if (what == "polygon") return kernels::on_polygons;
  if (what == "point") return kernels::on_points;
  return kernels::on_scalis;  // "scalis_segment", "scalis_triangle"
}
}  // namespace

void require_convolution_family(KernelFamily family, std::string_view what) {
  const kernels::PrimitiveKind kind = primitive_kind(what);
  const kernels::FamilyFacts facts = kernels::family_facts(family);
  if (facts.on(kind)) return;
  std::string families;  // the families this primitive does take, from their traits
  for (KernelFamily other : all_kernel_families) {
    if (!kernels::family_facts(other).on(kind)) continue;
    families += fmt::format("{}\"{}\"", families.empty() ? "" : ", ", family_name(other));
  }
  std::string where = "points";
  if (facts.on(kernels::on_segments)) where += facts.on(kernels::on_polygons) ? ", segments and polygons" : " and segments";
  throw InputError(fmt::format("the {} family has no closed form on a {} (it is defined on {} only); a {} takes {}",
                               family_name(family), what, where, what, families),
                   "kernel.family");
}

void require_valid_kernel_parameter(const KernelSpec& kernel) {
  // The trait's constructor checks its own parameters (InputError at
  // "kernel.<key>"); the degree is checked by each primitive's own table.
  KernelSpec without_degree = kernel;
  const kernels::FamilyFacts facts = kernels::family_facts(kernel.family);
  without_degree.degree = facts.min_degree;
  (void)kernels::make_radial_kernel(without_degree);
}

}  // namespace skelconv::detail
