// The checks shared by the radial kernel traits (skelconv/kernels/radial_kernel.hpp).
#include "skelconv/kernels/radial_kernel.hpp"

#include "skelconv/kernels/ferley.hpp"
#include "skelconv/kernels/kernel_list.hpp"
#include "skelconv/kernels/kernel_trait.hpp"

#include <algorithm>
#include <iterator>
#include <utility>

#include <fmt/format.h>

#include "../detail/input_checks.hpp"

namespace skelconv::kernels {

// Every family in RadialKernel satisfies the trait concept.
static_assert([]<std::size_t... i>(std::index_sequence<i...>) {
  return (RadialKernelTrait<std::variant_alternative_t<i, RadialKernel>> && ...);
}(std::make_index_sequence<std::variant_size_v<RadialKernel>>{}));

// Each trait's JSON name is family_name() of its enum value.
static_assert([]<std::size_t... i>(std::index_sequence<i...>) {
  return ((std::variant_alternative_t<i, RadialKernel>::name ==
           family_name(std::variant_alternative_t<i, RadialKernel>::family)) &&
          ...);
}(std::make_index_sequence<std::variant_size_v<RadialKernel>>{}));

// all_kernel_families (kernel_spec.hpp, which the reader's messages and the
// verifier iterate) lists every trait's family, once: a new family that is
// in RadialKernel but not in that list fails here.
static_assert(std::size(all_kernel_families) == std::variant_size_v<RadialKernel>);
static_assert([]<std::size_t... i>(std::index_sequence<i...>) {
  return ((std::ranges::count(all_kernel_families, std::variant_alternative_t<i, RadialKernel>::family) == 1) && ...);
}(std::make_index_sequence<std::variant_size_v<RadialKernel>>{}));

void require_degree(std::string_view family, int degree, int min_degree, int max_degree) {
  if (degree < min_degree || degree > max_degree) {
    throw InputError(fmt::format("unsupported degree {} for the {} family on a point; supported: {}..{}", degree,
                                 family, min_degree, max_degree),
                     "kernel.degree");
  }
}

void require_plane_degree(std::string_view family, int degree) {
  if (degree <= 2) {
    throw InputError(fmt::format("the plane normalisation of the {} family diverges for degree {} <= 2", family, degree),
                     "kernel.degree");
  }
}

void require_positive(double value, const char* where) { skelconv::detail::require_positive_parameter(value, where); }

FerleyKernel::FerleyKernel(const KernelSpec& spec) : e(spec.e), R(spec.R) {
  require_positive(e, "kernel.e");
  require_positive(R, "kernel.R");
  if (!(R > e)) {
    throw InputError(fmt::format("must be > e = {} (the support radius beyond the coating), got {}", e, R),
                     "kernel.R");
  }
}

}  // namespace skelconv::kernels
