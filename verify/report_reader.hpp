// verify/report_reader.hpp — a sweep's JSON report (report.hpp, json_report)
// read back into the options and result that produced it, so that shard
// reports can be merged (merge.hpp) and reports compared (compare.hpp).
#pragma once

#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "sweep.hpp"

namespace skelconv::verify {

/// A report that cannot be used: unreadable, not JSON, a field missing or of
/// the wrong type, or reports that do not belong together. what() names the
/// file and the JSON path, e.g. "shard1.json: cells[4].double.max_rel_f:
/// expected a number". skelconv-verify exits with status 2 on it.
struct ReportError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A report as read: the options (definition and settings) and the result.
struct SweepReport {
  std::string source;  ///< the file it was read from (for messages)
  SweepOptions options;
  SweepResult result;
};

/// Reads `report` (a parsed JSON report); `source` names it in errors.
SweepReport report_from_json(const nlohmann::json& report, const std::string& source);

/// Reads the JSON report in file `path`.
SweepReport read_report(const std::string& path);

/// Writes `report` as JSON to `path` (one cell per line, so that a committed
/// report diffs line by line), through a temporary file renamed into place:
/// nothing half-written. `with_samples` = false drops the worst samples (a
/// small baseline). Throws ReportError when the file cannot be written.
void write_report(const SweepReport& report, const std::string& path, bool with_samples = true);

}  // namespace skelconv::verify
