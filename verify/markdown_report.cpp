// verify/markdown_report.cpp — see markdown_report.hpp.
#include "markdown_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <ostream>
#include <set>
#include <string>

#include "report.hpp"

namespace skelconv::verify {
namespace {

/// Worst double errors of one (degree, region), over the weight degrees.
struct Worst {
  double f = 0, grad = 0;
  std::uint64_t points = 0;
};

std::string cell_text(const Worst& worst, Region region, const AccuracyTargets& targets) {
  if (worst.points == 0) return "no comparison";
  const bool above = !(worst.f <= targets.generic_f) || !(worst.grad <= targets.generic_grad);
  const std::string text = format_error(worst.f) + " / " + format_error(worst.grad);
  if (!above) return text;
  return region == Region::generic ? "**" + text + "** ❌" : text + " ⚠";
}

void write_family_table(std::ostream& out, KernelFamily family, const SweepResult& result,
                        const AccuracyTargets& targets) {
  std::map<int, std::map<Region, Worst>> table;  // degree → region → worst
  std::set<Region> regions;
  for (const auto& [key, cell] : result.cells) {
    const auto& [f, degree, weight_degree, region] = key;
    if (f != family) continue;
    Worst& worst = table[degree][region];
    worst.f = std::max(worst.f, cell.in_double.max_f);
    worst.grad = std::max(worst.grad, cell.in_double.max_grad);
    worst.points += cell.points;
    regions.insert(region);
  }
  out << "\n### " << family_name(family) << "\n\n| i |";
  for (Region region : regions) out << ' ' << region_name(region) << " |";
  out << "\n|---:|";
  for (std::size_t k = 0; k < regions.size(); ++k) out << "---|";
  out << '\n';
  for (const auto& [degree, row] : table) {
    out << "| " << degree << " |";
    for (Region region : regions) {
      const auto it = row.find(region);
      out << ' ' << (it == row.end() ? "–" : cell_text(it->second, region, targets)) << " |";
    }
    out << '\n';
  }
}

}  // namespace

void write_markdown_report(std::ostream& out, const SweepOptions& options, const SweepResult& result) {
  const GenericVerdict verdict = generic_verdict(result, options.exclusions);
  std::set<KernelFamily> families;
  for (const auto& [key, cell] : result.cells) families.insert(std::get<0>(key));
  out << "## skelconv-verify: generated segment functions against binary128 quadrature\n\n"
      << "Commit `" << options.commit << "`, seed " << options.seed << ", " << options.counts.generic
      << " samples per (family, degree) in the generic region and " << options.counts.other
      << " in each other region; " << result.samples << " samples";
  if (result.merged_shards > 0) out << " in " << result.merged_shards << " shards";
  out << ".\n\nEach cell: the worst relative error of f / of |∇f| in double, over the weight degrees 0–3 "
      << "and the entry points. ❌: generic cell above its target (f ≤ " << format_error(options.targets.generic_f)
      << ", |∇f| ≤ " << format_error(options.targets.generic_grad)
      << ", asserted); ⚠: another region above those targets (reported only).\n\n"
      << "**Verdict: " << (verdict.passed() ? "passed" : "FAILED") << "** — " << verdict.failing_points
      << " generic-target misses of " << verdict.compared << " generic comparisons, "
      << verdict.failing_exclusion_cells << " cells beyond the exclusion limits.\n";
  if (options.perturbation)
    out << "\n**Test perturbation:** " << family_name(options.perturbation->family) << " results × (1 + "
        << options.perturbation->relative << ").\n";
  for (KernelFamily family : families) write_family_table(out, family, result, options.targets);
}

}  // namespace skelconv::verify
