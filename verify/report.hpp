// verify/report.hpp — the sweep's report: a table on stdout, a JSON document
// for machines, and the verdict (the generic targets).
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep.hpp"

namespace skelconv::verify {

/// A relative error for the tables: "1.2e-16", or "inf" (non-finite).
std::string format_error(double value);

/// Exclusions of one (family, degree, region) cell, all weight degrees
/// together, against ExclusionLimits.
struct ExclusionCell {
  KernelFamily family;
  int degree;
  Region region;
  std::uint64_t evaluations = 0;  ///< compared + excluded + outside the support
  std::uint64_t compared = 0;
  std::uint64_t excluded = 0;     ///< still flagged after the retry
  std::uint64_t retried = 0;      ///< flagged by the standard reference
  double excluded_share() const { return evaluations ? double(excluded) / double(evaluations) : 0.0; }
  bool passed = true;             ///< within both limits
};

/// One entry per (family, degree, region) present in `result`, in order.
std::vector<ExclusionCell> exclusion_cells(const SweepResult& result, const ExclusionLimits& limits);

/// The sweep's verdict: the generic targets (double precision) and the
/// exclusion limits of every cell.
struct GenericVerdict {
  std::uint64_t failing_points = 0;  ///< comparisons above a generic target (or non-finite)
  std::uint64_t failing_cells = 0;   ///< (family, degree, weight degree) rows with such a point
  std::uint64_t compared = 0;        ///< generic comparisons made
  std::uint64_t failing_exclusion_cells = 0;  ///< (family, degree, region) cells beyond ExclusionLimits
  bool passed() const { return failing_points == 0 && compared > 0 && failing_exclusion_cells == 0; }
};

GenericVerdict generic_verdict(const SweepResult& result, const ExclusionLimits& limits);

/// Tables (double, then binary128), anomalies and the summary line.
void write_text_report(std::ostream& out, const SweepOptions& options, const SweepResult& result);

/// The sweep's definition and settings (the JSON report's "settings").
nlohmann::json settings_json(const SweepOptions& options);

nlohmann::json json_report(const SweepOptions& options, const SweepResult& result);

}  // namespace skelconv::verify
