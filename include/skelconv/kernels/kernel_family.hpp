// skelconv/kernels/kernel_family.hpp — the names of the kernel families.
//
// The enum is the key the generated tables (generated/segment_table.hpp and
// the others) and KernelSpec carry; everything else about a family lives in
// its trait (radial_kernel.hpp, kernel_list.hpp).
#pragma once

#include <string_view>

namespace skelconv {

/// Kernel families of docs/mathematics.md §1 (Hubert 2012 §2.1).
enum class KernelFamily {
  inverse,  ///< p^i(r) = r^-i
  cauchy,   ///< c_s^i(r) = (1 + s r²)^(-i/2)
  compact,  ///< k_R^i(r) = (1 − r²/R²)^(i/2) for r < R, else 0
  // The soft-object families (include/skelconv/kernels/): not in
  // the generated tables. Soft and Wyvill are combinations of compact levels
  // on segments and polygons, the Gaussian has its erf closed form on
  // segments (skelconv/kernels/derived_segment_kernels.hpp); Ferley's is points
  // only. Each trait's `primitives` says where a family is defined.
  soft,      ///< (1 − r²/R²)² for r < R (the exam notes' "soft objects")
  wyvill,    ///< 1 − 22/9 u + 17/9 u² − 4/9 u³, u = r²/R², for r < R
  ferley,    ///< 1 + k(e − r) for r < e, (r − R)²/(e − R)² for e ≤ r < R
  gaussian,  ///< b exp(−a r²) (Blinn, Muraki)
  polynomial,  ///< (1 − r²/R²)^k for r < R (points only; compact degree 2k)
};

/// "inverse", "cauchy", "compact", "soft", "wyvill", "ferley", "gaussian",
/// "polynomial":
/// the JSON spelling, which each trait repeats as its `name` (checked at
/// compile time in src/kernels/radial_kernel.cpp). A switch, not the traits,
/// because the generated code names families without including them.
constexpr std::string_view family_name(KernelFamily family) {
  switch (family) {
    case KernelFamily::inverse: return "inverse";
    case KernelFamily::cauchy: return "cauchy";
    case KernelFamily::compact: return "compact";
    case KernelFamily::soft: return "soft";
    case KernelFamily::wyvill: return "wyvill";
    case KernelFamily::ferley: return "ferley";
    case KernelFamily::gaussian: return "gaussian";
    case KernelFamily::polynomial: return "polynomial";
  }
  return "?";
}

}  // namespace skelconv
