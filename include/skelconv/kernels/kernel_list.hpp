// skelconv/kernels/kernel_list.hpp — every radial kernel trait, as one
// variant, and the one place a KernelSpec becomes a trait.
//
// Adding a family is: its trait header, one entry in RadialKernel
// below, and its name in KernelFamily (segment_input.hpp). The reader
// (src/runtime/skeleton_file.cpp) learns its JSON keys from family_facts().
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
#include "skelconv/kernels/soft.hpp"
#include "skelconv/kernels/wyvill.hpp"

namespace skelconv::kernels {

using RadialKernel = std::variant<InverseKernel, CauchyKernel, CompactKernel, SoftKernel, WyvillKernel, FerleyKernel,
                                  GaussianKernel>;

/// What the reader needs to know of a family, read off its trait.
struct FamilyFacts {
  std::string_view name;
  std::span<const std::string_view> parameters;  ///< JSON keys besides "family" (and "degree")
  bool has_degree = true;
  int min_degree = 0;               ///< smallest degree the trait accepts (0: no degree)
  unsigned primitives = on_points;  ///< PrimitiveKind bits (radial_kernel.hpp)
  bool singular_at_zero = false;    ///< K(0) = +inf (inverse)
  bool finite_support = false;      ///< K = 0 beyond a radius (compact, soft, wyvill, ferley)
  /// Non-empty: K is this exact combination of compact levels k_R^i.
  std::span<const CompactLevel> compact_levels;

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
    return {family_name(family), {}, true, 0, on_points, false, false, {}};
  } else {
    using Kernel = std::variant_alternative_t<index, RadialKernel>;
    if (family == Kernel::family) {
      std::span<const CompactLevel> levels;
      if constexpr (requires { Kernel::compact_levels; }) levels = Kernel::compact_levels;
      KernelSpec defaults;  // valid parameters for every family
      defaults.family = family;
      defaults.degree = Kernel::min_degree;
      const bool finite_support = std::isfinite(Kernel(defaults).support_radius());
      return {Kernel::name, std::span<const std::string_view>(Kernel::parameters), Kernel::has_degree,
              Kernel::min_degree, Kernel::primitives, Kernel::singular_at_zero, finite_support, levels};
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
