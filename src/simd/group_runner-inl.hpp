// src/simd/group_runner-inl.hpp — runs a list of lanes through a vector
// group function, re-running the lanes a group set aside (divergence.hpp)
// with lanes of the same key until every lane has a result or has been
// handed to the scalar path. Per-target header (see lanes-inl.hpp).
#if defined(SKELCONV_SIMD_GROUP_RUNNER_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SKELCONV_SIMD_GROUP_RUNNER_INL_H_
#undef SKELCONV_SIMD_GROUP_RUNNER_INL_H_
#else
#define SKELCONV_SIMD_GROUP_RUNNER_INL_H_
#endif

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "skelconv/simd/batch.hpp"
#include "src/simd/divergence.hpp"
#include "src/simd/lanes-inl.hpp"

HWY_BEFORE_NAMESPACE();
namespace skelconv::simd::HWY_NAMESPACE {

/// The results of one group, lane k in slot k.
struct GroupResult {
  alignas(64) double f[max_lanes];
  alignas(64) double gx[max_lanes];
  alignas(64) double gy[max_lanes];
  alignas(64) double gz[max_lanes];
};

/// Lanes set aside, by key (few keys: one per path through the kernel's
/// branches that some lane took).
class SetAside {
 public:
  void add(std::uint64_t key, std::uint32_t point) {
    for (auto& [k, points] : buckets_) {
      if (k == key) {
        points.push_back(point);
        return;
      }
    }
    buckets_.push_back({key, {point}});
  }
  bool empty() const { return buckets_.empty(); }
  /// Removes and returns one bucket's points.
  std::vector<std::uint32_t> take() {
    std::vector<std::uint32_t> points = std::move(buckets_.back().second);
    buckets_.pop_back();
    return points;
  }

 private:
  std::vector<std::pair<std::uint64_t, std::vector<std::uint32_t>>> buckets_;
};

/// Evaluates the points `work` (indices into `out`) with `group`, a callable
/// void(const std::uint32_t* points, Divergence&, GroupResult&) that
/// evaluates lane k at points[k] (all max_lanes slots are filled: a short
/// group repeats its first point). Lanes the kernel handed to the scalar
/// path, or whose results are not all finite, are appended to `scalar` (the
/// scalar path then computes them, or throws its error).
template <class Group>
void run_lanes(std::vector<std::uint32_t> work, Group& group, FieldSoA out, std::vector<std::uint32_t>& scalar,
               BatchCounts& counts) {
  const std::size_t width = lane_count();
  SetAside set_aside;
  for (;;) {
    for (std::size_t begin = 0; begin < work.size(); begin += width) {
      const std::size_t count = std::min(width, work.size() - begin);
      std::uint32_t points[max_lanes];
      for (std::size_t k = 0; k < max_lanes; ++k) points[k] = work[begin + (k < count ? k : 0)];
      Divergence divergence(count);
      GroupResult r;
      group(points, divergence, r);
      ++counts.group_runs;
      for (std::size_t k = 0; k < count; ++k) {
        const std::uint32_t p = points[k];
        if (divergence.to_scalar() >> k & 1u) {
          scalar.push_back(p);
        } else if (!(divergence.active() >> k & 1u)) {
          set_aside.add(divergence.set_aside_key(k), p);
          ++counts.set_aside;
        } else if (std::isfinite(r.f[k]) && std::isfinite(r.gx[k]) && std::isfinite(r.gy[k]) &&
                   std::isfinite(r.gz[k])) {
          out.f[p] = r.f[k];
          out.gx[p] = r.gx[k];
          out.gy[p] = r.gy[k];
          out.gz[p] = r.gz[k];
        } else {
          scalar.push_back(p);
        }
      }
    }
    if (set_aside.empty()) return;
    work = set_aside.take();
  }
}

}  // namespace skelconv::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // SKELCONV_SIMD_GROUP_RUNNER_INL_H_
