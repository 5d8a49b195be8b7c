// verify/sweep.cpp — see sweep.hpp.
#include "sweep.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>

#include "generated_kernels.hpp"
#include "point_evaluation.hpp"
#include "progress.hpp"
#include "sampling.hpp"

namespace skelconv::verify {

std::vector<std::pair<KernelFamily, int>> generated_family_degrees() {
  std::vector<std::pair<KernelFamily, int>> out;
  for (const auto& kernel : generated_kernels_double()) {
    const std::pair key{kernel.family, kernel.degree};
    if (std::find(out.begin(), out.end(), key) == out.end()) out.push_back(key);
  }
  return out;
}

std::vector<WorkItem> build_work_list(const SweepOptions& options) {
  std::vector<WorkItem> items;
  const std::uint64_t chunk = static_cast<std::uint64_t>(std::max(1, options.chunk_size));
  for (const auto& [family, degree] : generated_family_degrees()) {
    if (options.family && *options.family != family) continue;
    if (options.degree && *options.degree != degree) continue;
    for (Region region : all_regions) {
      if (!region_applies(region, family)) continue;
      if (options.region && *options.region != region) continue;
      const std::uint64_t total = static_cast<std::uint64_t>(options.counts.for_region(region));
      for (std::uint64_t first = 0; first < total; first += chunk)
        items.push_back({family, degree, region, first, std::min(chunk, total - first)});
    }
  }
  return items;
}

namespace {

/// 1, or 1 + relative for the family of a test perturbation.
double result_scale(const SweepOptions& options, KernelFamily family) {
  return options.perturbation && options.perturbation->family == family ? 1 + options.perturbation->relative : 1.0;
}

}  // namespace

SweepResult run_sweep(const SweepOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  SweepResult result;
  const std::vector<WorkItem> all_items = build_work_list(options);
  result.items_total = all_items.size();
  std::vector<WorkItem> items;
  for (std::size_t i = 0; i < all_items.size(); ++i)
    if (static_cast<int>(i % static_cast<std::size_t>(options.shard_count)) == options.shard_index)
      items.push_back(all_items[i]);
  result.items_run = items.size();
  std::uint64_t total_samples = 0;
  for (const auto& item : items) total_samples += item.count;
  result.samples = total_samples;

  ProgressReporter progress(options.progress, total_samples, items.size());
  std::atomic<std::size_t> next{0};
  std::mutex merge_mutex;
  std::atomic<std::uint64_t> evaluations{0};

  const auto worker = [&] {
    ReferenceIntegrators integrators(options.reference);
    for (std::size_t i = next++; i < items.size(); i = next++) {
      const WorkItem& item = items[i];
      const KernelsByWeightDegree kernels = find_kernels(item.family, item.degree);
      std::array<CellStats, max_weight_degree + 1> cells{};
      for (std::uint64_t k = item.first; k < item.first + item.count; ++k) {
        const SweepProblem pb = draw_problem(options.seed, item.family, item.degree, item.region, k);
        evaluate_sample(pb, kernels, integrators, options.targets, cells, result_scale(options, item.family));
      }
      {
        std::lock_guard lock(merge_mutex);
        for (int d = 0; d <= max_weight_degree; ++d) {
          if (!kernels[d].in_double || !kernels[d].in_extended) continue;
          result.cells[{item.family, item.degree, d, item.region}].merge(cells[d]);
        }
      }
      progress.item_done(item.count);
    }
    evaluations += integrators.standard.kernel_evaluations() + integrators.stronger.kernel_evaluations();
  };
  const int thread_count = std::max(1, options.threads);
  std::vector<std::thread> threads;
  for (int t = 1; t < thread_count; ++t) threads.emplace_back(worker);
  worker();
  for (auto& thread : threads) thread.join();
  progress.finish();

  result.kernel_evaluations = evaluations;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace skelconv::verify
