// src/simd/scalis_batch.cpp — skelconv::simd::value_and_gradient for SCALIS
// segments (include/skelconv/simd/batch.hpp, docs/simd.md).
//
// A scalar pre-pass sends the points where the runtime may return +inf
// (ScalisSegment::is_divergent_point: for inverse kernels P on the
// segment's line, AB × AP = 0 exactly; for Cauchy kernels P at an end of
// radius 0) to the scalar path; the others run through the generated
// `scalis_segment_<family>_i<i>_f_and_grad` (the function the scalar path
// calls) on Lanes, in groups (group_runner-inl.hpp), and are scaled by
// iso / normalisation as ScalisSegment::value_and_gradient does.
//
// Compiled once per Highway target (foreach_target.h re-includes this file).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/simd/scalis_batch.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "generated/scalis_segment_cauchy.hpp"
#include "generated/scalis_segment_inverse.hpp"
#include "skelconv/kernels/kernel_list.hpp"
#include "skelconv/primitives/scalis_segment.hpp"
#include "skelconv/simd/batch.hpp"
#include "src/simd/group_runner-inl.hpp"
#include "src/simd/lanes-inl.hpp"
#include "src/simd/scalar_fallback.hpp"
#include "src/simd/scalis_kernels.hpp"

HWY_BEFORE_NAMESPACE();
namespace skelconv::simd::HWY_NAMESPACE {
namespace {

/// What the group function needs besides the points.
struct ScalisUniforms {
  ScalisSegmentInput<double> input;  ///< a, b, τ0, τ1, σ (p unused)
  double iso, normalisation;         ///< f = iso F / normalisation
};

/// iso F / normalisation and iso ∇F / normalisation at points[0..max_lanes)
/// by the generated Full on Lanes (`flatten`: compiled for this target).
template <auto Full>
__attribute__((flatten)) void scalis_group(const ScalisUniforms& u, PointsSoA points, const std::uint32_t* lanes,
                                           Divergence& divergence, GroupResult& r) {
  const LaneTag d;
  alignas(64) double x[max_lanes], y[max_lanes], z[max_lanes];
  for (std::size_t k = 0; k < max_lanes; ++k) {
    x[k] = points.x[lanes[k]];
    y[k] = points.y[lanes[k]];
    z[k] = points.z[lanes[k]];
  }
  ScalisSegmentInput<Lanes> in;
  for (std::size_t j = 0; j < 3; ++j) {
    in.a[j] = u.input.a[j];
    in.b[j] = u.input.b[j];
  }
  in.tau0 = u.input.tau0;
  in.tau1 = u.input.tau1;
  in.sigma = u.input.sigma;
  in.p = {Lanes(hn::Load(d, x)), Lanes(hn::Load(d, y)), Lanes(hn::Load(d, z))};
  std::array<Lanes, 3> g;
  current_divergence = &divergence;
  const Lanes F = Full(in, g);
  current_divergence = nullptr;
  // The runtime's order: (iso × value) / normalisation.
  const Lanes iso(u.iso), normalisation(u.normalisation);
  hn::Store((iso * F / normalisation).vec(), d, r.f);
  hn::Store((iso * g[0] / normalisation).vec(), d, r.gx);
  hn::Store((iso * g[1] / normalisation).vec(), d, r.gy);
  hn::Store((iso * g[2] / normalisation).vec(), d, r.gz);
}

using GroupFunction = void (*)(const ScalisUniforms&, PointsSoA, const std::uint32_t*, Divergence&, GroupResult&);

GroupFunction find_group([[maybe_unused]] KernelFamily family, [[maybe_unused]] int degree) {
  // The portable SCALAR target (x86 machines without AVX2) would run the
  // generated code on one-lane vectors: the scalar path's work plus the lane
  // bookkeeping. It hands every point to the scalar path instead, which saves
  // a third of this file's compile time (docs/simd.md).
#if HWY_TARGET == HWY_SCALAR || HWY_TARGET == HWY_EMU128
  return nullptr;
#else
#define SKELCONV_SIMD_ENTRY(FAMILY, I) \
  if (family == KernelFamily::FAMILY && degree == I)  \
    return &scalis_group<&generated::scalis_segment_##FAMILY##_i##I##_f_and_grad<Lanes>>;
  SKELCONV_SIMD_SCALIS_KERNELS(SKELCONV_SIMD_ENTRY)
#undef SKELCONV_SIMD_ENTRY
  return nullptr;
#endif
}

/// P where ScalisSegment may return +inf: left to the scalar path.
/// (`on_segment`: the kernel's scalis_singularity is on the segment itself,
/// else at an end of radius 0, as ScalisSegment::is_divergent_point.)
bool maybe_divergent(const ScalisSegmentInput<double>& in, bool on_segment, double x, double y, double z) {
  const double ab[3] = {in.b[0] - in.a[0], in.b[1] - in.a[1], in.b[2] - in.a[2]};
  const double ap[3] = {x - in.a[0], y - in.a[1], z - in.a[2]};
  if (on_segment) {
    return ab[1] * ap[2] - ab[2] * ap[1] == 0.0 && ab[2] * ap[0] - ab[0] * ap[2] == 0.0 &&
           ab[0] * ap[1] - ab[1] * ap[0] == 0.0;
  }
  const bool at_a = x == in.a[0] && y == in.a[1] && z == in.a[2];
  const bool at_b = x == in.b[0] && y == in.b[1] && z == in.b[2];
  return (in.tau0 == 0.0 && at_a) || (in.tau1 == 0.0 && at_b);
}

}  // namespace

/// Vector part of simd::value_and_gradient for SCALIS segments; false if the
/// kernel has no vector instantiation.
bool scalis_batch(const ScalisSegmentInput<double>& input, KernelFamily family, int degree, double iso,
                  double normalisation, PointsSoA points, FieldSoA out, std::vector<std::uint32_t>& scalar,
                  BatchCounts& counts) {
  const GroupFunction group_function = find_group(family, degree);
  if (group_function == nullptr) return false;
  const ScalisUniforms u{input, iso, normalisation};
  const bool on_segment = kernels::family_facts(family).scalis_singularity == kernels::ScalisSingularity::on_segment;
  std::vector<std::uint32_t> work;
  work.reserve(points.n);
  for (std::size_t p = 0; p < points.n; ++p) {
    if (maybe_divergent(input, on_segment, points.x[p], points.y[p], points.z[p])) {
      scalar.push_back(std::uint32_t(p));
    } else {
      work.push_back(std::uint32_t(p));
    }
  }
  auto group = [&](const std::uint32_t* lanes, Divergence& divergence, GroupResult& r) {
    group_function(u, points, lanes, divergence, r);
  };
  run_lanes(std::move(work), group, out, scalar, counts);
  return true;
}

}  // namespace skelconv::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace skelconv::simd {
HWY_EXPORT(scalis_batch);

BatchCounts value_and_gradient(const ScalisSegment& segment, PointsSoA points, FieldSoA out) {
  BatchCounts counts;
  std::vector<std::uint32_t> scalar;
  ScalisSegmentInput<double> input;
  for (int j = 0; j < 3; ++j) {
    input.a[std::size_t(j)] = segment.a()[j];
    input.b[std::size_t(j)] = segment.b()[j];
  }
  input.tau0 = segment.tau0();
  input.tau1 = segment.tau1();
  input.sigma = segment.kernel().sigma;
  const bool vectorised = HWY_DYNAMIC_DISPATCH(scalis_batch)(input, segment.kernel().family, segment.kernel().degree,
                                                             segment.iso(), segment.normalisation(), points, out,
                                                             scalar, counts);
  detail::finish_on_scalar_path(segment, vectorised, scalar, points, out, counts);
  return counts;
}

bool has_vector_kernel(const ScalisSegment& segment) {
  const KernelFamily family = segment.kernel().family;
  const int degree = segment.kernel().degree;
#define SKELCONV_SIMD_ENTRY(FAMILY, I) \
  if (family == KernelFamily::FAMILY && degree == I) return true;
  SKELCONV_SIMD_SCALIS_KERNELS(SKELCONV_SIMD_ENTRY)
#undef SKELCONV_SIMD_ENTRY
  return false;
}

}  // namespace skelconv::simd
#endif  // HWY_ONCE
