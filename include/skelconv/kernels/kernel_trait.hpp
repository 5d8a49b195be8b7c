// skelconv/kernels/kernel_trait.hpp — the C++20 concept a kernel family's
// trait satisfies (the interface radial_kernel.hpp describes in prose).
//
// Every entry of RadialKernel (kernel_list.hpp) is checked against it at
// compile time (src/kernels/radial_kernel.cpp), so a new family that forgets
// a member fails to compile with the member named, instead of failing in the
// dispatch templates that read it.
#pragma once

#include <concepts>
#include <optional>
#include <string_view>

#include "skelconv/kernels/kernel_spec.hpp"

namespace skelconv::kernels {

template <class K>
concept RadialKernelTrait = requires(const K k, const KernelSpec& spec, double r, double c) {
  // Identity and JSON spelling.
  { K::family } -> std::convertible_to<KernelFamily>;
  { K::name } -> std::convertible_to<std::string_view>;
  { K::parameters.size() } -> std::convertible_to<std::size_t>;  // JSON keys besides "family", "degree"
  { K::has_degree } -> std::convertible_to<bool>;
  // Where the family has a field (PrimitiveKind bits) and its degrees.
  { K::primitives } -> std::convertible_to<unsigned>;
  { K::min_degree } -> std::convertible_to<int>;
  { K::max_degree } -> std::convertible_to<int>;
  { K::singular_at_zero } -> std::convertible_to<bool>;
  // Parameters and their checks (the constructor throws InputError at
  // "kernel.<key>"), the support radius (+inf: infinite support), K and
  // dK/dr (templates on the scalar; checked in double here), the iso radius.
  K(spec);
  { k.support_radius() } -> std::convertible_to<double>;
  { k.value(r) } -> std::convertible_to<double>;
  { k.derivative(r) } -> std::convertible_to<double>;
  { k.point_iso_radius(c) } -> std::convertible_to<std::optional<double>>;
  // What the runtime asks instead of comparing families (radial_kernel.hpp).
  { K::finite_support } -> std::convertible_to<bool>;
  { K::vanishes_far } -> std::convertible_to<bool>;
  { k.scaling_power() } -> std::convertible_to<int>;
  { k.length_scale() } -> std::convertible_to<double>;
  { k.max_value() } -> std::convertible_to<double>;
  { k.max_slope() } -> std::convertible_to<double>;
};

}  // namespace skelconv::kernels
