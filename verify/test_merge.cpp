// verify/test_merge.cpp — merge: a sweep run as 3 shards, each
// written to a JSON report and read back, merges into the unsharded run's
// report field by field; shard reports of different sweeps are refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "merge.hpp"
#include "report.hpp"

namespace skelconv::verify {
namespace {

namespace fs = std::filesystem;

/// A small sweep of one compact kernel: all 7 regions (support ones too),
/// chunks of 6 samples so that every shard gets items of several regions.
SweepOptions small_sweep() {
  SweepOptions options;
  options.family = KernelFamily::compact;
  options.degree = 4;
  options.counts = {30, 12};
  options.chunk_size = 6;
  options.progress = false;
  return options;
}

/// Through a file and back: what `skelconv-verify --json` and `merge` do.
SweepReport round_trip(const SweepOptions& options, const SweepResult& result, const std::string& name) {
  const fs::path path = fs::temp_directory_path() / ("skelconv_test_merge_" + name + ".json");
  write_report({"", options, result}, path.string());
  SweepReport report = read_report(path.string());
  fs::remove(path);
  return report;
}

std::vector<SweepReport> shard_reports(SweepOptions options, int n) {
  std::vector<SweepReport> reports;
  options.threads = 1;
  options.shard_count = n;
  for (int k = n - 1; k >= 0; --k) {  // any order
    options.shard_index = k;
    reports.push_back(round_trip(options, run_sweep(options), "shard" + std::to_string(k)));
  }
  return reports;
}

/// The report without what may differ between equal sweeps: the wall time,
/// the thread count and the merge count.
nlohmann::json comparable(const SweepReport& report) {
  nlohmann::json json = json_report(report.options, report.result);
  json["settings"].erase("threads");
  json["summary"].erase("seconds");
  json["summary"].erase("merged_shards");
  return json;
}

class Merge : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    SweepOptions options = small_sweep();
    options.threads = 2;
    unsharded_ = new SweepReport{"unsharded", options, run_sweep(options)};
    shards_ = new std::vector<SweepReport>(shard_reports(small_sweep(), 3));
  }
  static void TearDownTestSuite() { delete unsharded_, delete shards_; }
  static SweepReport* unsharded_;
  static std::vector<SweepReport>* shards_;
};
SweepReport* Merge::unsharded_ = nullptr;
std::vector<SweepReport>* Merge::shards_ = nullptr;

TEST_F(Merge, ThreeShardsEqualTheUnshardedRunFieldByField) {
  const SweepReport merged = merge_reports(*shards_);
  EXPECT_EQ(merged.result.merged_shards, 3);
  ASSERT_EQ(merged.result.cells.size(), unsharded_->result.cells.size());
  EXPECT_GT(merged.result.cells.size(), 20u);  // 7 regions × several weight degrees
  const nlohmann::json expected = comparable(*unsharded_), actual = comparable(merged);
  // Field by field, so that a failure names the field.
  for (const auto& [key, value] : expected.items()) EXPECT_EQ(actual[key], value) << "member " << key;
  EXPECT_EQ(actual, expected);
  // Every shard ran something, and no shard ran everything.
  for (const SweepReport& shard : *shards_) {
    EXPECT_GT(shard.result.items_run, 0u);
    EXPECT_LT(shard.result.items_run, shard.result.items_total);
  }
}

TEST_F(Merge, ReadBackIsExact) {
  const SweepReport& shard = shards_->front();
  const SweepReport again = round_trip(shard.options, shard.result, "again");
  EXPECT_EQ(json_report(again.options, again.result), json_report(shard.options, shard.result));
}

void expect_refused(const std::vector<SweepReport>& reports, const std::string& message) {
  try {
    merge_reports(reports);
    ADD_FAILURE() << "merged, expected: " << message;
  } catch (const ReportError& e) {
    EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
  }
}

TEST_F(Merge, RefusesReportsOfDifferentSweeps) {
  std::vector<SweepReport> reports = *shards_;
  reports[1].options.seed += 1;
  expect_refused(reports, "settings.seed is");
  reports = *shards_;
  reports[2].options.commit = "0123abc";
  expect_refused(reports, "settings.commit is \"0123abc\"");
  reports = *shards_;
  reports[1].options.counts.other = 13;
  expect_refused(reports, "settings.points_other is 13");
  reports = *shards_;
  reports[2].options.region = Region::far;
  expect_refused(reports, "settings.filters is");
}

TEST_F(Merge, RefusesMissingDuplicateOrMergedShards) {
  std::vector<SweepReport> reports = *shards_;
  reports.pop_back();  // shard 0 (they are in order 2, 1, 0)
  expect_refused(reports, "shard(s) 0 of 3 missing");
  reports = *shards_;
  reports.push_back(reports[0]);
  expect_refused(reports, "is also given as");
  expect_refused({merge_reports(*shards_)}, "already a merged report");
  expect_refused({}, "no reports given");
}

TEST(MergeStatistics, TiesGoToTheSmallerSampleIndex) {
  // Equal maxima are common (errors are multiples of ulps); which sample is
  // "the worst" must not depend on the order threads or shards merge in.
  SweepProblem early, late;
  early.index = 3;
  late.index = 7;
  const RelativeErrors same{1e-15, 2e-15, 2e-15, false};
  PrecisionStats from_early, from_late;
  from_early.add(same, early, AccuracyTargets{});
  from_late.add(same, late, AccuracyTargets{});
  PrecisionStats one = from_early, other = from_late;
  one.merge(from_late);
  other.merge(from_early);
  EXPECT_EQ(one.worst_f->index, 3u);
  EXPECT_EQ(other.worst_f->index, 3u);
  EXPECT_EQ(other.worst_grad->index, 3u);
  PrecisionStats in_order;  // and within one work item, added late then early
  in_order.add(same, late, AccuracyTargets{});
  in_order.add(same, early, AccuracyTargets{});
  EXPECT_EQ(in_order.worst_f->index, 3u);
}

TEST(ReportReader, NamesTheFileAndTheJsonPath) {
  SweepOptions options = small_sweep();
  options.counts = {6, 0};
  SweepResult result;
  CellStats cell;
  cell.points = 1;
  result.cells[{KernelFamily::compact, 4, 0, Region::generic}] = cell;
  result.cells[{KernelFamily::compact, 4, 1, Region::generic}] = cell;
  nlohmann::json json = json_report(options, result);
  json["cells"][1]["double"].erase("max_rel_f");
  try {
    report_from_json(json, "x.json");
    ADD_FAILURE() << "read a report without cells[1].double.max_rel_f";
  } catch (const ReportError& e) {
    EXPECT_STREQ(e.what(), "x.json: cells[1].double.max_rel_f: missing");
  }
  json = json_report(options, result);
  json["cells"][0]["region"] = "nowhere";
  EXPECT_THROW(report_from_json(json, "x.json"), ReportError);
  json = json_report(options, result);
  json["tool"] = "skelconv-verify-polygons";
  EXPECT_THROW(report_from_json(json, "x.json"), ReportError);
}

}  // namespace
}  // namespace skelconv::verify
