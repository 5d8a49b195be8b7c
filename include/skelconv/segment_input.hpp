// skelconv/segment_input.hpp — the contract between the runtime and the
// generated segment kernels (generated/segment_*.hpp).
//
// Every generated segment function reads one SegmentInput and computes
//
//     f(P) = |AB| ∫_{t0}^{t1} w(t) K(|P − Γ(t)|) dt,   Γ(t) = A + t (B − A)
//
// (SPEC §2), and/or ∇_P f. One struct for all families keeps the generated
// table uniform: a family reads only the fields it needs.
#pragma once

#include <array>
#include <string_view>

#include "skelconv/op_count.hpp"

namespace skelconv {

/// Kernel families of SPEC §1 (Hubert 2012 §2.1).
enum class KernelFamily {
  inverse,  ///< p^i(r) = r^-i
  cauchy,   ///< c_s^i(r) = (1 + s r²)^(-i/2)
  compact,  ///< k_R^i(r) = (1 − r²/R²)^(i/2) for r < R, else 0
  // The soft-object families (include/skelconv/kernels/): not in
  // the generated tables. Soft and Wyvill are combinations of compact levels
  // on segments and polygons, the Gaussian has its erf closed form on
  // segments (skelconv/derived_segment_kernels.hpp); Ferley's is points
  // only. Each trait's `primitives` says where a family is defined.
  soft,      ///< (1 − r²/R²)² for r < R (the exam notes' "soft objects")
  wyvill,    ///< 1 − 22/9 u + 17/9 u² − 4/9 u³, u = r²/R², for r < R
  ferley,    ///< 1 + k(e − r) for r < e, (r − R)²/(e − R)² for e ≤ r < R
  gaussian,  ///< b exp(−a r²) (Blinn, Muraki)
};

/// "inverse", "cauchy", "compact", "soft", "wyvill", "ferley", "gaussian".
constexpr std::string_view family_name(KernelFamily family) {
  switch (family) {
    case KernelFamily::inverse: return "inverse";
    case KernelFamily::cauchy: return "cauchy";
    case KernelFamily::compact: return "compact";
    case KernelFamily::soft: return "soft";
    case KernelFamily::wyvill: return "wyvill";
    case KernelFamily::ferley: return "ferley";
    case KernelFamily::gaussian: return "gaussian";
  }
  return "?";
}

/// Largest weight-polynomial degree the generator emits by default.
inline constexpr int max_weight_degree = 3;

/// Inputs of one generated segment evaluation, on scalar type T.
template <class T>
struct SegmentInput {
  std::array<T, 3> a{};  ///< segment start A (t = 0)
  std::array<T, 3> b{};  ///< segment end B (t = 1)
  std::array<T, 3> p{};  ///< query point P
  /// Weight w(t) = Σ_k w[k] t^k; a function of weight degree d reads w[0..d].
  std::array<T, max_weight_degree + 1> w{T(1), T(0), T(0), T(0)};
  T s = T(1);   ///< Cauchy sharpness s > 0 (cauchy only)
  T R = T(1);   ///< support radius R > 0 (compact, and the compact levels of soft and wyvill)
  T gaussian_a = T(1);  ///< Gaussian sharpness a > 0 (gaussian only: K = b exp(−a r²))
  T gaussian_b = T(1);  ///< Gaussian height b > 0 (gaussian only)
  /// Compact only: the part [t0, t1] ⊆ [0, 1] of the segment inside the ball
  /// of radius R around P (see skelconv/clip.hpp). The kernel vanishes at a
  /// clipped end, so the moving bounds add nothing to ∇f (SPEC §2).
  T t0 = T(0);
  T t1 = T(1);
};

}  // namespace skelconv
