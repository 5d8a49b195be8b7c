// verify/sweep.hpp — the accuracy sweep: a deterministic work list of
// (family, degree, region, chunk) items, split into shards and run on threads.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "build_info.hpp"
#include "error_stats.hpp"
#include "reference_quadrature.hpp"
#include "regions.hpp"
#include "skelconv/primitives/segment_input.hpp"

namespace skelconv::verify {

/// Test only: every generated result (f and ∇f, double and binary128) of one
/// family is multiplied by (1 + relative), as if one term of its formula had
/// changed. `skelconv-verify compare` must catch it (ctest
/// verify_compare_catches_perturbation); never set in a real sweep.
struct TestPerturbation {
  KernelFamily family = KernelFamily::inverse;
  double relative = 0;
};

struct SweepOptions {
  PointCounts counts = default_point_counts;
  std::uint64_t seed = 20240601;
  int shard_index = 0;  ///< this process runs the items with index % shard_count == shard_index
  int shard_count = 1;
  int threads = 2;
  std::optional<KernelFamily> family;  ///< filters (a filtered run keeps the same samples)
  std::optional<int> degree;
  std::optional<Region> region;
  int chunk_size = 100;  ///< points per work item
  bool progress = true;  ///< progress line on stderr
  AccuracyTargets targets;
  ExclusionLimits exclusions;
  ReferenceTolerances reference;
  std::optional<TestPerturbation> perturbation;
  /// The commit the generated kernels and the verifier were built from; a
  /// report read back keeps the commit it was written with.
  std::string commit = std::string(build_commit());
};

/// One unit of work: points [first, first + count) of (family, degree, region).
struct WorkItem {
  KernelFamily family;
  int degree;
  Region region;
  std::uint64_t first;
  std::uint64_t count;
};

/// (family, degree, weight degree, region) → statistics.
using CellKey = std::tuple<KernelFamily, int, int, Region>;
using SweepCells = std::map<CellKey, CellStats>;

struct SweepResult {
  SweepCells cells;
  std::size_t items_total = 0;  ///< items of the whole (unsharded, filtered) list
  std::size_t items_run = 0;    ///< items of this shard
  std::uint64_t samples = 0;    ///< samples drawn by this shard
  double seconds = 0;
  std::uint64_t kernel_evaluations = 0;  ///< reference kernel evaluations (cost indicator)
  int merged_shards = 0;                 ///< shard reports merged into this one (0: a single run)
};

/// The (family, degree) pairs the generated table provides (weight degree 0..3
/// looked up per pair), in table order.
std::vector<std::pair<KernelFamily, int>> generated_family_degrees();

/// The full, filtered work list in its deterministic order (before sharding).
std::vector<WorkItem> build_work_list(const SweepOptions& options);

SweepResult run_sweep(const SweepOptions& options);

}  // namespace skelconv::verify
