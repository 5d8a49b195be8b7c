// bench/batch_kernels.hpp — the kernels the batch benchmarks instantiate
// (shared by batch_bench.cpp and instruction_counts.cpp): Zanni et al. 2013 Table 4's
// classical rows, the compact family, and inverse i3 w2, whose generated
// code has a run-time branch between two forms.
#pragma once

#include "batch_eval.hpp"
#include "bench_support.hpp"
#include "generated/segment_cauchy.hpp"
#include "generated/segment_compact.hpp"
#include "generated/segment_inverse.hpp"

namespace skelconv::bench {

/// Evaluates a batch; returns how many lanes needed the full (scalar) function.
using BatchFunction = std::size_t (*)(const Input&, PointsSoA, FieldSoA);

struct BatchEntry {
  KernelKey key;
  BatchFunction batch;
};

#define SKELCONV_BATCH(name) \
  &generated::name##_f_and_grad_generic<double>, &generated::name##_f_and_grad<double>
inline const BatchEntry batch_entries[] = {
    {{KernelFamily::inverse, 3, 1}, &f_and_grad_batch<SKELCONV_BATCH(segment_inverse_i3_w1)>},
    {{KernelFamily::inverse, 3, 2}, &f_and_grad_batch<SKELCONV_BATCH(segment_inverse_i3_w2)>},
    {{KernelFamily::cauchy, 4, 1}, &f_and_grad_batch<SKELCONV_BATCH(segment_cauchy_i4_w1)>},
    {{KernelFamily::cauchy, 4, 3}, &f_and_grad_batch<SKELCONV_BATCH(segment_cauchy_i4_w3)>},
    {{KernelFamily::compact, 4, 0}, &compact_f_and_grad_batch<SKELCONV_BATCH(segment_compact_i4_w0)>},
    {{KernelFamily::compact, 6, 0}, &compact_f_and_grad_batch<SKELCONV_BATCH(segment_compact_i6_w0)>},
    {{KernelFamily::compact, 3, 0}, &compact_f_and_grad_batch<SKELCONV_BATCH(segment_compact_i3_w0)>},
};
#undef SKELCONV_BATCH

/// Query points in SoA layout with room for the outputs.
struct Batch {
  std::vector<double> x, y, z, f, gx, gy, gz;
  explicit Batch(std::size_t n) : x(n), y(n), z(n), f(n), gx(n), gy(n), gz(n) {
    const std::vector<Vec> points = make_box_points(n);
    for (std::size_t k = 0; k < n; ++k) {
      x[k] = points[k][0];
      y[k] = points[k][1];
      z[k] = points[k][2];
    }
  }
  PointsSoA points() const { return {x.data(), y.data(), z.data(), x.size()}; }
  FieldSoA field() { return {f.data(), gx.data(), gy.data(), gz.data()}; }
};

/// The scalar loop: per point, fill a SegmentInput and call through the
/// table's function pointer (what the runtime does); compact kernels clip
/// with skelconv::clip_to_ball and skip the call when the clip is empty.
inline void scalar_loop(const KernelRef& k, const Input& segment, PointsSoA p, FieldSoA out) {
  for (std::size_t j = 0; j < p.n; ++j) {
    Input in = segment;
    in.p = {p.x[j], p.y[j], p.z[j]};
    Vec g{0, 0, 0};
    double f = 0;
    if (kernels::has_finite_support(k.family)) {
      const auto clip = clip_to_ball(in.a, in.b, in.p, in.R);
      if (clip) {
        in.t0 = clip->t0;
        in.t1 = clip->t1;
        f = k.f_and_grad(in, g);
      }
    } else {
      f = k.f_and_grad(in, g);
    }
    out.f[j] = f;
    out.gx[j] = g[0];
    out.gy[j] = g[1];
    out.gz[j] = g[2];
  }
}

}  // namespace skelconv::bench
