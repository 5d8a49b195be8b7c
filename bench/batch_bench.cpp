// bench/batch_bench.cpp — the batch (structure-of-arrays) API of
// bench/batch_eval.hpp against the scalar loop (issue 5, §2 fourth bullet).
//   batch/<kernel>/scalar   one call per point through the generated table's
//                           function pointer (what the runtime does today);
//                           compact: skelconv::clip_to_ball with its branches,
//                           and no call when the clip is empty;
//   batch/<kernel>/simd     bench::f_and_grad_batch / compact_f_and_grad_batch:
//                           the same generated function inlined in a
//                           loop GCC vectorises (AVX2), branch-free clip.
// Points: uniform in the segment's box grown by 1.5 R (about a third outside
// the compact support). Both variants write the same SoA outputs; counter
// max_rel_diff compares them.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "batch_kernels.hpp"

namespace skelconv::bench {
namespace {

std::size_t batch_size = 4096;

/// Largest |batch − scalar| relative to the largest |scalar| value, over f
/// and the gradient components.
double compare(const KernelRef& k, BatchFunction batch) {
  Batch a(batch_size), b(batch_size);
  const Input segment = segment_input(k.family);
  scalar_loop(k, segment, a.points(), a.field());
  batch(segment, b.points(), b.field());
  double scale = 0, diff = 0;
  for (auto pair : {&Batch::f, &Batch::gx, &Batch::gy, &Batch::gz}) {
    for (std::size_t j = 0; j < batch_size; ++j) {
      scale = std::max(scale, std::abs((a.*pair)[j]));
      diff = std::max(diff, std::abs((a.*pair)[j] - (b.*pair)[j]));
    }
  }
  return diff / scale;
}

void bench_scalar(benchmark::State& state, const KernelRef* k) {
  Batch batch(batch_size);
  const Input segment = segment_input(k->family);
  for (auto _ : state) {
    scalar_loop(*k, segment, batch.points(), batch.field());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(batch_size));
}

void bench_simd(benchmark::State& state, const KernelRef* k, BatchFunction function) {
  const double max_rel_diff = compare(*k, function);
  Batch batch(batch_size);
  const Input segment = segment_input(k->family);
  for (auto _ : state) {
    function(segment, batch.points(), batch.field());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(batch_size));
  state.counters["max_rel_diff"] = max_rel_diff;
}

void register_all() {
  for (const BatchEntry& e : batch_entries) {
    const KernelRef* k = find_kernel(e.key.family, e.key.degree, e.key.weight_degree);
    if (!k) continue;
    benchmark::RegisterBenchmark(("batch/" + k->name + "/scalar").c_str(), bench_scalar, k);
    benchmark::RegisterBenchmark(("batch/" + k->name + "/simd").c_str(), bench_simd, k, e.batch);
  }
}

}  // namespace
}  // namespace skelconv::bench

int main(int argc, char** argv) {
  // --smoke (CTest): tiny batches.
  int kept = 1;
  for (int j = 1; j < argc; ++j) {
    if (std::strcmp(argv[j], "--smoke") == 0) {
      skelconv::bench::batch_size = 64;
    } else {
      argv[kept++] = argv[j];
    }
  }
  argc = kept;
  skelconv::bench::register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
