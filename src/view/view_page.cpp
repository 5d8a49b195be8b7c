// Implementation of skelconv/view/view_page.hpp.
#include "skelconv/view/view_page.hpp"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "embedded_text.hpp"
#include "skelconv/errors.hpp"

namespace skelconv {
namespace {

/// One term c · f_k of the field: a segment and its weight in the sum (the
/// product of the sum weights on its path from the root).
struct Term {
  const Segment* segment = nullptr;
  std::string location;
  double c = 1.0;
};

/// The terms of the tree under node `id` (located at `where`), weights
/// multiplied down. Refuses every node the shader cannot evaluate.
void collect_terms(const Skeleton& skeleton, Skeleton::NodeId id, const std::string& where, double c,
                   std::vector<Term>& terms) {
  const Blend& blend = skeleton.blend(id);
  if (blend.kind != BlendKind::sum) {
    throw InputError("blend \"" + std::string(blend_name(blend.kind)) +
                         "\": skelconv view evaluates sum nodes only (docs/view.md)",
                     where);
  }
  for (std::size_t k = 0; k < skeleton.child_count(id); ++k) {
    const std::string child = id == Skeleton::root ? fmt::format("primitives[{}]", k)
                                                   : fmt::format("{}.children[{}]", where, k);
    const double w = blend.weight_of(k);
    if (!(w >= 0.0)) {
      throw InputError(fmt::format("weight {} < 0: the viewer's step bound needs every term of a sum >= 0 "
                                   "(docs/view.md)", w),
                       fmt::format("{}.weights[{}]", where, k));
    }
    const auto [is_blend, index] = skeleton.child(id, k);
    if (is_blend) {
      collect_terms(skeleton, index, child, c * w, terms);
      continue;
    }
    const Primitive& primitive = skeleton.primitives()[index];
    const Segment* segment = std::get_if<Segment>(&primitive);
    if (segment == nullptr) {
      static constexpr const char* kNames[] = {"segment", "polygon", "scalis_segment", "scalis_triangle", "point"};
      throw InputError(fmt::format("type \"{}\": skelconv view shows segments only (the GLSL target, "
                                   "generated/glsl/, has segment kernels only; docs/view.md)",
                                   kNames[primitive.index()]),
                       child);
    }
    terms.push_back({segment, child, c * w});
  }
}

/// The least of w(t) = Σ w_j t^j over [0, 1] (degree ≤ 3): at the ends and
/// at the roots of w' in between.
double weight_minimum(std::span<const double> w) {
  const auto at = [&](double t) {
    double value = 0.0;
    for (std::size_t j = w.size(); j-- > 0;) value = value * t + w[j];
    return value;
  };
  double least = std::min(at(0.0), at(1.0));
  const double d1 = w.size() > 1 ? w[1] : 0.0, d2 = w.size() > 2 ? 2 * w[2] : 0.0, d3 = w.size() > 3 ? 3 * w[3] : 0.0;
  std::vector<double> roots;  // of d1 + d2 t + d3 t²
  if (d3 != 0.0) {
    const double disc = d2 * d2 - 4 * d3 * d1;
    if (disc >= 0) {
      roots = {(-d2 + std::sqrt(disc)) / (2 * d3), (-d2 - std::sqrt(disc)) / (2 * d3)};
    }
  } else if (d2 != 0.0) {
    roots = {-d1 / d2};
  }
  for (double t : roots)
    if (t > 0.0 && t < 1.0) least = std::min(least, at(t));
  return least;
}

/// The text of the generated GLSL file of `family` (embedded).
std::string_view glsl_file(KernelFamily family) {
  switch (family) {
    case KernelFamily::inverse: return embedded::segment_inverse_glsl;
    case KernelFamily::cauchy: return embedded::segment_cauchy_glsl;
    case KernelFamily::compact: return embedded::segment_compact_glsl;
    default: return {};
  }
}

/// The function `signature` of `file` with its comment block, or "" when the
/// file has none.
std::string glsl_function(std::string_view file, const std::string& signature) {
  const std::size_t at = file.find("\nfloat " + signature);
  if (at == std::string_view::npos) return {};
  std::size_t begin = at + 1;
  // Back over the comment lines just above it.
  while (begin > 0) {
    const std::size_t previous = file.rfind('\n', begin - 2);
    const std::size_t line = previous == std::string_view::npos ? 0 : previous + 1;
    if (file.substr(line, 2) != "//") break;
    begin = line;
  }
  const std::size_t end = file.find("\n}\n", at);
  return std::string(file.substr(begin, end + 3 - begin));
}

/// Checks that the GLSL files can evaluate `term`; returns the name of its
/// kernel functions (without _f / _f_and_grad).
std::string check_term(const Term& term) {
  const Segment& s = *term.segment;
  const KernelSpec& kernel = s.kernel();
  const std::string name = s.generated_name();
  if (glsl_file(kernel.family).empty() || glsl_function(glsl_file(kernel.family), name + "_f(").empty()) {
    throw InputError(fmt::format("kernel {} degree {} with a weight of degree {}: the GLSL target has no generic "
                                 "form of it (generated/glsl/: inverse and cauchy, compact of odd degree)",
                                 family_name(kernel.family), kernel.degree, s.weight_degree()),
                     term.location + ".kernel");
  }
  if (kernel.family != KernelFamily::compact && weight_minimum(s.weight()) < 0.0) {
    throw InputError("w(t) < 0 somewhere in [0, 1]: the viewer's step bound for inverse and Cauchy kernels needs "
                     "w >= 0 (docs/view.md)",
                     term.location + ".weight");
  }
  return name;
}

/// The camera's vertical field of view, radians (about 40 degrees: little
/// perspective distortion, the object large in the window).
constexpr double field_of_view = 0.7;

/// The page's frame (file comment of view_page.hpp).
struct Frame {
  Vec3 centre = Vec3::Zero();
  double scale = 1.0;
  Vec3 to_page(const Vec3& p) const { return (p - centre) / scale; }
};

Frame page_frame(const std::vector<Term>& terms) {
  Vec3 low = Vec3::Constant(HUGE_VAL), high = Vec3::Constant(-HUGE_VAL);
  for (const Term& t : terms) {
    low = low.cwiseMin(t.segment->a()).cwiseMin(t.segment->b());
    high = high.cwiseMax(t.segment->a()).cwiseMax(t.segment->b());
  }
  Frame frame;
  if (terms.empty()) return frame;
  frame.centre = 0.5 * (low + high);
  // A power of two: dividing by it is exact.
  frame.scale = std::exp2(std::round(std::log2(std::max(0.5 * (high - low).norm(), 1e-300))));
  return frame;
}

/// One term in the page's frame, with what the step bound needs.
struct PageTerm {
  Vec3 a, b;
  double c = 0, s = 1, R = 1;
  std::array<double, 4> w{};
  int degree = 1;
  KernelFamily family = KernelFamily::inverse;
  double weight_bound = 0;  ///< Σ |w_j| / (j + 1) ≥ ∫_0^1 |w(t)| dt
};

PageTerm page_term(const Term& term, const Frame& frame) {
  const Segment& s = *term.segment;
  PageTerm p;
  p.a = frame.to_page(s.a());
  p.b = frame.to_page(s.b());
  p.family = s.kernel().family;
  p.degree = s.kernel().degree;
  p.s = s.kernel().s * frame.scale * frame.scale;
  p.R = s.kernel().R / frame.scale;
  const auto w = s.weight();
  for (std::size_t j = 0; j < w.size(); ++j) {
    p.w[j] = w[j];
    p.weight_bound += std::abs(w[j]) / double(j + 1);
  }
  // f(P) = λ^power f'(P'), λ = scale: inverse 1 − i, Cauchy and compact 1.
  const int power = p.family == KernelFamily::inverse ? 1 - p.degree : 1;
  p.c = term.c * std::pow(frame.scale, power);
  if (term.c != 0.0 && !(p.c >= FLT_MIN && p.c <= FLT_MAX)) {
    throw InputError(fmt::format("the weight of this term in the page's frame ({:.3g}) is out of float's range: "
                                 "the skeleton is too large or too small for the viewer's float shader",
                                 p.c),
                     term.location);
  }
  return p;
}

/// K(r) of the term's kernel (decreasing in r).
double kernel_value(const PageTerm& t, double r) {
  switch (t.family) {
    case KernelFamily::inverse: return std::pow(r, -t.degree);
    case KernelFamily::cauchy: return std::pow(1.0 + t.s * r * r, -0.5 * t.degree);
    default: return r >= t.R ? 0.0 : std::pow(1.0 - r * r / (t.R * t.R), 0.5 * t.degree);
  }
}

/// max_r |K'(r)| of the compact kernel (1 − r²/R²)^(i/2): i u (1 − u²)^((i−2)/2) / R
/// with u = r/R, largest at u² = 1/(i − 1) for i ≥ 2 (at u = 1 for i = 2).
double compact_slope_bound(const PageTerm& t) {
  const double i = t.degree;
  const double u = i > 2 ? 1.0 / std::sqrt(i - 1) : 1.0;
  return i * u * std::pow(1.0 - u * u, 0.5 * (i - 2)) / t.R;
}

/// A radius r such that f < level at every point farther than r from every
/// segment: there each term is at most c |AB| ∫|w| K(r).
double support_margin(const std::vector<PageTerm>& terms, double level) {
  const auto bound = [&](double r) {
    double total = 0.0;
    for (const PageTerm& t : terms) total += t.c * (t.b - t.a).norm() * t.weight_bound * kernel_value(t, r);
    return total;
  };
  double high = 1.0;
  for (int k = 0; k < 200 && bound(high) >= level; ++k) high *= 2;
  double low = 0.0;
  for (int k = 0; k < 100; ++k) {
    const double mid = 0.5 * (low + high);
    (bound(mid) >= level ? low : high) = mid;
  }
  return high;
}

/// How far from the page's centre the surface f = iso reaches, roughly
/// (for the first camera only): from the ends and midpoint of every segment
/// outwards along the six axis directions until f < iso, by doubling then
/// bisection on the double-precision field.
double surface_extent(const Skeleton& skeleton, const std::vector<Term>& terms, const Frame& frame) {
  const auto inside = [&](const Vec3& p) {
    try {
      return skeleton.value(p) >= skeleton.iso();
    } catch (const EvaluationError&) {
      return false;
    }
  };
  double extent = 0.0;
  for (const Term& t : terms) {
    for (const Vec3& start : {t.segment->a(), t.segment->b(), Vec3(0.5 * (t.segment->a() + t.segment->b()))}) {
      for (int axis = 0; axis < 6; ++axis) {
        const Vec3 direction = (axis < 3 ? 1.0 : -1.0) * Vec3::Unit(axis % 3);
        double low = 0.0, high = 1e-3 * frame.scale;
        for (int k = 0; k < 60 && inside(start + high * direction); ++k) low = high, high *= 2;
        for (int k = 0; k < 30; ++k) {
          const double mid = 0.5 * (low + high);
          (inside(start + mid * direction) ? low : high) = mid;
        }
        extent = std::max(extent, frame.to_page(start + high * direction).norm());
      }
    }
  }
  return extent;
}

}  // namespace

namespace {

/// Replaces the one occurrence of `marker` in `text` (the templates hold
/// each marker once; a missing one is a build mistake, not user input).
std::string fill(std::string text, std::string_view marker, const std::string& value) {
  const std::size_t at = text.find(marker);
  if (at == std::string::npos) throw std::logic_error("view template without " + std::string(marker));
  return text.replace(at, marker.size(), value);
}

/// The shader's dispatch on the kernel index: kernel_f and kernel_f_and_grad.
std::string dispatch_text(const std::vector<std::string>& kernels) {
  std::string f = "float kernel_f(int kernel, SegmentInput si) {\n";
  std::string g = "float kernel_f_and_grad(int kernel, SegmentInput si, out vec3 grad) {\n";
  for (std::size_t k = 0; k < kernels.size(); ++k) {
    f += fmt::format("  if (kernel == {}) return {}_f(si);\n", k, kernels[k]);
    g += fmt::format("  if (kernel == {}) return {}_f_and_grad(si, grad);\n", k, kernels[k]);
  }
  return f + "  return 0.0;\n}\n\n" + g + "  grad = vec3(0.0);\n  return 0.0;\n}\n";
}

/// The functions of the kernels in use, once each, after the input block
/// they share (the same in every GLSL file).
std::string kernels_text(const std::vector<std::string>& kernels, const std::vector<KernelFamily>& families) {
  const std::string_view any = embedded::segment_inverse_glsl;
  const std::size_t begin = any.find("#ifndef SKELCONV_SEGMENT_INPUT");
  const std::size_t end = any.find("#endif", begin) + std::string_view("#endif").size();
  std::string text = std::string(any.substr(begin, end - begin)) + "\n\n";
  for (std::size_t k = 0; k < kernels.size(); ++k) {
    text += glsl_function(glsl_file(families[k]), kernels[k] + "_f(") + "\n";
    text += glsl_function(glsl_file(families[k]), kernels[k] + "_f_and_grad(") + "\n";
  }
  return text;
}

/// "</" would end the <script> element that holds the text.
std::string script_safe(std::string text) {
  for (std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at)) text.replace(at, 2, "<\\/");
  return text;
}

nlohmann::json vec_json(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

std::string make_view_page(const Skeleton& skeleton, const ViewPageOptions& options) {
  skeleton.validate();
  std::vector<Term> terms;
  collect_terms(skeleton, Skeleton::root, "primitives", 1.0, terms);
  if (terms.empty()) throw InputError("no primitive: there is no surface to show", "primitives");
  if (terms.size() > max_view_primitives) {
    throw InputError(fmt::format("{} primitives: the viewer's shader loops over every primitive per step and "
                                 "shows at most {} (docs/view.md); use skelconv mesh",
                                 terms.size(), max_view_primitives),
                     "primitives");
  }
  std::vector<std::string> kernels;
  std::vector<KernelFamily> families;
  const Frame frame = page_frame(terms);
  std::vector<PageTerm> page_terms;
  nlohmann::json primitives = nlohmann::json::array();
  double half_diagonal = 0.0;
  for (const Term& term : terms) {
    const std::string name = check_term(term);
    const auto found = std::find(kernels.begin(), kernels.end(), name);
    const std::size_t index = std::size_t(found - kernels.begin());
    if (found == kernels.end()) {
      kernels.push_back(name);
      families.push_back(term.segment->kernel().family);
    }
    const PageTerm t = page_term(term, frame);
    page_terms.push_back(t);
    half_diagonal = std::max({half_diagonal, t.a.norm(), t.b.norm()});
    const bool compact = t.family == KernelFamily::compact;
    // The step bound's number (view_march.glsl): the degree, or c L with
    // L = |AB| ∫|w| max|K'| bounding |grad f_k|.
    const double bound = compact ? t.c * (t.b - t.a).norm() * t.weight_bound * compact_slope_bound(t) : t.degree;
    primitives.push_back({{"location", term.location},
                          {"kernel", fmt::format("{} {}", family_name(t.family), t.degree)},
                          {"kernel_index", index},
                          // view_march.glsl's family code.
                          {"family", compact ? 1 : t.family == KernelFamily::inverse ? 0 : 2},
                          {"a", vec_json(t.a)},
                          {"b", vec_json(t.b)},
                          {"w", t.w},
                          {"s", t.s},
                          {"R", t.R},
                          {"c", t.c},
                          {"bound", bound}});
  }
  const double iso = skeleton.iso();
  const double iso_min = iso / options.iso_range;
  // Half the lowest iso: the float shader's field may differ a little from
  // the double bound.
  const double radius = half_diagonal + support_margin(page_terms, 0.5 * iso_min);
  // The first camera frames the surface of the file's iso (or the sphere
  // when no surface was found from the skeleton's points).
  const double extent = surface_extent(skeleton, terms, frame);
  const double view_radius = extent > 1e-2 ? std::min(radius, extent) : radius;
  const nlohmann::json data = {{"name", options.name},
                               {"frame", {{"centre", vec_json(frame.centre)}, {"scale", frame.scale}}},
                               {"iso", iso},
                               {"iso_min", iso_min},
                               {"iso_max", iso * options.iso_range},
                               {"centre", {0.0, 0.0, 0.0}},
                               {"radius", radius},
                               // The floor of a marching step: 1e-4 of the sphere, far below a pixel.
                               {"min_step", 1e-4 * radius},
                               {"fov", field_of_view},
                               {"distance", 1.25 * view_radius / std::sin(0.5 * field_of_view)},
                               {"primitives", primitives}};
  std::string shader = embedded::view_march_glsl;
  shader = fill(shader, "//@@KERNELS@@", kernels_text(kernels, families));
  shader = fill(shader, "//@@DISPATCH@@", dispatch_text(kernels));
  shader = fill(shader, "/*@@PRIMITIVE_COUNT@@*/1", std::to_string(terms.size()));
  shader = "#version 300 es\nprecision highp float;\nprecision highp int;\n" + shader;
  std::string page = embedded::view_template_html;
  page = fill(page, "/*@@FRAGMENT_SHADER@@*/", script_safe(shader));
  return fill(page, "/*@@SKELETON_DATA@@*/", script_safe(data.dump(1)));
}

}  // namespace skelconv
