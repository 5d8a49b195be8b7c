// src/simd/segment_batch.cpp — skelconv::simd::value_and_gradient for
// segments (include/skelconv/simd/batch.hpp, docs/simd.md).
//
// Per chunk of points: a vector pre-pass sorts the points into those with a
// trivial result (compact kernels: outside the support, f = 0, the test and
// clip of clip_to_ball, operation for operation), those the scalar path must
// see (inverse kernels: P on the segment's line, where the runtime decides
// between +inf and a finite value) and the rest, with their clip interval;
// the rest run through the generated `<name>_f_and_grad` (the function the
// scalar path calls) on Lanes, a group of 4 or 8 points at a time
// (group_runner-inl.hpp); the points whose form is a Miller recurrence
// (beyond an end, near the line) and the other scalar points go to
// Segment::value_and_gradient.
//
// Compiled once per Highway target (foreach_target.h re-includes this file).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/simd/segment_batch.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "generated/segment_cauchy.hpp"
#include "generated/segment_compact.hpp"
#include "generated/segment_inverse.hpp"
#include "skelconv/kernels/kernel_list.hpp"
#include "skelconv/primitives/segment.hpp"
#include "skelconv/simd/batch.hpp"
#include "src/simd/group_runner-inl.hpp"
#include "src/simd/lanes-inl.hpp"
#include "src/simd/scalar_fallback.hpp"
#include "src/simd/segment_kernels.hpp"

HWY_BEFORE_NAMESPACE();
namespace skelconv::simd::HWY_NAMESPACE {
namespace {

/// Points per pre-pass chunk: its arrays stay in L1/L2 while its lanes run.
constexpr std::size_t chunk_size = 1024;

/// One chunk's per-point inputs beyond P: the compact clip interval.
struct ChunkClip {
  double t0[chunk_size];
  double t1[chunk_size];
};

/// f and ∇f at points[0..max_lanes) by the generated Full on Lanes. The
/// kernel template is defined outside this target's region; `flatten`
/// inlines it here, so that it is compiled for this target (lanes-inl.hpp).
template <auto Full>
__attribute__((flatten)) void segment_group(const SegmentInput<double>& segment, PointsSoA points,
                                            const ChunkClip& clip, std::size_t chunk_begin,
                                            const std::uint32_t* lanes, Divergence& divergence, GroupResult& r) {
  const LaneTag d;
  alignas(64) double x[max_lanes], y[max_lanes], z[max_lanes], t0[max_lanes], t1[max_lanes];
  for (std::size_t k = 0; k < max_lanes; ++k) {
    const std::uint32_t p = lanes[k];
    x[k] = points.x[p];
    y[k] = points.y[p];
    z[k] = points.z[p];
    t0[k] = clip.t0[p - chunk_begin];
    t1[k] = clip.t1[p - chunk_begin];
  }
  SegmentInput<Lanes> in;
  for (std::size_t j = 0; j < 3; ++j) {
    in.a[j] = segment.a[j];
    in.b[j] = segment.b[j];
  }
  for (std::size_t j = 0; j < segment.w.size(); ++j) in.w[j] = segment.w[j];
  in.s = segment.s;
  in.R = segment.R;
  in.p = {Lanes(hn::Load(d, x)), Lanes(hn::Load(d, y)), Lanes(hn::Load(d, z))};
  in.t0 = Lanes(hn::Load(d, t0));
  in.t1 = Lanes(hn::Load(d, t1));
  Lanes f;
  std::array<Lanes, 3> g;
  current_divergence = &divergence;
  f = Full(in, g);
  current_divergence = nullptr;
  hn::Store(f.vec(), d, r.f);
  hn::Store(g[0].vec(), d, r.gx);
  hn::Store(g[1].vec(), d, r.gy);
  hn::Store(g[2].vec(), d, r.gz);
}

using GroupFunction = void (*)(const SegmentInput<double>&, PointsSoA, const ChunkClip&, std::size_t,
                               const std::uint32_t*, Divergence&, GroupResult&);

/// The group function of the listed kernel (segment_kernels.hpp), or null.
GroupFunction find_group([[maybe_unused]] KernelFamily family, [[maybe_unused]] int degree,
                         [[maybe_unused]] int weight_degree) {
  // The portable SCALAR target (x86 machines without AVX2) would run the
  // generated code on one-lane vectors: the scalar path's work plus the lane
  // bookkeeping. It hands every point to the scalar path instead, which saves
  // a third of this file's compile time (docs/simd.md).
#if HWY_TARGET == HWY_SCALAR || HWY_TARGET == HWY_EMU128
  return nullptr;
#else
#define SKELCONV_SIMD_ENTRY(FAMILY, I, W)                                                          \
  if (family == KernelFamily::FAMILY && degree == I && weight_degree == W)                        \
    return &segment_group<&generated::segment_##FAMILY##_i##I##_w##W##_f_and_grad<Lanes>>;
  SKELCONV_SIMD_SEGMENT_KERNELS(SKELCONV_SIMD_ENTRY)
#undef SKELCONV_SIMD_ENTRY
  return nullptr;
#endif
}

/// What the pre-pass needs of the kernel (its trait, kernel_list.hpp).
struct KernelNeeds {
  bool singular_on_line;  ///< K(0) = +inf: points on the segment's line go to the scalar path
  bool clipped;           ///< a finite support: the generated form integrates the clipped [t0, t1]
};

/// The pre-pass over points [begin, end): fills `work` with the points for
/// the vector kernel and `scalar` with those for the scalar path, writes
/// f = 0, ∇f = 0 for points outside a finite support, and the clip
/// interval of the others.
void sort_points(const SegmentInput<double>& segment, KernelNeeds needs, PointsSoA points, std::size_t begin,
                 std::size_t end, ChunkClip& clip, FieldSoA out, std::vector<std::uint32_t>& work,
                 std::vector<std::uint32_t>& scalar, BatchCounts& counts) {
  const LaneTag d;
  const std::size_t width = lane_count();
  const auto ab0 = hn::Set(d, segment.b[0] - segment.a[0]), ab1 = hn::Set(d, segment.b[1] - segment.a[1]),
             ab2 = hn::Set(d, segment.b[2] - segment.a[2]);
  const double ab_ab = (segment.b[0] - segment.a[0]) * (segment.b[0] - segment.a[0]) +
                       (segment.b[1] - segment.a[1]) * (segment.b[1] - segment.a[1]) +
                       (segment.b[2] - segment.a[2]) * (segment.b[2] - segment.a[2]);
  const auto a = hn::Set(d, ab_ab), aRR = hn::Set(d, ab_ab * segment.R * segment.R);
  const auto zero = hn::Zero(d), one = hn::Set(d, 1.0);
  alignas(64) double t0[max_lanes], t1[max_lanes];
  for (std::size_t q = begin; q < end; q += width) {
    const std::size_t count = std::min(width, end - q);
    // Past the end: repeat the last point (its lanes are ignored below).
    alignas(64) double x[max_lanes], y[max_lanes], z[max_lanes];
    for (std::size_t k = 0; k < width; ++k) {
      const std::size_t p = q + (k < count ? k : count - 1);
      x[k] = points.x[p];
      y[k] = points.y[p];
      z[k] = points.z[p];
    }
    const auto ap0 = hn::Sub(hn::Load(d, x), hn::Set(d, segment.a[0]));
    const auto ap1 = hn::Sub(hn::Load(d, y), hn::Set(d, segment.a[1]));
    const auto ap2 = hn::Sub(hn::Load(d, z), hn::Set(d, segment.a[2]));
    const auto cx = hn::Sub(hn::Mul(ab1, ap2), hn::Mul(ab2, ap1));
    const auto cy = hn::Sub(hn::Mul(ab2, ap0), hn::Mul(ab0, ap2));
    const auto cz = hn::Sub(hn::Mul(ab0, ap1), hn::Mul(ab1, ap0));
    uint8_t to_scalar_bits[8] = {}, inside_bits[8] = {};
    if (needs.singular_on_line) {
      // P on the line of the segment (AB × AP = 0 exactly): the runtime's
      // own test decides between the singularity and a finite value.
      const auto on_line = hn::And(hn::And(hn::Eq(cx, zero), hn::Eq(cy, zero)), hn::Eq(cz, zero));
      hn::StoreMaskBits(d, on_line, to_scalar_bits);
    }
    if (needs.clipped) {
      // clip_to_ball (include/skelconv/detail/clip.hpp), operation for operation.
      const auto b = hn::Add(hn::Add(hn::Mul(ab0, ap0), hn::Mul(ab1, ap1)), hn::Mul(ab2, ap2));
      const auto disc = hn::Sub(aRR, hn::Add(hn::Add(hn::Mul(cx, cx), hn::Mul(cy, cy)), hn::Mul(cz, cz)));
      const auto half_width = hn::Div(hn::Sqrt(hn::IfThenElse(hn::Gt(disc, zero), disc, zero)), a);
      const auto centre = hn::Div(b, a);
      const auto lo = hn::Sub(centre, half_width), hi = hn::Add(centre, half_width);
      const auto v0 = hn::IfThenElse(hn::Lt(zero, lo), lo, zero);  // std::max(0, lo)
      const auto v1 = hn::IfThenElse(hn::Lt(hi, one), hi, one);    // std::min(1, hi)
      hn::StoreMaskBits(d, hn::And(hn::Gt(disc, zero), hn::Lt(v0, v1)), inside_bits);
      hn::Store(v0, d, t0);
      hn::Store(v1, d, t1);
      // disc within its rounding of 0: clip_to_ball decides on the exact
      // gap there, so the scalar path takes those points.
      const auto near_tangent = hn::Le(disc, hn::Mul(hn::Set(d, 64 * std::numeric_limits<double>::epsilon()), aRR));
      hn::StoreMaskBits(d, near_tangent, to_scalar_bits);
    }
    for (std::size_t k = 0; k < count; ++k) {
      const std::uint32_t p = std::uint32_t(q + k);
      if (needs.clipped) {
        if (!(inside_bits[0] >> k & 1u)) {
          out.f[p] = out.gx[p] = out.gy[p] = out.gz[p] = 0.0;
          ++counts.zero_points;
          continue;
        }
        clip.t0[p - begin] = t0[k];
        clip.t1[p - begin] = t1[k];
      } else {
        clip.t0[p - begin] = 0.0;
        clip.t1[p - begin] = 1.0;
      }
      if (to_scalar_bits[0] >> k & 1u) {
        scalar.push_back(p);
      } else {
        work.push_back(p);
      }
    }
  }
}

}  // namespace

/// Vector part of simd::value_and_gradient: every point gets its result or
/// is appended to `scalar`. False if the kernel has no vector instantiation.
bool segment_batch(const SegmentInput<double>& segment, KernelFamily family, int degree, int weight_degree,
                   PointsSoA points, FieldSoA out, std::vector<std::uint32_t>& scalar, BatchCounts& counts) {
  const GroupFunction group_function = find_group(family, degree, weight_degree);
  if (group_function == nullptr) return false;
  const kernels::FamilyFacts facts = kernels::family_facts(family);
  const KernelNeeds needs{facts.singular_at_zero, facts.finite_support};
  ChunkClip clip;
  std::vector<std::uint32_t> work;
  for (std::size_t begin = 0; begin < points.n; begin += chunk_size) {
    const std::size_t end = std::min(points.n, begin + chunk_size);
    work.clear();
    sort_points(segment, needs, points, begin, end, clip, out, work, scalar, counts);
    auto group = [&](const std::uint32_t* lanes, Divergence& divergence, GroupResult& r) {
      group_function(segment, points, clip, begin, lanes, divergence, r);
    };
    run_lanes(work, group, out, scalar, counts);
  }
  return true;
}

}  // namespace skelconv::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace skelconv::simd {
HWY_EXPORT(segment_batch);

namespace {
SegmentInput<double> segment_input(const Segment& segment) {
  SegmentInput<double> in;
  for (int j = 0; j < 3; ++j) {
    in.a[std::size_t(j)] = segment.a()[j];
    in.b[std::size_t(j)] = segment.b()[j];
  }
  in.w = {0.0, 0.0, 0.0, 0.0};
  for (std::size_t k = 0; k < segment.weight().size(); ++k) in.w[k] = segment.weight()[k];
  in.s = segment.kernel().s;
  in.R = segment.kernel().R;
  return in;
}
}  // namespace

BatchCounts value_and_gradient(const Segment& segment, PointsSoA points, FieldSoA out) {
  BatchCounts counts;
  std::vector<std::uint32_t> scalar;
  const bool vectorised =
      HWY_DYNAMIC_DISPATCH(segment_batch)(segment_input(segment), segment.kernel().family, segment.kernel().degree,
                                          segment.weight_degree(), points, out, scalar, counts);
  detail::finish_on_scalar_path(segment, vectorised, scalar, points, out, counts);
  return counts;
}

bool has_vector_kernel(const Segment& segment) {
  const KernelFamily family = segment.kernel().family;
  const int degree = segment.kernel().degree, weight_degree = segment.weight_degree();
#define SKELCONV_SIMD_ENTRY(FAMILY, I, W) \
  if (family == KernelFamily::FAMILY && degree == I && weight_degree == W) return true;
  SKELCONV_SIMD_SEGMENT_KERNELS(SKELCONV_SIMD_ENTRY)
#undef SKELCONV_SIMD_ENTRY
  return false;
}

}  // namespace skelconv::simd
#endif  // HWY_ONCE
