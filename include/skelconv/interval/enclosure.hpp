// skelconv/interval/enclosure.hpp — sound enclosures [lo, hi] of a skeleton's
// field over an axis-aligned box (docs/bound.md).
//
// "Sound": for every point P of the box, the exact field f(P) (of the
// primitives as defined in docs/mathematics.md, with the double-precision parameters
// stored in them) lies in [lo, hi], rounding included: everything is
// computed in outward-rounded interval arithmetic (interval.hpp).
//
//   point       the exam notes' inclusion function, exactly: w·[K(d_max),
//               K(d_min)] from the interval squared distance (kernel_range.hpp)
//   segment     the segment is cut into pieces; on each piece the distance to
//               the box lies in [d_min, d_max] (d_min: box to the piece's
//               bounding box; d_max: box corners to the piece's ends), the
//               weight polynomial in its interval value, and
//               ∫_piece w K ∈ length · W · [K(d_max), K(d_min)]
//   polygon     a fan of signed triangles from vertex 0 (exact for any simple
//               polygon: ∫_Ω = Σ ± ∫_T), each cut into 4^k pieces, likewise
//   SCALIS      as the segment / triangle, with the radius τ in its interval
//               on each piece: K(d/(στ))/τ (segment), /τ² (triangle), times c/h
//   blends      sum: Σ w_k [lo_k, hi_k]; union: [max lo_k, max hi_k];
//               super-elliptic: its formula in interval arithmetic (it is
//               increasing in each f_k); the θ variant with cos θ ∈ [−1, 1],
//               i.e. a = 1 − cos θ ∈ [min_angle_factor, 2]
//
// An inverse kernel gives hi = +inf when the box touches its skeleton.
// The number of pieces grows as the box shrinks relative to the primitive
// (EnclosureOptions), so the enclosure tightens with the box.
#pragma once

#include <cstddef>
#include <optional>

#include "skelconv/interval/interval.hpp"
#include "skelconv/skeleton/skeleton.hpp"

namespace skelconv::interval {

struct EnclosureOptions {
  /// A segment is cut into ⌈pieces_per_box · length / box diagonal⌉
  /// pieces (at least 1, at most max_segment_pieces): pieces about a box
  /// diagonal long add about as much width as the box itself.
  double pieces_per_box = 2.0;
  std::size_t max_segment_pieces = 256;
  /// A triangle is cut into 4^k pieces, the smallest k whose pieces are at
  /// most a box diagonal across, k ≤ max_triangle_levels (4^4 = 256).
  int max_triangle_levels = 4;
};

/// Enclosure of primitive `primitive` over `box`.
Interval enclose(const Primitive& primitive, const Box& box, const EnclosureOptions& options = {});

/// Enclosure of the whole skeleton's field over `box` (the blend tree).
Interval enclose(const Skeleton& skeleton, const Box& box, const EnclosureOptions& options = {});

/// Enclosure of ∇f of a POINT primitive over `box` (nullopt for the other
/// primitive types: not provided yet). ∇f = w g(r) (P − C) with
/// g(r) = K'(r)/r, which is non-decreasing in r (≤ 0, rising to 0) for
/// every family (docs/bound.md), so g ∈ [g(r_min), g(r_max)]. A box that
/// reaches the centre (r_min = 0) gets (−inf, +inf) components.
std::optional<IntervalPoint> enclose_gradient(const Primitive& primitive, const Box& box);

/// Where a box stands with respect to the surface f = iso.
enum class Classification { inside, outside, undetermined };

/// inside if lo > iso, outside if hi < iso, else undetermined.
Classification classify(const Interval& enclosure, double iso);

const char* classification_name(Classification classification);

}  // namespace skelconv::interval
