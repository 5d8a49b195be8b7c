// verify/report.hpp — the sweep's report: a table on stdout, a JSON document
// for machines, and the verdict (the generic targets).
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>

#include <nlohmann/json.hpp>

#include "sweep.hpp"

namespace skelconv::verify {

/// The verdict on the asserted region (generic, double precision).
struct GenericVerdict {
  std::uint64_t failing_points = 0;  ///< comparisons above a generic target (or non-finite)
  std::uint64_t failing_cells = 0;   ///< (family, degree, weight degree) rows with such a point
  std::uint64_t compared = 0;        ///< generic comparisons made
  bool passed() const { return failing_points == 0 && compared > 0; }
};

GenericVerdict generic_verdict(const SweepResult& result);

/// Tables (double, then binary128), anomalies and the summary line.
void write_text_report(std::ostream& out, const SweepOptions& options, const SweepResult& result);

nlohmann::json json_report(const SweepOptions& options, const SweepResult& result);

}  // namespace skelconv::verify
