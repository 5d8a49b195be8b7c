// skelconv/kernels/read_trait.hpp — a family's static trait members, for
// header-only code.
//
// family_facts() and with_trait() (kernel_list.hpp) construct a trait or
// throw InputError, both defined in the runtime library; the templates that
// also run on other scalar types without it (generic.hpp, polygon_field.hpp)
// read the static members of a family's trait through read_trait instead.
#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>
#include <variant>

#include "skelconv/kernels/kernel_list.hpp"

namespace skelconv::kernels {

/// f(std::type_identity<Trait>{}) for the trait of `family`, or `otherwise`
/// when no trait has that value. Constructs nothing and throws nothing.
template <class R, class F, std::size_t index = 0>
constexpr R read_trait(KernelFamily family, F&& f, R otherwise) {
  if constexpr (index == std::variant_size_v<RadialKernel>) {
    return otherwise;
  } else {
    using Kernel = std::variant_alternative_t<index, RadialKernel>;
    if (family == Kernel::family) return f(std::type_identity<Kernel>{});
    return read_trait<R, F, index + 1>(family, std::forward<F>(f), std::move(otherwise));
  }
}

/// The trait's finite_support (false for a value that names no family).
constexpr bool has_finite_support(KernelFamily family) {
  return read_trait<bool>(family, [](auto trait) { return decltype(trait)::type::finite_support; }, false);
}

}  // namespace skelconv::kernels
