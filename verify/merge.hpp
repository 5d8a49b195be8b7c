// verify/merge.hpp — shard reports (skelconv-verify --shard k/n) combined into
// the report of the unsharded sweep.
//
// Every statistic of a cell merges exactly (CellStats::merge: sums of counts,
// maxima of errors, the worst sample with ties broken by sample index), and
// every sample belongs to exactly one shard, so the merged report equals the
// unsharded run field by field except the wall time and the thread count
// (ctest verify_merge: test_merge.cpp). Summary counters add up; `seconds`
// becomes the sum of the shards' wall times (worker-seconds).
#pragma once

#include <vector>

#include "report_reader.hpp"

namespace skelconv::verify {

/// The settings that define a sweep's samples and verdict — everything in the
/// report's "settings" except which shard ran and on how many threads. Shards
/// of one sweep must agree on all of it, the commit included.
nlohmann::json sweep_definition(const SweepOptions& options);

/// Merges the reports of shards 0..n−1 of one sweep (any order); the one
/// report of an unsharded sweep (n = 1) merges into itself. Throws
/// ReportError, naming the files, when they come from different sweep
/// definitions (seed, sizes, filters, commit, ...), when a shard is missing or
/// given twice, or when the work lists disagree.
SweepReport merge_reports(const std::vector<SweepReport>& shards);

}  // namespace skelconv::verify
