// skelconv/kernels/radial_kernel.hpp — what a radial kernel trait is.
//
// A kernel family is described ONCE, as a small struct (a "trait") that the
// point primitive (skelconv/primitives/point.hpp), the JSON reader and the
// bounding-volume index (skelconv/field/support_index.hpp) use without
// switching on the family:
//
//   struct SomeKernel {
//     static constexpr KernelFamily family;          // the enum value
//     static constexpr std::string_view name;        // JSON "family" name
//     static constexpr std::array<std::string_view, N> parameters;  // JSON keys besides
//                                                     // "family" and "degree"
//     static constexpr bool has_degree;              // JSON "degree" is read
//     static constexpr unsigned primitives;          // PrimitiveKind bits: where the
//                                                     // family has a field (below)
//     static constexpr std::array<CompactLevel, N> compact_levels;  // optional member:
//                                                     // K = Σ c_j k_R^(i_j), exactly (below)
//     static constexpr int min_degree, max_degree;   // degrees i on a point
//     static constexpr bool singular_at_zero;        // K(0) = +inf (inverse)
//     explicit SomeKernel(const KernelSpec&);        // validates: InputError at
//                                                     // "kernel.degree", "kernel.<param>"
//     double support_radius() const;                 // K(r) = 0 for r >= it; +inf if none
//     static constexpr bool finite_support;          // support_radius() is finite
//     static constexpr bool vanishes_far;            // K is 0 (finite support) or underflows
//                                                     // to 0 at a finite r (faster than any power)
//     int scaling_power() const;                     // p: with its length parameters scaled
//                                                     // by λ, the kernel is λ^p K(r/λ) (below)
//     double length_scale() const;                   // its own length (1 if it has none)
//     double max_value() const;                      // max K = K(0) (+inf: singular)
//     double max_slope() const;                      // max |dK/dr| (+inf: singular)
//     template <class T> T value(const T& r) const;       // K(r), r >= 0
//     template <class T> T derivative(const T& r) const;  // dK/dr, r >= 0
//     std::optional<double> point_iso_radius(double c) const;  // ρ: K(ρ) = c
//     std::optional<double> line_iso_radius(double c) const;   // optional member:
//                                                     // d where ∫K along an infinite line = c
//     static constexpr bool thickness_correction;    // optional member: the thickness
//                                                     // corrections take this family (compact)
//     static constexpr int polygon_excluded_degree;  // optional member, with
//     static constexpr std::string_view polygon_excluded_reason;  // a degree the polygon
//                                                     // closed forms leave out (inverse 2)
//   };
//
// Scaling (scaling_power): multiplying every length by λ, and the kernel's
// length parameters with them (R, e as lengths, s and a as length^−2), turns
// K into λ^p K(r/λ): p = −i for the inverse kernel, which has no length of its
// own, and 0 for every other family, a function of r/R, s r², a r². A
// segment's field then scales by λ^(1+p), a polygon's by λ^(2+p).
//
// Every family is non-increasing in r (the interval enclosures of
// skelconv/interval/ rely on it), and value() compares only its argument r
// with constants, so that it also runs on a point interval.
//
// value() and derivative() are templates on the scalar type (double, long
// double, boost::multiprecision numbers…) so that tests can evaluate the same
// formula in extended precision. A new family (as soft, wyvill, ferley and
// gaussian and polynomial were) is one more such struct, one more entry in
// RadialKernel (skelconv/kernels/kernel_list.hpp), its name in KernelFamily
// and in all_kernel_families (docs/architecture.md, "Adding a kernel family").
//
// The segment and polygon primitives keep their generated closed forms
// (generated/, docs/generated_api.md): the traits describe the kernel, not the
// convolution.
#pragma once

#include <cmath>
#include <string_view>

#include "skelconv/errors.hpp"
#include "skelconv/kernels/kernel_spec.hpp"

namespace skelconv::kernels {

/// The primitives a family has a field on, as bits of a trait's
/// `primitives`: points always (f = w K(r)); segments and polygons where a
/// closed form exists (generated, or a combination of generated ones);
/// SCALIS segments and triangles only for the families of docs/mathematics.md §4.
enum PrimitiveKind : unsigned {
  on_points = 1u << 0,
  on_segments = 1u << 1,
  on_polygons = 1u << 2,
  on_scalis = 1u << 3,  ///< SCALIS segments and triangles
};

/// One term (numerator / denominator) · k_R^degree of a kernel that is an
/// exact combination of compact levels (docs/mathematics.md §1 k_R^i with the trait's R):
/// soft = k_R^4, Wyvill = 5/9 k_R^4 + 4/9 k_R^6. Its segment and polygon
/// fields are the same combination of the generated compact closed forms
/// (skelconv/kernels/derived_segment_kernels.hpp, Polygon). The coefficient is a
/// ratio of integers so that extended-precision evaluation sees it exactly.
struct CompactLevel {
  int numerator = 1;
  int denominator = 1;
  int degree = 4;  ///< i of k_R^i
};

/// (1 + u)^(−i/2)-style half-integer powers: x^(n/2) for x ≥ 0 and n ≥ 0,
/// by integer powering and at most one square root (exact for even n).
template <class T>
T half_integer_power(const T& x, int n) {
  using std::sqrt;
  T result(1);
  T base = x;
  for (int k = n / 2; k > 0; k >>= 1) {  // x^⌊n/2⌋ by binary powering
    if (k & 1) result *= base;
    base *= base;
  }
  if (n % 2 != 0) result *= sqrt(x);
  return result;
}

/// The x in [lo, hi] with f(x) = target for an increasing f with
/// f(lo) ≤ target ≤ f(hi), by bisection to the last bit (the iso radii of
/// families without an explicit inverse).
template <class F>
double bisect_increasing(F f, double lo, double hi, double target) {
  for (int step = 0; step < 200; ++step) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (f(mid) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

/// Throws InputError at "kernel.degree" unless min ≤ degree ≤ max.
void require_degree(std::string_view family, int degree, int min_degree, int max_degree);

/// Throws InputError at "kernel.degree" for a degree i ≤ 2, whose SCALIS
/// plane normalisation ∬ K(√(1 + |u|²)) du diverges (K ~ d^−2).
void require_plane_degree(std::string_view family, int degree);

/// Throws InputError at `where` ("kernel.s") unless value is finite and > 0.
void require_positive(double value, const char* where);

}  // namespace skelconv::kernels
