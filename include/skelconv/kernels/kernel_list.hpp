// skelconv/kernels/kernel_list.hpp — every radial kernel trait, as one
// variant, and the one place a KernelSpec becomes a trait.
//
// Adding a family is: its trait header, one entry in RadialKernel
// below, its name in KernelFamily (kernel_family.hpp) and in
// all_kernel_families (kernel_spec.hpp); docs/architecture.md lists the
// tests and docs that go with it. The reader
// (src/skeleton/skeleton_file.cpp) learns its JSON keys from family_facts().
#pragma once

#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

#include "skelconv/kernels/cauchy.hpp"
#include "skelconv/kernels/compact.hpp"
#include "skelconv/kernels/ferley.hpp"
#include "skelconv/kernels/gaussian.hpp"
#include "skelconv/kernels/inverse.hpp"
#include "skelconv/kernels/polynomial.hpp"
#include "skelconv/kernels/scalis_description.hpp"
#include "skelconv/kernels/soft.hpp"
#include "skelconv/kernels/wyvill.hpp"

namespace skelconv::kernels {

using RadialKernel = std::variant<InverseKernel, CauchyKernel, CompactKernel, SoftKernel, WyvillKernel, FerleyKernel,
                                  GaussianKernel, PolynomialKernel>;

/// What the reader needs to know of a family, read off its trait.
struct FamilyFacts {
  std::string_view name;
  std::span<const std::string_view> parameters;  ///< JSON keys besides "family" (and "degree")
  bool has_degree = true;
  int min_degree = 0;               ///< smallest degree the trait accepts (0: no degree)
  unsigned primitives = on_points;  ///< PrimitiveKind bits (radial_kernel.hpp)
  bool singular_at_zero = false;    ///< K(0) = +inf (inverse)
  bool finite_support = false;      ///< K = 0 beyond a radius (compact, soft, wyvill, ferley, polynomial)
  bool vanishes_far = false;        ///< the trait's vanishes_far: a positive field may be 0 in double
  /// No length of its own (scaling_power ≠ 0, radial_kernel.hpp: inverse):
  /// K(r/σ) = σ^(−p) K(r), so a scale σ factors out of every field.
  bool scale_free = false;
  /// Non-empty: K is this exact combination of compact levels k_R^i.
  std::span<const CompactLevel> compact_levels;
  /// The trait's optional thickness_correction: the thickness corrections
  /// take this family (skelconv/skeleton/thickness_correction.hpp).
  bool thickness_correction = false;
  /// The trait's optional polygon_excluded_degree (0: none), a degree inside
  /// the polygon range that the closed forms leave out, and the reason.
  int polygon_excluded_degree = 0;
  std::string_view polygon_excluded_reason;

  // The SCALIS description (scalis_description.hpp); defaults elsewhere.
  ScalisSingularity scalis_singularity = ScalisSingularity::none;
  bool scalis_segment_generated = false;
  bool scalis_sigma_above_one = false;
  double scalis_radius_term = 0.0;

  bool on(PrimitiveKind kind) const { return (primitives & kind) != 0; }
};

namespace detail {
template <std::size_t index = 0>
RadialKernel make_from(const KernelSpec& spec) {
  if constexpr (index == std::variant_size_v<RadialKernel>) {
    throw InputError("family \"" + std::string(family_name(spec.family)) + "\" has no radial kernel trait",
                     "kernel.family");
  } else {
    using Kernel = std::variant_alternative_t<index, RadialKernel>;
    if (spec.family == Kernel::family) return Kernel(spec);
    return make_from<index + 1>(spec);
  }
}
template <std::size_t index = 0>
FamilyFacts facts_from(KernelFamily family) {
  if constexpr (index == std::variant_size_v<RadialKernel>) {
    FamilyFacts facts;
    facts.name = family_name(family);
    return facts;
  } else {
    using Kernel = std::variant_alternative_t<index, RadialKernel>;
    if (family == Kernel::family) {
      FamilyFacts facts;
      facts.name = Kernel::name;
      facts.parameters = std::span<const std::string_view>(Kernel::parameters);
      facts.has_degree = Kernel::has_degree;
      facts.min_degree = Kernel::min_degree;
      facts.primitives = Kernel::primitives;
      facts.singular_at_zero = Kernel::singular_at_zero;
      KernelSpec defaults;  // valid parameters for every family
      defaults.family = family;
      defaults.degree = Kernel::min_degree;
      facts.finite_support = Kernel::finite_support;
      facts.vanishes_far = Kernel::vanishes_far;
      facts.scale_free = Kernel(defaults).scaling_power() != 0;
      if constexpr (requires { Kernel::compact_levels; }) facts.compact_levels = Kernel::compact_levels;
      if constexpr (requires { Kernel::thickness_correction; }) facts.thickness_correction = Kernel::thickness_correction;
      if constexpr (requires { Kernel::polygon_excluded_degree; }) {
        facts.polygon_excluded_degree = Kernel::polygon_excluded_degree;
        facts.polygon_excluded_reason = Kernel::polygon_excluded_reason;
      }
      if constexpr ((Kernel::primitives & on_scalis) != 0) {
        facts.scalis_singularity = Kernel::scalis_singularity;
        facts.scalis_segment_generated = Kernel::scalis_segment_generated;
        facts.scalis_sigma_above_one = Kernel::scalis_sigma_above_one;
        facts.scalis_radius_term = Kernel::scalis_radius_term;
      }
      return facts;
    }
    return facts_from<index + 1>(family);
  }
}
}  // namespace detail

/// f(std::type_identity<Trait>{}) for the trait of `family`, one of those
/// whose `primitives` include `kind` (InputError at "kernel.family" for any
/// other: the primitives check that first, so it does not happen). The
/// primitives read their family-specific descriptions (e.g. the SCALIS
/// normalisations, scalis_description.hpp) through this instead of switching
/// on the family.
template <unsigned kind, class F, std::size_t index = 0>
decltype(auto) with_trait(KernelFamily family, F&& f) {
  if constexpr (index == std::variant_size_v<RadialKernel>) {
    throw InputError("the " + std::string(family_name(family)) + " family is not defined on this primitive",
                     "kernel.family");
    return f(std::type_identity<std::variant_alternative_t<0, RadialKernel>>{});  // the return type
  } else {
    using Kernel = std::variant_alternative_t<index, RadialKernel>;
    if constexpr ((Kernel::primitives & kind) != 0) {
      if (family == Kernel::family) return f(std::type_identity<Kernel>{});
    }
    return with_trait<kind, F, index + 1>(family, std::forward<F>(f));
  }
}

/// The JSON name, keys and primitives of `family` (from its trait).
inline FamilyFacts family_facts(KernelFamily family) { return detail::facts_from(family); }

/// The trait of spec.family with spec's parameters, validated (InputError
/// at "kernel.degree", "kernel.s", "kernel.R").
inline RadialKernel make_radial_kernel(const KernelSpec& spec) { return detail::make_from(spec); }

/// The support radius of any trait (+inf for infinite support).
inline double support_radius(const RadialKernel& kernel) {
  return std::visit([](const auto& k) { return k.support_radius(); }, kernel);
}

namespace detail {
/// The trait of spec.family with spec's parameters (InputError at
/// "kernel.<key>") and spec's degree unchecked: the degrees of segments,
/// polygons and SCALIS primitives are those of their own tables, not the
/// trait's point range.
inline RadialKernel trait_of_any_degree(const KernelSpec& spec) {
  KernelSpec checked = spec;
  checked.degree = family_facts(spec.family).min_degree;
  RadialKernel kernel = make_radial_kernel(checked);
  std::visit(
      [&](auto& k) {
        if constexpr (requires { k.degree; }) k.degree = spec.degree;
      },
      kernel);
  return kernel;
}
}  // namespace detail

/// The trait's scaling_power(), length_scale(), max_value(), max_slope()
/// (radial_kernel.hpp) for spec, of any degree (detail::trait_of_any_degree).
inline int scaling_power(const KernelSpec& spec) {
  return std::visit([](const auto& k) { return k.scaling_power(); }, detail::trait_of_any_degree(spec));
}
inline double length_scale(const KernelSpec& spec) {
  return std::visit([](const auto& k) { return k.length_scale(); }, detail::trait_of_any_degree(spec));
}
inline double max_value(const KernelSpec& spec) {
  return std::visit([](const auto& k) { return k.max_value(); }, detail::trait_of_any_degree(spec));
}
inline double max_slope(const KernelSpec& spec) {
  return std::visit([](const auto& k) { return k.max_slope(); }, detail::trait_of_any_degree(spec));
}

/// Radius of the iso-surface w K(r) = c around a point primitive of weight
/// w > 0 (the trait's point_iso_radius at level c / w); nullopt where there
/// is none (c / w outside (0, K(0))).
inline std::optional<double> point_iso_radius(const RadialKernel& kernel, double c, double weight = 1.0) {
  return std::visit([&](const auto& k) { return k.point_iso_radius(c / weight); }, kernel);
}

/// Distance of the iso-surface ∫ w K = c from an infinite straight segment,
/// for the families that give it (soft, wyvill, gaussian); nullopt for the
/// others, and where there is none.
inline std::optional<double> line_iso_radius(const RadialKernel& kernel, double c, double weight = 1.0) {
  return std::visit(
      [&](const auto& k) -> std::optional<double> {
        if constexpr (requires { k.line_iso_radius(c); }) {
          return k.line_iso_radius(c / weight);
        } else {
          return std::nullopt;
        }
      },
      kernel);
}

}  // namespace skelconv::kernels
