// skelconv/kernels/kernel_list.hpp — every radial kernel trait, as one
// variant, and the one place a KernelSpec becomes a trait.
//
// Adding a family (issue 13) is: its trait header, one entry in RadialKernel
// below, and its name in KernelFamily (segment_input.hpp).
#pragma once

#include <string>
#include <variant>

#include "skelconv/kernels/cauchy.hpp"
#include "skelconv/kernels/compact.hpp"
#include "skelconv/kernels/inverse.hpp"

namespace skelconv::kernels {

using RadialKernel = std::variant<InverseKernel, CauchyKernel, CompactKernel>;

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
}  // namespace detail

/// The trait of spec.family with spec's parameters, validated (InputError
/// at "kernel.degree", "kernel.s", "kernel.R").
inline RadialKernel make_radial_kernel(const KernelSpec& spec) { return detail::make_from(spec); }

/// The support radius of any trait (+inf for infinite support).
inline double support_radius(const RadialKernel& kernel) {
  return std::visit([](const auto& k) { return k.support_radius(); }, kernel);
}

}  // namespace skelconv::kernels
