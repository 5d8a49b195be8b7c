// Implementation of skelconv/view/view_page.hpp.
#include "skelconv/view/view_page.hpp"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "embedded_text.hpp"
#include "mesh_preview.hpp"
#include "page_text.hpp"
#include "skelconv/errors.hpp"
#include "skelconv/kernels/kernel_list.hpp"
#include "skelconv/kernels/read_trait.hpp"

namespace skelconv {

using detail::field_of_view;
using detail::fill;
using detail::Frame;
using detail::script_safe;
using detail::vec_json;

namespace {

/// One term c · f_k of the field: a segment, point or SCALIS segment and its
/// weight in the sum (the product of the sum weights on its path from the
/// root).
struct Term {
  const Primitive* primitive = nullptr;
  std::string location;
  double c = 1.0;
  /// The skeleton element in the world: a segment AB (A = B = the centre
  /// for a point).
  Vec3 a() const;
  Vec3 b() const;
};

Vec3 Term::a() const {
  if (const auto* s = std::get_if<Segment>(primitive)) return s->a();
  if (const auto* s = std::get_if<ScalisSegment>(primitive)) return s->a();
  return std::get<PointPrimitive>(*primitive).center();
}

Vec3 Term::b() const {
  if (const auto* s = std::get_if<Segment>(primitive)) return s->b();
  if (const auto* s = std::get_if<ScalisSegment>(primitive)) return s->b();
  return std::get<PointPrimitive>(*primitive).center();
}

/// The terms of the tree under node `id` (located at `where`), weights
/// multiplied down, in file order. Refuses the blend nodes and weights the
/// shader cannot evaluate; the primitives are checked by check_term.
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
    terms.push_back({&skeleton.primitives()[index], child, c * w});
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

/// The generated GLSL file (embedded) that holds the kernel `name`
/// ("segment_cauchy_i4_w1", "point_soft", "scalis_segment_inverse_i3").
std::string_view glsl_file(std::string_view name) {
  const std::pair<std::string_view, const char*> files[] = {
      {"segment_inverse_", detail::segment_inverse_glsl},
      {"segment_cauchy_", detail::segment_cauchy_glsl},
      {"segment_compact_", detail::segment_compact_glsl},
      {"scalis_segment_inverse_", detail::scalis_segment_inverse_glsl},
      {"scalis_segment_cauchy_", detail::scalis_segment_cauchy_glsl},
      {"point_", detail::point_glsl}};
  for (const auto& [prefix, text] : files)
    if (name.starts_with(prefix)) return text;
  return {};
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

/// Checks that the GLSL files can evaluate `term` and that the step bound
/// holds for it; returns the name of its kernel functions (without _f /
/// _f_and_grad).
std::string check_term(const Term& term) {
  const Primitive& primitive = *term.primitive;
  if (!std::holds_alternative<Segment>(primitive) && !std::holds_alternative<PointPrimitive>(primitive) &&
      !std::holds_alternative<ScalisSegment>(primitive)) {
    static constexpr const char* kNames[] = {"segment", "polygon", "scalis_segment", "scalis_triangle", "point"};
    throw InputError(fmt::format("type \"{}\": the viewer's shader evaluates segments, points and SCALIS "
                                 "segments (the kernels of generated/glsl/; docs/view.md)",
                                 kNames[primitive.index()]),
                     term.location);
  }
  std::string name;
  if (const auto* s = std::get_if<Segment>(term.primitive)) {
    const KernelSpec& kernel = s->kernel();
    name = s->generated_name();
    // A finite support takes the Lipschitz step, which bounds |w|; the
    // others take the ratio step, which needs every term >= 0.
    if (!kernels::family_facts(kernel.family).finite_support && weight_minimum(s->weight()) < 0.0) {
      throw InputError("w(t) < 0 somewhere in [0, 1]: the viewer's step bound for inverse and Cauchy kernels needs "
                       "w >= 0 (docs/view.md)",
                       term.location + ".weight");
    }
    if (glsl_function(glsl_file(name), name + "_f(").empty()) {
      throw InputError(fmt::format("kernel {} degree {} with a weight of degree {}: the GLSL target has no form "
                                   "of it (generated/glsl/: inverse, cauchy and compact)",
                                   family_name(kernel.family), kernel.degree, s->weight_degree()),
                       term.location + ".kernel");
    }
  } else if (const auto* s = std::get_if<ScalisSegment>(term.primitive)) {
    name = s->evaluator_name();
    if (glsl_function(glsl_file(name), name + "_f(").empty()) {
      throw InputError(fmt::format("SCALIS kernel {} degree {}: the GLSL target has no form of it "
                                   "(generated/glsl/: inverse and cauchy)",
                                   family_name(s->kernel().family), s->kernel().degree),
                       term.location + ".kernel");
    }
  } else {
    const auto& point = std::get<PointPrimitive>(*term.primitive);
    name = "point_" + std::string(family_name(point.kernel().family));
    // A family without a GLSL point form (generated/glsl/point.glsl) is
    // refused here, by what the generated file holds, not by name.
    if (glsl_function(glsl_file(name), name + "_f(").empty()) {
      throw InputError(fmt::format("point kernel {}: the GLSL target has no form of it (generated/glsl/point.glsl)",
                                   family_name(point.kernel().family)),
                       term.location + ".kernel");
    }
    if (!(point.weight() > 0.0)) {
      throw InputError("weight < 0: the viewer's step bound needs every term >= 0 (docs/view.md)",
                       term.location + ".weight");
    }
  }
  return name;
}

Frame page_frame(const std::vector<Term>& terms) {
  Vec3 low = Vec3::Constant(HUGE_VAL), high = Vec3::Constant(-HUGE_VAL);
  for (const Term& t : terms) {
    low = low.cwiseMin(t.a()).cwiseMin(t.b());
    high = high.cwiseMax(t.a()).cwiseMax(t.b());
  }
  Frame frame;
  if (terms.empty()) return frame;
  frame.centre = 0.5 * (low + high);
  // A power of two: dividing by it is exact. A single point: its kernel's
  // own length, or 1.
  double half_diagonal = 0.5 * (high - low).norm();
  if (half_diagonal == 0.0) {
    half_diagonal = kernels::length_scale(std::get<PointPrimitive>(*terms[0].primitive).kernel());
  }
  frame.scale = std::exp2(std::round(std::log2(std::max(half_diagonal, 1e-300))));
  return frame;
}

/// The shader's family code of a term (view_march.glsl): how it is
/// evaluated and which step bound it takes.
enum class Code {
  inverse_segment = 0,
  compact_segment = 1,
  cauchy_segment = 2,
  scalis_inverse = 4,
  scalis_cauchy = 5,
  inverse_point = 6,
  cauchy_point = 7,
  supported_point = 8,  ///< compact, soft, wyvill, ferley: K = 0 beyond R
  gaussian_point = 9,
};

/// One term in the page's frame, with what the step bound needs.
struct PageTerm {
  Vec3 a, b;
  Code code = Code::inverse_segment;
  double c = 0, s = 1, R = 1;
  /// The third texel: w0 .. w3 (segments), (tau0, tau1, sigma, 0) (SCALIS),
  /// (i, e, a, b) (points).
  std::array<double, 4> texel{};
  int degree = 1;
  KernelFamily family{};
  /// The term is at most c · magnitude · K(r) at distance r from its
  /// element (support_margin): |AB| Σ |w_j| / (j + 1) for a segment
  /// (≥ |AB| ∫_0^1 |w(t)| dt), 1 for a point, |AB| σ^i max τ^(i−1) for a
  /// SCALIS segment (its integrand is at most σ^i τ^(i−1) r^(−i)).
  double magnitude = 0;
  /// max_r |K'(r)| in the page's frame (the trait's max_slope); the
  /// Lipschitz codes' step bound is c |AB| ∫|w| of it.
  double slope = 0;
  /// The supported codes bound K by K(0) below R (kernel_value): K(0), the
  /// trait's max_value (1 but for Ferley's (R + e)/(R − e)).
  double peak = 1;
};

/// The shader's codes of a segment and a point (view_march.glsl takes its
/// step bound by code), read off the family's trait (radial_kernel.hpp): a
/// finite support takes the Lipschitz step inside the support and the gap
/// beyond it; an infinite support that still vanishes far (the Gaussian)
/// the Lipschitz step everywhere; a power of a quadratic (α r² + β)^(−i/2)
/// (the trait's quadratic_form) the ratio step of the inverse (β = 0) or
/// the Cauchy (β = 1) kernel. Families without a GLSL form never get here
/// (check_term refuses them first).
struct ShaderCodes {
  Code segment, point;
};
ShaderCodes shader_code(KernelFamily family) {
  const std::optional<ShaderCodes> codes = kernels::read_trait<std::optional<ShaderCodes>>(
      family,
      [](auto trait) -> std::optional<ShaderCodes> {
        using K = typename decltype(trait)::type;
        if constexpr (K::finite_support) {
          return ShaderCodes{Code::compact_segment, Code::supported_point};
        } else if constexpr (K::vanishes_far) {
          return ShaderCodes{Code::compact_segment, Code::gaussian_point};
        } else if constexpr (requires { K::quadratic_form(1.0); }) {
          if (K::quadratic_form(1.0)[1] == 0.0) return ShaderCodes{Code::inverse_segment, Code::inverse_point};
          return ShaderCodes{Code::cauchy_segment, Code::cauchy_point};
        } else {
          return std::nullopt;
        }
      },
      std::nullopt);
  // A GLSL form whose step bound the rules above do not give is a
  // programming error (check_term refuses the families without a GLSL form).
  if (!codes) throw std::logic_error("no shader code for " + std::string(family_name(family)));
  return *codes;
}

bool is_supported(Code code) { return code == Code::compact_segment || code == Code::supported_point; }

/// The term's weight in the page's frame, refused beyond float's range.
double page_weight(const Term& term, double c) {
  if (term.c != 0.0 && !(c >= FLT_MIN && c <= FLT_MAX)) {
    throw InputError(fmt::format("the weight of this term in the page's frame ({:.3g}) is out of float's range: "
                                 "the skeleton is too large or too small for the viewer's float shader",
                                 c),
                     term.location);
  }
  return c;
}

PageTerm page_segment(const Term& term, const Segment& s, const Frame& frame) {
  PageTerm p;
  p.family = s.kernel().family;
  p.code = shader_code(p.family).segment;
  p.degree = s.kernel().degree;
  p.s = s.kernel().s * frame.scale * frame.scale;
  p.R = s.kernel().R / frame.scale;
  const auto w = s.weight();
  double weight_bound = 0.0;
  for (std::size_t j = 0; j < w.size(); ++j) {
    p.texel[j] = w[j];
    weight_bound += std::abs(w[j]) / double(j + 1);
  }
  p.magnitude = (s.b() - s.a()).norm() / frame.scale * weight_bound;
  KernelSpec page_kernel = s.kernel();
  page_kernel.R = p.R;
  page_kernel.s = p.s;
  p.slope = kernels::max_slope(page_kernel);
  // f(P) = λ^power f'(P'), λ = scale: 1 + the trait's scaling_power
  // (radial_kernel.hpp): inverse 1 − i, Cauchy and compact 1.
  const int power = 1 + kernels::scaling_power(s.kernel());
  p.c = page_weight(term, term.c * std::pow(frame.scale, power));
  return p;
}

PageTerm page_point(const Term& term, const PointPrimitive& point, const Frame& frame) {
  const KernelSpec& k = point.kernel();
  PageTerm p;
  p.family = k.family;
  p.code = shader_code(k.family).point;
  p.degree = k.degree;
  // Lengths divide by λ, so s and a (per length²) multiply by λ².
  p.s = k.s * frame.scale * frame.scale;
  p.R = k.R / frame.scale;
  p.texel = {double(k.degree), k.e / frame.scale, k.a * frame.scale * frame.scale, k.b};
  p.magnitude = 1.0;
  KernelSpec page_kernel = k;
  page_kernel.R = p.R;
  page_kernel.e = p.texel[1];
  page_kernel.a = p.texel[2];
  page_kernel.s = p.s;
  p.slope = kernels::max_slope(page_kernel);
  if (is_supported(p.code)) p.peak = kernels::max_value(page_kernel);
  // w K(r) = w λ^p K(r'), p the trait's scaling_power (radial_kernel.hpp):
  // −i for the inverse kernel; the others are functions of r/R, r²s, r²a.
  const int power = kernels::scaling_power(k);
  p.c = page_weight(term, term.c * point.weight() * std::pow(frame.scale, power));
  return p;
}

PageTerm page_scalis(const Term& term, const ScalisSegment& s, const Frame& frame) {
  PageTerm p;
  p.family = s.kernel().family;
  const kernels::FamilyFacts facts = kernels::family_facts(p.family);
  // The GLSL SCALIS forms: inverse (singular on the segment) and Cauchy.
  p.code = facts.scalis_singularity == kernels::ScalisSingularity::on_segment ? Code::scalis_inverse
                                                                               : Code::scalis_cauchy;
  p.degree = s.kernel().degree;
  // F is scale invariant (radii scale with the frame); a kernel without a
  // length of its own (inverse) takes σ = 1 and h at σ = 1, as ScalisSegment
  // does (σ^i cancels).
  const double sigma = facts.scale_free ? 1.0 : s.kernel().sigma;
  p.texel = {s.tau0() / frame.scale, s.tau1() / frame.scale, sigma, 0.0};
  const double h = ScalisSegment::normalisation(p.family, p.degree, sigma);
  const double tau_max = std::max(p.texel[0], p.texel[1]);
  p.magnitude = (s.b() - s.a()).norm() / frame.scale * std::pow(sigma, p.degree) * std::pow(tau_max, p.degree - 1);
  p.c = page_weight(term, term.c * s.iso() / h);
  return p;
}

PageTerm page_term(const Term& term, const Frame& frame) {
  PageTerm p;
  if (const auto* s = std::get_if<Segment>(term.primitive)) p = page_segment(term, *s, frame);
  else if (const auto* s = std::get_if<ScalisSegment>(term.primitive)) p = page_scalis(term, *s, frame);
  else p = page_point(term, std::get<PointPrimitive>(*term.primitive), frame);
  p.a = frame.to_page(term.a());
  p.b = frame.to_page(term.b());
  return p;
}

/// K(r) of the term's kernel (decreasing in r) in the page's frame; for a
/// SCALIS segment the r^(−i) that bounds its integrand.
double kernel_value(const PageTerm& t, double r) {
  switch (t.code) {
    case Code::inverse_segment:
    case Code::inverse_point:
    case Code::scalis_inverse:
    case Code::scalis_cauchy: return std::pow(r, -t.degree);
    case Code::cauchy_segment:
    case Code::cauchy_point: return std::pow(1.0 + t.s * r * r, -0.5 * t.degree);
    case Code::gaussian_point: return t.texel[3] * std::exp(-t.texel[2] * r * r);
    default: return r >= t.R ? 0.0 : 1.0;  // every supported kernel is at most 1 (its K(0) = 1, or 1 + k e for Ferley)
  }
}

/// A radius r such that f < level at every point farther than r from every
/// skeleton element: there each term is at most c · magnitude · K(r).
double support_margin(const std::vector<PageTerm>& terms, double level) {
  const auto bound = [&](double r) {
    double total = 0.0;
    for (const PageTerm& t : terms) {
      total += t.c * t.magnitude * t.peak * kernel_value(t, r);
    }
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
/// (for the first camera only): from the ends and midpoint of every element
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
    for (const Vec3& start : {t.a(), t.b(), Vec3(0.5 * (t.a() + t.b()))}) {
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

/// The panel's name of a term's kernel: "cauchy 4" (segment), "point
/// soft", "point compact 4", "scalis inverse 3".
std::string kernel_label(const Term& term, const PageTerm& t) {
  const std::string family(family_name(t.family));
  if (std::holds_alternative<Segment>(*term.primitive)) return fmt::format("{} {}", family, t.degree);
  if (std::holds_alternative<ScalisSegment>(*term.primitive)) return fmt::format("scalis {} {}", family, t.degree);
  return kernels::family_facts(t.family).has_degree ? fmt::format("point {} {}", family, t.degree) : "point " + family;
}

/// The view_march.glsl function that builds the input of kernel `name`
/// from a primitive's row.
std::string input_builder(const std::string& name) {
  if (name.starts_with("point_")) return "point_input";
  if (name.starts_with("scalis_segment_")) return "scalis_input";
  return "segment_input";
}

/// The shader's dispatch on the kernel index: kernel_f and kernel_f_and_grad.
std::string dispatch_text(const std::vector<std::string>& kernels) {
  std::string f = "float kernel_f(int kernel, Row r, vec3 p) {\n";
  std::string g = "float kernel_f_and_grad(int kernel, Row r, vec3 p, out vec3 grad) {\n";
  for (std::size_t k = 0; k < kernels.size(); ++k) {
    const std::string input = input_builder(kernels[k]) + "(r, p)";
    f += fmt::format("  if (kernel == {}) return {}_f({});\n", k, kernels[k], input);
    g += fmt::format("  if (kernel == {}) return {}_f_and_grad({}, grad);\n", k, kernels[k], input);
  }
  return f + "  return 0.0;\n}\n\n" + g + "  grad = vec3(0.0);\n  return 0.0;\n}\n";
}

/// The guarded blocks (#ifndef SKELCONV_... #endif: input structs and
/// helpers) of `file`.
std::string guarded_blocks(std::string_view file) {
  std::string text;
  for (std::size_t at = file.find("#ifndef SKELCONV_"); at != std::string_view::npos;
       at = file.find("#ifndef SKELCONV_", at + 1)) {
    const std::size_t end = file.find("#endif", at) + std::string_view("#endif").size();
    text += std::string(file.substr(at, end - at)) + "\n\n";
  }
  return text;
}

/// Every input struct and helper (the shader's input builders use all three
/// structs), then the functions of the kernels in use, once each.
std::string kernels_text(const std::vector<std::string>& kernels) {
  std::string text = guarded_blocks(detail::segment_inverse_glsl) +
                     guarded_blocks(detail::scalis_segment_inverse_glsl) + guarded_blocks(detail::point_glsl);
  for (const std::string& name : kernels) {
    text += glsl_function(glsl_file(name), name + "_f(") + "\n";
    text += glsl_function(glsl_file(name), name + "_f_and_grad(") + "\n";
  }
  return text;
}

}  // namespace

namespace {

/// The ray-marching page; InputError (located) when the shader cannot
/// evaluate the skeleton.
std::string ray_march_page(const Skeleton& skeleton, const ViewPageOptions& options) {
  std::vector<Term> terms;
  collect_terms(skeleton, Skeleton::root, "primitives", 1.0, terms);
  // Every term in file order, so that a refusal names the first element
  // the ray marcher cannot show (its type or its kernel).
  for (const Term& term : terms) check_term(term);
  if (terms.size() > max_view_primitives) {
    throw InputError(fmt::format("{} primitives: the viewer's shader loops over every primitive per step and "
                                 "shows at most {} (docs/view.md)",
                                 terms.size(), max_view_primitives),
                     "primitives");
  }
  std::vector<std::string> kernels;
  const Frame frame = page_frame(terms);
  std::vector<PageTerm> page_terms;
  nlohmann::json primitives = nlohmann::json::array();
  double half_diagonal = 0.0;
  for (const Term& term : terms) {
    const std::string name = check_term(term);
    const auto found = std::find(kernels.begin(), kernels.end(), name);
    const std::size_t index = std::size_t(found - kernels.begin());
    if (found == kernels.end()) kernels.push_back(name);
    const PageTerm t = page_term(term, frame);
    page_terms.push_back(t);
    half_diagonal = std::max({half_diagonal, t.a.norm(), t.b.norm()});
    // The step bound's number (view_march.glsl): the degree, or c L with L
    // bounding |grad f_k| (|AB| ∫|w| max|K'| for a segment, w max|K'| for a
    // point: magnitude · slope).
    const bool lipschitz = is_supported(t.code) || t.code == Code::gaussian_point;
    const double bound = lipschitz ? t.c * t.magnitude * t.slope : t.degree;
    primitives.push_back({{"location", term.location},
                          {"kernel", kernel_label(term, t)},
                          {"kernel_index", index},
                          {"family", int(t.code)},
                          {"a", vec_json(t.a)},
                          {"b", vec_json(t.b)},
                          {"w", t.texel},
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
                               {"mode", "ray marching"},
                               // Points: a cross 1/50 of the sphere's radius.
                               {"overlay", detail::overlay_lines(skeleton, frame, 0.02 * radius)},
                               {"primitives", primitives}};
  std::string shader = detail::view_march_glsl;
  shader = fill(shader, "//@@KERNELS@@", kernels_text(kernels));
  shader = fill(shader, "//@@DISPATCH@@", dispatch_text(kernels));
  shader = fill(shader, "/*@@PRIMITIVE_COUNT@@*/1", std::to_string(terms.size()));
  shader = "#version 300 es\nprecision highp float;\nprecision highp int;\n" + shader;
  std::string page = detail::view_template_html;
  page = fill(page, "/*@@FRAGMENT_SHADER@@*/", script_safe(shader));
  return fill(page, "/*@@SKELETON_DATA@@*/", script_safe(data.dump(1)));
}

}  // namespace

namespace {

/// Refuses, at "iso", a skeleton whose field stays at or below its iso at
/// every skeleton point (Skeleton::skeleton_points, where skelconv mesh
/// looks for its surface, with the mesher's message): there is nothing to
/// show, and the ray-marched page would open on an empty scene. A point
/// where the field cannot be evaluated leaves the question to the page.
void require_surface(const Skeleton& skeleton) {
  const double iso = skeleton.iso();
  double largest = -std::numeric_limits<double>::infinity();
  Vec3 largest_at = Vec3::Zero();
  for (const Vec3& p : skeleton.skeleton_points()) {
    double f = 0.0;
    try {
      f = skeleton.value(p);
    } catch (const EvaluationError&) {
      return;
    }
    if (f > iso) return;
    if (f > largest) largest = f, largest_at = p;
  }
  throw InputError(fmt::format("no surface at iso {}: the field is below it on the whole skeleton (largest value "
                               "{:.6g} at ({}, {}, {}))",
                               iso, largest, largest_at.x(), largest_at.y(), largest_at.z()),
                   "iso");
}

}  // namespace

std::string make_view_page(const Skeleton& skeleton, const ViewPageOptions& options, ViewPageReport* report) {
  skeleton.validate();  // bad input is refused here, whatever the page
  // Refused before either page is tried: the mesh preview has no box to mesh in.
  if (skeleton.primitives().empty()) throw InputError("no primitive: there is no surface to show", "primitives");
  require_surface(skeleton);
  ViewPageReport local;
  ViewPageReport& r = report ? *report : local;
  try {
    r = ViewPageReport{};
    if (options.force_mesh_preview) throw InputError("the mesh preview was asked for (--mesh-preview)");
    return ray_march_page(skeleton, options);
  } catch (const InputError& refusal) {
    if (!options.mesh_preview) throw;
    r.mesh_preview = true;
    r.reason = refusal.what();
  }
  return detail::mesh_preview_page(skeleton, options, r);
}

namespace detail {

std::string fill(std::string text, std::string_view marker, const std::string& value) {
  const std::size_t at = text.find(marker);
  if (at == std::string::npos) throw std::logic_error("view template without " + std::string(marker));
  return text.replace(at, marker.size(), value);
}

std::string script_safe(std::string text) {
  for (std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at)) text.replace(at, 2, "<\\/");
  return text;
}

nlohmann::json overlay_lines(const Skeleton& skeleton, const Frame& frame, double cross) {
  nlohmann::json lines = nlohmann::json::array();
  const auto line = [&](const Vec3& a, const Vec3& b) {
    for (const Vec3& end : {frame.to_page(a), frame.to_page(b)})
      for (int j = 0; j < 3; ++j) lines.push_back(end[j]);
  };
  const auto loop = [&](const auto& vertices) {
    for (std::size_t k = 0; k < vertices.size(); ++k) line(vertices[k], vertices[(k + 1) % vertices.size()]);
  };
  for (const Primitive& primitive : skeleton.primitives()) {
    if (const auto* s = std::get_if<Segment>(&primitive)) line(s->a(), s->b());
    else if (const auto* s = std::get_if<ScalisSegment>(&primitive)) line(s->a(), s->b());
    else if (const auto* p = std::get_if<Polygon>(&primitive)) loop(p->vertices());
    else if (const auto* t = std::get_if<ScalisTriangle>(&primitive)) loop(t->vertices());
    else {
      const Vec3 c = std::get<PointPrimitive>(primitive).center();
      for (int axis = 0; axis < 3; ++axis)
        line(c - cross * frame.scale * Vec3::Unit(axis), c + cross * frame.scale * Vec3::Unit(axis));
    }
  }
  return lines;
}

}  // namespace detail
}  // namespace skelconv
