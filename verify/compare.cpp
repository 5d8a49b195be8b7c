// verify/compare.cpp — see compare.hpp.
#include "compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <ostream>
#include <string>

#include "report.hpp"

namespace skelconv::verify {
namespace {

double maximum_of(const CellStats& cell, Measure measure) {
  switch (measure) {
    case Measure::f_double: return cell.in_double.max_f;
    case Measure::grad_double: return cell.in_double.max_grad;
    case Measure::f_extended: return cell.in_extended.max_f;
    case Measure::grad_extended: return cell.in_extended.max_grad;
  }
  return 0;
}

bool is_double(Measure measure) { return measure == Measure::f_double || measure == Measure::grad_double; }

std::string cell_name(const CellKey& key) {
  const auto& [family, degree, weight_degree, region] = key;
  return std::string(family_name(family)) + " i=" + std::to_string(degree) + " w=" + std::to_string(weight_degree) +
         " " + std::string(region_name(region));
}

std::string pad(const std::string& text, std::size_t width) {
  return text.size() >= width ? text : std::string(width - text.size(), ' ') + text;
}

/// (family, degree, region): the table's row, weight degrees together.
using RegionRow = std::tuple<KernelFamily, int, Region>;
struct RegionRowMaxima {
  std::array<double, 4> before{}, after{};
  bool failed = false;
};

void write_table(std::ostream& out, const Comparison& comparison) {
  std::map<RegionRow, RegionRowMaxima> rows;
  for (const CellComparison& c : comparison.cells) {
    RegionRowMaxima& row = rows[{std::get<0>(c.key), std::get<1>(c.key), std::get<3>(c.key)}];
    for (std::size_t m = 0; m < all_measures.size(); ++m) {
      row.before[m] = std::max(row.before[m], c.before[m]);
      row.after[m] = std::max(row.after[m], c.after[m]);
    }
    row.failed = row.failed || c.failed();
  }
  out << "family    i region            |  f double before → after | ∇f double before → after |"
         "    f binary128 before → after |   ∇f binary128 before → after |\n";
  for (const auto& [key, row] : rows) {
    const auto& [family, degree, region] = key;
    std::string line = std::string(family_name(family));
    line.resize(8, ' ');
    line += pad(std::to_string(degree), 3) + " " + std::string(region_name(region));
    line.resize(30, ' ');
    out << line << "|";
    for (std::size_t m = 0; m < all_measures.size(); ++m)
      out << pad(format_error(row.before[m]), m < 2 ? 15 : 20) << " →" << pad(format_error(row.after[m]), 8) << " |";
    out << (row.failed ? "  WORSE" : "") << '\n';
  }
}

void write_failures(std::ostream& out, const Comparison& comparison) {
  for (const CellComparison& c : comparison.cells) {
    if (c.lost) out << "  LOST " << cell_name(c.key) << ": compared points in BASE, none in NEW\n";
    for (std::size_t m = 0; m < all_measures.size(); ++m) {
      if (!c.worse[m]) continue;
      char ratio[32];
      std::snprintf(ratio, sizeof ratio, "%.3g", c.after[m] / c.before[m]);
      out << "  WORSE " << cell_name(c.key) << ", " << measure_name(all_measures[m]) << ": "
          << format_error(c.before[m]) << " → " << format_error(c.after[m]) << " (×" << ratio << ")\n";
    }
  }
  for (const CellKey& key : comparison.removed) out << "  DISAPPEARED " << cell_name(key) << '\n';
}

}  // namespace

const char* measure_name(Measure measure) {
  switch (measure) {
    case Measure::f_double: return "f (double)";
    case Measure::grad_double: return "|grad f| (double)";
    case Measure::f_extended: return "f (binary128)";
    case Measure::grad_extended: return "|grad f| (binary128)";
  }
  return "?";
}

std::size_t Comparison::failed_cells() const {
  return static_cast<std::size_t>(std::count_if(cells.begin(), cells.end(), [](const auto& c) { return c.failed(); }));
}

Comparison compare_reports(const SweepReport& base, const SweepReport& fresh, const CompareOptions& options) {
  const SweepOptions &b = base.options, &n = fresh.options;
  if (b.seed != n.seed || b.counts.generic != n.counts.generic || b.counts.other != n.counts.other)
    throw ReportError(fresh.source + ": seed " + std::to_string(n.seed) + ", " + std::to_string(n.counts.generic) +
                      "/" + std::to_string(n.counts.other) + " points, but " + base.source + " has seed " +
                      std::to_string(b.seed) + ", " + std::to_string(b.counts.generic) + "/" +
                      std::to_string(b.counts.other) + ": not the same samples, nothing to compare");
  Comparison out;
  out.tolerance_factor = options.tolerance_factor;
  out.double_floor = options.double_floor;
  out.extended_floor = options.extended_floor >= 0 ? options.extended_floor : b.reference.flag_threshold;
  for (const auto& [key, before] : base.result.cells) {
    const auto it = fresh.result.cells.find(key);
    if (it == fresh.result.cells.end()) {
      out.removed.push_back(key);
      continue;
    }
    const CellStats& after = it->second;
    CellComparison c{key};
    c.lost = before.points > 0 && after.points == 0;
    for (std::size_t m = 0; m < all_measures.size(); ++m) {
      c.before[m] = maximum_of(before, all_measures[m]);
      c.after[m] = maximum_of(after, all_measures[m]);
      const double floor = is_double(all_measures[m]) ? out.double_floor : out.extended_floor;
      // Written so that a NaN after (never produced: non-finite is +inf) would count as worse.
      c.worse[m] = !(c.after[m] <= options.tolerance_factor * c.before[m] || c.after[m] <= floor);
    }
    out.cells.push_back(c);
  }
  for (const auto& [key, cell] : fresh.result.cells)
    if (!base.result.cells.contains(key)) out.added.push_back(key);
  return out;
}

void write_comparison(std::ostream& out, const Comparison& comparison, const SweepReport& base,
                      const SweepReport& fresh) {
  out << "skelconv-verify compare: max relative errors per (family, degree, region), weight degrees together\n"
      << "BASE " << base.source << " (commit " << base.options.commit << ")\nNEW  " << fresh.source << " (commit "
      << fresh.options.commit << ")\n";
  if (fresh.options.perturbation)
    out << "NEW has a test perturbation: " << family_name(fresh.options.perturbation->family) << " results × (1 + "
        << fresh.options.perturbation->relative << ")\n";
  out << "A cell (family, degree, weight degree, region) is worse when after > " << comparison.tolerance_factor
      << " × before and after > " << format_error(comparison.double_floor) << " (double) or "
      << format_error(comparison.extended_floor) << " (binary128).\n\n";
  write_table(out, comparison);
  out << '\n';
  write_failures(out, comparison);
  std::map<std::tuple<KernelFamily, int>, int> added;
  for (const CellKey& key : comparison.added) ++added[{std::get<0>(key), std::get<1>(key)}];
  for (const auto& [key, cells] : added)
    out << "  new: " << family_name(std::get<0>(key)) << " i=" << std::get<1>(key) << " (" << cells
        << " cells, not in BASE)\n";
  out << "\ncompare: " << comparison.cells.size() << " cells compared, " << comparison.failed_cells() << " worse, "
      << comparison.removed.size() << " disappeared, " << comparison.added.size() << " new: "
      << (comparison.passed() ? "PASSED" : "FAILED") << (comparison.cells.empty() ? " (no cell in both reports)" : "")
      << '\n';
}

}  // namespace skelconv::verify
