// codegen/generated_families.hpp — the kernel families the generator knows,
// one row each (the codegen side of "a family is described once"; the
// runtime side is its trait, include/skelconv/kernels/).
//
// Every row is K = (α q + β)^(−n/2) of the squared distance q = |P − X|²
// (segment_families.hpp derives the closed forms from that shape):
//
//     inverse p^i    α = 1,      β = 0,  n = i
//     Cauchy  c_s^i  α = s,      β = 1,  n = i
//     compact k_R^i  α = −1/R²,  β = 1,  n = −i   (on the clipped [t0, t1])
//
// A family of another shape (the Gaussian's exp(−a q)) is not a row here: its
// segment closed form is hand-written (include/skelconv/primitives/segment_gaussian.hpp),
// and families that are combinations of these rows (soft, Wyvill) need no
// generated code of their own (include/skelconv/kernels/derived_segment_kernels.hpp).
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

#include <skelconv/primitives/segment_input.hpp>

namespace skelconv::codegen {

struct GeneratedFamily {
  /// How α depends on the kernel's parameter.
  enum class Alpha {
    one,                   ///< α = 1 (no parameter)
    parameter,             ///< α = the parameter (Cauchy's s)
    minus_inverse_square,  ///< α = −1/parameter² (compact's R)
  };
  KernelFamily family;
  const char* parameter;  ///< the SegmentInput field α reads ("s", "R"), nullptr for none
  Alpha alpha;
  int beta;
  bool compact_support;         ///< n = −i, integrals over the clip [t0, t1]
  int min_segment_degree;       ///< i ≥ this on segments
  int min_polygon_degree;       ///< i ≥ this on polygons (p^2 diverges there)
  bool even_polygon_degrees;    ///< polygons take even i only (Hubert 2012 §8)
  const char* kernel_text;      ///< K for the equations: "{d}" the distance vector, "{i}" the degree
};

inline constexpr GeneratedFamily generated_families[] = {
    {KernelFamily::inverse, nullptr, GeneratedFamily::Alpha::one, 0, false, 1, 3, false, "|{d}|^(−{i})"},
    {KernelFamily::cauchy, "s", GeneratedFamily::Alpha::parameter, 1, false, 1, 3, false, "(1 + s |{d}|²)^(−{i}/2)"},
    {KernelFamily::compact, "R", GeneratedFamily::Alpha::minus_inverse_square, 1, true, 2, 2, true,
     "(1 − |{d}|²/R²)^({i}/2)"},
};

/// The row of `family`; std::logic_error for a family the generator does not know.
inline const GeneratedFamily& generated_family(KernelFamily family) {
  for (const GeneratedFamily& row : generated_families)
    if (row.family == family) return row;
  throw std::logic_error("the generator has no closed form for the " + std::string(family_name(family)) + " family");
}

/// The row's kernel_text with {d} and {i} replaced.
inline std::string kernel_text(const GeneratedFamily& row, const std::string& d, int degree) {
  std::string text = row.kernel_text;
  for (const auto& [key, value] : {std::pair<std::string, std::string>{"{d}", d}, {"{i}", std::to_string(degree)}}) {
    for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + value.size()))
      text.replace(at, key.size(), value);
  }
  return text;
}

}  // namespace skelconv::codegen
