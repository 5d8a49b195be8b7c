// bench/batch_eval.hpp — a batch API: one segment, many query points in
// structure-of-arrays layout, f and ∇f for all of them.
// Proposed here, in bench/, until the runtime adopts it.
//
// How it vectorises: the loop body is the generated scalar function itself,
// instantiated on double and inlined (the kernel is a template argument, not
// a pointer, and the batch function is `flatten`ed: the kernels are too big
// for GCC's inlining heuristics). GCC's loop vectoriser then turns a
// straight-line kernel into 4-wide AVX2 code, given the bench flags
// (bench/CMakeLists.txt):
//   * sqrt and division vectorise when errno is off (-fno-math-errno);
//   * atan2, log and asinh go to glibc's vector math library (libmvec) once
//     they are declared `simd` (below; glibc itself only does so under
//     -ffast-math, which we do not want for these cancellation-sensitive
//     forms);
//   * an `if` between two straight-line forms, std::max and `c ? a : b`
//     become blends, provided the arms may be executed speculatively
//     (-fno-trapping-math);
//   * the per-lane SegmentInput is rebuilt field by field from locals
//     (detail::Uniforms): an aggregate copy, or a load from `segment` after a
//     store to the outputs (possible aliasing), stops the vectoriser.
//   * the loop body must be straight-line: a loop inside it with a
//     data-dependent trip count (J_downward / J_upward_compact of
//     include/skelconv/stable_recurrence.hpp, on the "P beyond an end, near
//     the line" forms) keeps the whole loop scalar. Hence two passes: the
//     vectorised loop runs every lane through the generated
//     `<name>_f_and_grad_generic` (every form without a loop of run-time
//     length; the fixed Gauss–Legendre rules (7–20 nodes) are loops GCC
//     unrolls completely given the --param limits of bench/CMakeLists.txt)
//     and records the lanes where it returned false; a
//     scalar loop then re-evaluates only those with the full
//     `<name>_f_and_grad` (the Miller-recurrence forms beyond an end),
//     called out of line. Results are those of the scalar path (the batch
//     benchmark checks them: 1e-13 relative per point, see batch_bench.cpp).
//   * a flag array of bool or integers next to the kernel's bool result gives
//     GCC 12 "no vectype for stmt"; the flags are doubles.
// Preconditions (as for the generated scalar code): points are not on an
// inverse-kernel segment. The compact path clips branch-free: every lane
// computes its clip interval with min/max, the lanes whose clip is empty are
// evaluated on a harmless interval and their result is selected to 0.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "skelconv/clip.hpp"
#include "skelconv/segment_input.hpp"
#include "skelconv/simd/batch.hpp"

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__FAST_MATH__) && \
    !defined(SKELCONV_BATCH_NO_LIBMVEC)
// libmvec (glibc ≥ 2.35 for atan2/asinh) has 2-, 4- and 8-wide variants of
// these; declaring them `simd` lets the vectoriser call them. Link -lmvec.
extern "C" {
__attribute__((__simd__("notinbranch"))) double atan2(double, double) noexcept;
__attribute__((__simd__("notinbranch"))) double log(double) noexcept;
__attribute__((__simd__("notinbranch"))) double asinh(double) noexcept;
}
#endif

// The generated kernels are too large for GCC's inlining heuristics; flatten
// inlines them (and everything they call) into the batch loop, which the
// vectoriser needs: a call in the loop body stops it.
#if defined(__GNUC__)
#define SKELCONV_BATCH_FLATTEN __attribute__((flatten))
#else
#define SKELCONV_BATCH_FLATTEN
#endif

namespace skelconv::bench {

/// Query points and outputs, structure of arrays: the library's batch types
/// (skelconv/simd/batch.hpp), so that a benchmark feeds both paths the same.
using simd::FieldSoA;
using simd::PointsSoA;

namespace detail {
/// The per-segment fields of a SegmentInput as scalars. The loops rebuild
/// each lane's SegmentInput field by field from these locals: copying
/// `segment` inside the loop would reload it after every store to the
/// outputs (they may alias it, as far as the compiler knows), and under
/// `#pragma omp simd` the aggregate copy itself is rejected ("more than one
/// data ref in stmt").
struct Uniforms {
  double a0, a1, a2, b0, b1, b2, w0, w1, w2, w3, s, R;
  explicit Uniforms(const SegmentInput<double>& in)
      : a0(in.a[0]), a1(in.a[1]), a2(in.a[2]), b0(in.b[0]), b1(in.b[1]), b2(in.b[2]),
        w0(in.w[0]), w1(in.w[1]), w2(in.w[2]), w3(in.w[3]), s(in.s), R(in.R) {}
  void fill(SegmentInput<double>& in) const {
    in.a = {a0, a1, a2};
    in.b = {b0, b1, b2};
    in.w = {w0, w1, w2, w3};
    in.s = s;
    in.R = R;
  }
};
}  // namespace detail

/// The scalar fix-up: the full generated function (stable forms included)
/// for one lane, kept out of line so that `flatten` does not paste the
/// stable forms' loops next to the vectorised loop.
template <auto Full>
[[gnu::noinline]] void full_lane(const SegmentInput<double>& in, double& f, double& gx, double& gy, double& gz) {
  std::array<double, 3> g;
  f = Full(in, g);
  gx = g[0];
  gy = g[1];
  gz = g[2];
}

/// Points per chunk: the vectorised pass over a chunk records which lanes
/// need the full function in a small array on the stack, then the scalar
/// pass re-evaluates those (while the chunk is still in L1).
inline constexpr std::size_t batch_chunk = 256;

/// f and ∇f at every point for an inverse or Cauchy kernel. `segment` holds
/// A, B, the weight and s; its p is ignored. Generic: a generated
/// `<name>_f_and_grad_generic` on double (straight-line, evaluated for every
/// lane in the vectorised loop); Full: the matching `<name>_f_and_grad`, called
/// only for the lanes where Generic returned false. Returns how many lanes
/// needed Full. E.g.
///     f_and_grad_batch<&generated::segment_cauchy_i4_w1_f_and_grad_generic<double>,
///                      &generated::segment_cauchy_i4_w1_f_and_grad<double>>(in, pts, out);
template <auto Generic, auto Full>
SKELCONV_BATCH_FLATTEN std::size_t f_and_grad_batch(const SegmentInput<double>& segment, PointsSoA points,
                                                    FieldSoA out) {
  const double *x = points.x, *y = points.y, *z = points.z;
  double *f = out.f, *gx = out.gx, *gy = out.gy, *gz = out.gz;
  const detail::Uniforms u(segment);
  std::size_t fallbacks = 0;
  for (std::size_t begin = 0; begin < points.n; begin += batch_chunk) {
    const std::size_t end = std::min(points.n, begin + batch_chunk);
    // 1 where the lane needs the full function. A double, like the data: a
    // bool or integer flag mixed with the kernel's bool result gives GCC 12
    // "no vectype for stmt" and the loop stays scalar.
    double need[batch_chunk];
#pragma GCC ivdep
    for (std::size_t k = begin; k < end; ++k) {
      SegmentInput<double> in;
      u.fill(in);
      in.p = {x[k], y[k], z[k]};
      std::array<double, 3> g;
      double value;
      const bool ok = Generic(in, value, g);
      f[k] = value;
      gx[k] = g[0];
      gy[k] = g[1];
      gz[k] = g[2];
      need[k - begin] = ok ? 0.0 : 1.0;
    }
    for (std::size_t k = begin; k < end; ++k) {
      if (!need[k - begin]) continue;
      SegmentInput<double> in;
      u.fill(in);
      in.p = {x[k], y[k], z[k]};
      full_lane<Full>(in, f[k], gx[k], gy[k], gz[k]);
      ++fallbacks;
    }
  }
  return fallbacks;
}

/// The same for a compact kernel, clip included and branch-free: the clip of
/// skelconv::clip_to_ball (include/skelconv/clip.hpp) with its early returns
/// replaced by min/max and one final select. Lanes outside the support get
/// 0 and never need Full.
template <auto Generic, auto Full>
SKELCONV_BATCH_FLATTEN std::size_t compact_f_and_grad_batch(const SegmentInput<double>& segment, PointsSoA points,
                                                            FieldSoA out) {
  const double *x = points.x, *y = points.y, *z = points.z;
  double *f = out.f, *gx = out.gx, *gy = out.gy, *gz = out.gz;
  // Locals only: out may alias `segment` as far as the compiler knows, and a
  // load of it after a store in the loop would stop the vectoriser.
  const detail::Uniforms u(segment);
  const double ab0 = u.b0 - u.a0, ab1 = u.b1 - u.a1, ab2 = u.b2 - u.a2;
  const double a = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  const double R = u.R;
  std::size_t fallbacks = 0;
  for (std::size_t begin = 0; begin < points.n; begin += batch_chunk) {
    const std::size_t end = std::min(points.n, begin + batch_chunk);
    double need[batch_chunk];  // as above
#pragma GCC ivdep
    for (std::size_t k = begin; k < end; ++k) {
      const double ap0 = x[k] - u.a0, ap1 = y[k] - u.a1, ap2 = z[k] - u.a2;
      const double b = ab0 * ap0 + ab1 * ap1 + ab2 * ap2;
      const double cx = ab1 * ap2 - ab2 * ap1, cy = ab2 * ap0 - ab0 * ap2, cz = ab0 * ap1 - ab1 * ap0;
      // The arithmetic of clip_to_ball, operation for operation (a clip that
      // differs by an ulp changes f by ~1e-12 relative where the interval is
      // short, at the edge of the support).
      const double disc = a * R * R - (cx * cx + cy * cy + cz * cz);
      const double half_width = std::sqrt(std::max(disc, 0.0)) / a;
      const double centre = b / a;
      const double t0 = std::max(0.0, centre - half_width);
      const double t1 = std::min(1.0, centre + half_width);
      const bool inside = (disc > 0.0) & (t0 < t1);
      // Outside: a valid, empty-ish interval whose value is discarded below.
      const double safe_t0 = inside ? t0 : 0.0;
      const double safe_t1 = inside ? t1 : 0.5;
      SegmentInput<double> in;
      u.fill(in);
      in.p = {x[k], y[k], z[k]};
      in.t0 = safe_t0;
      in.t1 = safe_t1;
      std::array<double, 3> g;
      double value;
      const bool ok = Generic(in, value, g);
      f[k] = inside ? value : 0.0;
      gx[k] = inside ? g[0] : 0.0;
      gy[k] = inside ? g[1] : 0.0;
      gz[k] = inside ? g[2] : 0.0;
      need[k - begin] = ok ? 0.0 : (inside ? 1.0 : 0.0);
    }
    for (std::size_t k = begin; k < end; ++k) {
      if (!need[k - begin]) continue;
      SegmentInput<double> in;
      u.fill(in);
      in.p = {x[k], y[k], z[k]};
      // The scalar path's clip (inside the support: never empty here).
      const auto clip = clip_to_ball(in.a, in.b, in.p, in.R);
      in.t0 = clip ? clip->t0 : 0.0;
      in.t1 = clip ? clip->t1 : 0.0;
      full_lane<Full>(in, f[k], gx[k], gy[k], gz[k]);
      ++fallbacks;
    }
  }
  return fallbacks;
}

}  // namespace skelconv::bench
