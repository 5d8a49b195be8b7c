// verify/merge.cpp — see merge.hpp.
#include "merge.hpp"

#include <algorithm>

#include "report.hpp"

namespace skelconv::verify {
namespace {

/// The first member where two definitions differ ("seed", "filters", ...).
std::string first_difference(const nlohmann::json& x, const nlohmann::json& y) {
  for (const auto& [key, value] : x.items())
    if (!y.contains(key) || y[key] != value) return key;
  for (const auto& [key, value] : y.items())
    if (!x.contains(key)) return key;
  return "";
}

std::string shown(const nlohmann::json& definition, const std::string& key) {
  return definition.contains(key) ? definition[key].dump() : "(absent)";
}

/// Throws unless every shard has the first one's definition and shard count,
/// and the shards are exactly 0..n−1.
void check_shards_belong_together(const std::vector<SweepReport>& shards) {
  if (shards.empty()) throw ReportError("merge: no reports given");
  const SweepReport& first = shards.front();
  const nlohmann::json definition = sweep_definition(first.options);
  const int n = first.options.shard_count;
  std::vector<const SweepReport*> by_index(static_cast<std::size_t>(n), nullptr);
  for (const SweepReport& shard : shards) {
    const nlohmann::json other = sweep_definition(shard.options);
    if (const std::string key = first_difference(definition, other); !key.empty())
      throw ReportError(shard.source + ": settings." + key + " is " + shown(other, key) + " but " + first.source +
                        " has " + shown(definition, key) + ": reports of different sweeps cannot be merged");
    if (shard.options.shard_count != n)
      throw ReportError(shard.source + ": settings.shard_count is " + std::to_string(shard.options.shard_count) +
                        " but " + first.source + " has " + std::to_string(n));
    if (shard.result.merged_shards > 0)
      throw ReportError(shard.source + ": already a merged report; merge the shard reports themselves");
    if (shard.result.items_total != first.result.items_total)
      throw ReportError(shard.source + ": summary.items_total differs from " + first.source);
    const SweepReport*& slot = by_index[static_cast<std::size_t>(shard.options.shard_index)];
    if (slot)
      throw ReportError(shard.source + ": shard " + std::to_string(shard.options.shard_index) + "/" +
                        std::to_string(n) + " is also given as " + slot->source);
    slot = &shard;
  }
  std::string missing;
  for (int k = 0; k < n; ++k)
    if (!by_index[static_cast<std::size_t>(k)]) missing += (missing.empty() ? "" : ", ") + std::to_string(k);
  if (!missing.empty())
    throw ReportError("merge: shard(s) " + missing + " of " + std::to_string(n) + " missing (" + first.source +
                      " belongs to a " + std::to_string(n) + "-shard sweep)");
}

}  // namespace

nlohmann::json sweep_definition(const SweepOptions& options) {
  nlohmann::json definition = settings_json(options);
  definition.erase("shard_index");
  definition.erase("shard_count");
  definition.erase("threads");
  return definition;
}

SweepReport merge_reports(const std::vector<SweepReport>& shards) {
  check_shards_belong_together(shards);
  SweepReport merged;
  merged.source = "merge of " + std::to_string(shards.size()) + " shard reports";
  merged.options = shards.front().options;
  merged.options.shard_index = 0;
  merged.options.shard_count = 1;
  SweepResult& result = merged.result;
  result.items_total = shards.front().result.items_total;
  // Merging the one report of an unsharded sweep is the identity (e.g. to
  // drop its samples with --without-samples): it stays a single run.
  result.merged_shards = shards.front().options.shard_count > 1 ? static_cast<int>(shards.size()) : 0;
  for (const SweepReport& shard : shards) {
    for (const auto& [key, cell] : shard.result.cells) result.cells[key].merge(cell);
    result.items_run += shard.result.items_run;
    result.samples += shard.result.samples;
    result.seconds += shard.result.seconds;
    result.kernel_evaluations += shard.result.kernel_evaluations;
  }
  if (result.items_run != result.items_total)
    throw ReportError("merge: the shards ran " + std::to_string(result.items_run) + " work items, the sweep has " +
                      std::to_string(result.items_total));
  return merged;
}

}  // namespace skelconv::verify
