// verify/compare.hpp — did a change (a regenerated formula, a new compiler)
// make any region worse? Compares two sweep reports of the same samples
// (same seed and sizes) cell by cell: (family, degree, weight degree, region),
// max relative error of f and of ∇f, in double and in binary128.
//
// A cell is worse when, for one of the four maxima, after > k · before and
// after > the floor of its precision. The floors (CompareOptions) say below
// which an error tells nothing about the formula. A cell of BASE missing from
// NEW (or left without comparisons) fails; a cell only in NEW (a family or
// degree added since) is listed as new and does not fail.
#pragma once

#include <array>
#include <iosfwd>
#include <vector>

#include "report_reader.hpp"

namespace skelconv::verify {

struct CompareOptions {
  /// k: how much larger a maximum may get before the cell is worse.
  double tolerance_factor = 2;
  /// Floor for the double maxima: 16 ulps of 1 (16 · 2^-52 ≈ 3.6e-15). A
  /// closed form of tens of roundings, each ≤ 2^-53 relative, has errors of
  /// a few ulps even when perfectly conditioned; the smallest cell maximum
  /// of the default sweep is 1.75 ulps and a third of them are below 16
  /// (docs/verify.md); re-ordering the same terms moves them around there.
  /// Below 16 ulps a change is rounding noise, not a formula regression.
  double double_floor = 16 * 0x1p-52;
  /// Floor for the binary128 maxima; negative = BASE's reference flag
  /// threshold (1e-20 by default): no reference less accurate than that is
  /// used, so below it a binary128 "error" may be the reference's own; and a
  /// formula error that small is 4 digits below double's rounding.
  double extended_floor = -1;
};

/// The four maxima the comparison looks at.
enum class Measure { f_double, grad_double, f_extended, grad_extended };
inline constexpr std::array<Measure, 4> all_measures{Measure::f_double, Measure::grad_double, Measure::f_extended,
                                                     Measure::grad_extended};
const char* measure_name(Measure measure);  ///< "f (double)", ...

struct CellComparison {
  CellKey key;
  std::array<double, 4> before{}, after{};  ///< indexed like all_measures
  std::array<bool, 4> worse{};
  bool lost = false;  ///< compared points in BASE, none in NEW
  bool failed() const { return lost || worse[0] || worse[1] || worse[2] || worse[3]; }
};

struct Comparison {
  std::vector<CellComparison> cells;  ///< cells in both reports, in key order
  std::vector<CellKey> added;         ///< only in NEW: reported, not a failure
  std::vector<CellKey> removed;       ///< only in BASE: a failure
  double double_floor = 0, extended_floor = 0, tolerance_factor = 0;
  std::size_t failed_cells() const;
  /// A comparison of no cell at all proves nothing: it fails.
  bool passed() const { return !cells.empty() && failed_cells() == 0 && removed.empty(); }
};

/// Throws ReportError when the two reports did not sweep the same samples
/// (different seed or point counts).
Comparison compare_reports(const SweepReport& base, const SweepReport& fresh, const CompareOptions& options);

/// Per (family, degree, region), max over the weight degrees of the double
/// and binary128 maxima, before → after, marked where a cell got worse; then
/// every failing cell, the new and the disappeared ones, and a summary line.
void write_comparison(std::ostream& out, const Comparison& comparison, const SweepReport& base,
                      const SweepReport& fresh);

}  // namespace skelconv::verify
