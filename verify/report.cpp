// verify/report.cpp — see report.hpp.
#include "report.hpp"

#include <algorithm>
#include <cstdio>
#include <ostream>
#include <set>
#include <string>
#include <tuple>

#include "generated_kernels.hpp"

namespace skelconv::verify {
namespace {

std::string pad_left(const std::string& text, std::size_t width) {
  return text.size() >= width ? text : std::string(width - text.size(), ' ') + text;
}

std::string pad_right(const std::string& text, std::size_t width) {
  return text.size() >= width ? text : text + std::string(width - text.size(), ' ');
}

/// (family, degree, weight degree): a row of the table, one column per region.
using KernelRow = std::tuple<KernelFamily, int, int>;

std::set<KernelRow> rows_of(const SweepResult& result) {
  std::set<KernelRow> rows;
  for (const auto& [key, cell] : result.cells) rows.insert({std::get<0>(key), std::get<1>(key), std::get<2>(key)});
  return rows;
}

const CellStats* find_cell(const SweepResult& result, const KernelRow& row, Region region) {
  const auto it = result.cells.find({std::get<0>(row), std::get<1>(row), std::get<2>(row), region});
  return it == result.cells.end() ? nullptr : &it->second;
}

constexpr std::size_t number_width = 8;  // "1.2e-16" plus the mark

void write_table(std::ostream& out, const SweepResult& result, bool in_double, const AccuracyTargets& targets) {
  out << pad_right("family", 8) << pad_left("i", 3) << pad_left("w", 3) << " |";
  for (Region region : all_regions) {
    std::string title(1, ' ');
    title += region_short_name(region);
    out << pad_right(title, 2 * number_width + 2) << "|";
  }
  out << '\n' << std::string(14, ' ') << " |";
  for (std::size_t r = 0; r < all_regions.size(); ++r)
    out << pad_left("f", number_width) << pad_left("|grad|", number_width + 1) << " |";
  out << '\n';
  KernelFamily previous_family{};
  bool first = true;
  for (const KernelRow& row : rows_of(result)) {
    if (!first && std::get<0>(row) != previous_family) out << '\n';
    first = false;
    previous_family = std::get<0>(row);
    out << pad_right(std::string(family_name(std::get<0>(row))), 8) << pad_left(std::to_string(std::get<1>(row)), 3)
        << pad_left(std::to_string(std::get<2>(row)), 3) << " |";
    for (Region region : all_regions) {
      const CellStats* cell = find_cell(result, row, region);
      if (!cell || cell->points == 0) {
        out << pad_left("-", number_width) << pad_left("-", number_width + 1) << " |";
        continue;
      }
      const PrecisionStats& stats = in_double ? cell->in_double : cell->in_extended;
      const bool asserted = in_double && region == Region::generic;
      const auto mark = [&](double value, double target) {
        return format_error(value) + (asserted && !(value <= target) ? "!" : " ");
      };
      out << pad_left(mark(stats.max_f, targets.generic_f), number_width)
          << pad_left(mark(stats.max_grad, targets.generic_grad), number_width + 1) << " |";
    }
    out << '\n';
  }
}

nlohmann::json problem_json(const SweepProblem& pb) {
  char buffer[64];
  const auto exact = [&](double x) {  // round-trip decimal, so the sample can be replayed exactly
    std::snprintf(buffer, sizeof buffer, "%.17g", x);
    return std::string(buffer);
  };
  const auto vec = [&](const auto& v) {
    nlohmann::json out = nlohmann::json::array();
    for (double x : v) out.push_back(exact(x));
    return out;
  };
  nlohmann::json out{{"region", region_name(pb.region)}, {"index", pb.index}, {"A", vec(pb.a)}, {"B", vec(pb.b)},
                     {"P", vec(pb.p)},  {"w", vec(pb.w)},  {"s", exact(pb.s)},  {"R", exact(pb.R)}};
  if (pb.family == KernelFamily::gaussian) {  // its own parameters, so that its worst sample replays too
    out["gaussian_a"] = exact(pb.gaussian_a);
    out["gaussian_b"] = exact(pb.gaussian_b);
  }
  return out;
}

nlohmann::json precision_json(const PrecisionStats& stats) {
  nlohmann::json out{{"max_rel_f", stats.max_f},
                     {"max_rel_grad", stats.max_grad},
                     {"max_rel_grad_component", stats.max_grad_component},
                     {"nonfinite", stats.nonfinite},
                     {"f_above_generic_target", stats.f_above_target},
                     {"grad_above_generic_target", stats.grad_above_target}};
  if (stats.worst_f) out["worst_f_sample"] = problem_json(*stats.worst_f);
  if (stats.worst_grad) out["worst_grad_sample"] = problem_json(*stats.worst_grad);
  return out;
}

// Exclusions per (family, degree) row and region: "excluded/evaluations",
// '!' where the cell is beyond its limits.
void write_exclusion_table(std::ostream& out, const std::vector<ExclusionCell>& cells, const ExclusionLimits& limits) {
  char share[32];
  std::snprintf(share, sizeof share, "%.3g%%", 100 * limits.max_excluded_share);
  out << "\nEXCLUSIONS — references still flagged after the retry with the stronger reference, per (family, "
         "degree, region), all weight degrees: excluded/evaluations ('!' = more than "
      << share << " excluded, or fewer than " << 100 * limits.min_compared_share << "% compared).\n";
  constexpr std::size_t width = 12;
  out << pad_right("family", 8) << pad_left("i", 3) << " |";
  for (Region region : all_regions) out << pad_left(std::string(region_short_name(region)), width) << " |";
  out << '\n';
  std::size_t k = 0;
  while (k < cells.size()) {
    const KernelFamily family = cells[k].family;
    const int degree = cells[k].degree;
    out << pad_right(std::string(family_name(family)), 8) << pad_left(std::to_string(degree), 3) << " |";
    for (Region region : all_regions) {
      std::string text = "-";
      for (std::size_t j = k; j < cells.size() && cells[j].family == family && cells[j].degree == degree; ++j)
        if (cells[j].region == region)
          text = std::to_string(cells[j].excluded) + "/" + std::to_string(cells[j].evaluations) +
                 (cells[j].passed ? " " : "!");
      out << pad_left(text, width) << " |";
    }
    out << '\n';
    while (k < cells.size() && cells[k].family == family && cells[k].degree == degree) ++k;
  }
}

}  // namespace

std::string format_error(double value) {
  char buffer[32];
  if (value != value || value == std::numeric_limits<double>::infinity()) return "inf";
  std::snprintf(buffer, sizeof buffer, "%.1e", value);
  return buffer;
}

std::vector<ExclusionCell> exclusion_cells(const SweepResult& result, const ExclusionLimits& limits) {
  std::vector<ExclusionCell> cells;
  for (const auto& [key, cell] : result.cells) {  // ordered by family, degree, weight degree, region
    const auto [family, degree, weight_degree, region] = key;
    auto it = std::find_if(cells.begin(), cells.end(), [&](const ExclusionCell& c) {
      return c.family == family && c.degree == degree && c.region == region;
    });
    if (it == cells.end()) it = cells.insert(cells.end(), ExclusionCell{family, degree, region});
    it->evaluations += cell.points + cell.excluded + cell.outside_support;
    it->compared += cell.points;
    it->excluded += cell.excluded;
    it->retried += cell.retried;
  }
  std::sort(cells.begin(), cells.end(), [](const ExclusionCell& x, const ExclusionCell& y) {
    return std::tie(x.family, x.degree, x.region) < std::tie(y.family, y.degree, y.region);
  });
  for (ExclusionCell& c : cells) c.passed = limits.allow(c.compared, c.excluded, c.evaluations);
  return cells;
}

GenericVerdict generic_verdict(const SweepResult& result, const ExclusionLimits& limits) {
  GenericVerdict verdict;
  for (const ExclusionCell& c : exclusion_cells(result, limits))
    if (!c.passed) ++verdict.failing_exclusion_cells;
  for (const auto& [key, cell] : result.cells) {
    if (std::get<3>(key) != Region::generic) continue;
    verdict.compared += cell.points;
    const PrecisionStats& s = cell.in_double;
    // A point can miss both targets; counting f and ∇f misses separately is an
    // upper bound we report as such (the JSON has both counts).
    const std::uint64_t failing = s.f_above_target + s.grad_above_target;
    verdict.failing_points += failing;
    if (failing > 0) ++verdict.failing_cells;
  }
  return verdict;
}

void write_text_report(std::ostream& out, const SweepOptions& options, const SweepResult& result) {
  out << "skelconv-verify: max relative error of the generated segment functions against binary128\n"
         "quadrature of the definition integral (docs/mathematics.md §2). Rows: family, kernel degree i, weight degree w.\n"
      << "seed " << options.seed << ", samples per (family, degree, region): generic " << options.counts.generic
      << ", other regions " << options.counts.other << "; shard " << options.shard_index << "/"
      << options.shard_count << " (" << result.items_run << " of " << result.items_total << " items)";
  if (result.merged_shards > 0) out << ", merged from " << result.merged_shards << " shard reports";
  out << "; commit " << options.commit << "\n\n";
  out << "DOUBLE — generated code in double. Asserted: generic f <= " << format_error(options.targets.generic_f)
      << ", |grad f| <= " << format_error(options.targets.generic_grad)
      << " ('!' = above). Other regions are reported only.\n";
  write_table(out, result, true, options.targets);
  out << "\nEXTENDED — the same generated code in binary128: what remains here is formula error, not rounding.\n";
  write_table(out, result, false, options.targets);
  const std::vector<ExclusionCell> exclusions = exclusion_cells(result, options.exclusions);
  write_exclusion_table(out, exclusions, options.exclusions);

  out << "\nAnomalies (excluded = reference error estimate above " << format_error(options.reference.flag_threshold)
      << " even after the retry, not compared; support mismatch = double and binary128 clips disagree on "
         "emptiness):\n";
  std::uint64_t excluded = 0, retried = 0, mismatches = 0, nonfinite = 0, compared = 0, outside = 0;
  double worst_reference = 0;
  bool any = false;
  for (const auto& [key, cell] : result.cells) {
    excluded += cell.excluded;
    retried += cell.retried;
    mismatches += cell.support_mismatch;
    nonfinite += cell.in_double.nonfinite + cell.in_extended.nonfinite;
    compared += cell.points;
    outside += cell.outside_support;
    worst_reference = std::max(worst_reference, cell.max_reference_error);
    if (cell.excluded || cell.support_mismatch || cell.in_double.nonfinite || cell.in_extended.nonfinite) {
      any = true;
      out << "  " << family_name(std::get<0>(key)) << " i=" << std::get<1>(key) << " w=" << std::get<2>(key) << " "
          << region_name(std::get<3>(key)) << ": excluded " << cell.excluded << ", support mismatch "
          << cell.support_mismatch << ", non-finite double " << cell.in_double.nonfinite << ", non-finite binary128 "
          << cell.in_extended.nonfinite << '\n';
    }
  }
  if (!any) out << "  none\n";
  const GenericVerdict verdict = generic_verdict(result, options.exclusions);
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.1f", result.seconds);
  out << "\nsummary: " << result.samples << " samples, " << compared
      << " comparisons (each: 3 entry points, double and binary128), " << retried << " references retried, "
      << excluded << " excluded, " << outside
      << " outside the support (f = 0, clips agree), " << mismatches << " support mismatches, " << nonfinite
      << " non-finite results; largest reference error estimate " << format_error(worst_reference)
      << "; generic-target misses: " << verdict.failing_points << " (f and |grad f| counted separately) in "
      << verdict.failing_cells << " rows, of " << verdict.compared << " generic comparisons; cells beyond the "
      << "exclusion limits: " << verdict.failing_exclusion_cells << "; " << seconds << " s\n";
}

nlohmann::json settings_json(const SweepOptions& options) {
  nlohmann::json filters{{"family", nullptr}, {"degree", nullptr}, {"region", nullptr}};
  if (options.family) filters["family"] = family_name(*options.family);
  if (options.degree) filters["degree"] = *options.degree;
  if (options.region) filters["region"] = region_name(*options.region);
  nlohmann::json settings{
      {"commit", options.commit},
      {"seed", options.seed},
      {"points_generic", options.counts.generic},
      {"points_other", options.counts.other},
      {"chunk_size", options.chunk_size},
      {"filters", filters},
      {"shard_index", options.shard_index},
      {"shard_count", options.shard_count},
      {"threads", options.threads},
      {"target_generic_f", options.targets.generic_f},
      {"target_generic_grad", options.targets.generic_grad},
      {"reference_requested_tolerance", options.reference.requested},
      {"reference_flag_threshold", options.reference.flag_threshold},
      {"reference_max_levels", options.reference.max_levels},
      {"reference_retry_requested_tolerance", options.reference.retry().requested},
      {"reference_retry_max_levels", options.reference.retry().max_levels},
      {"max_excluded_share", options.exclusions.max_excluded_share},
      {"min_compared_share", options.exclusions.min_compared_share},
      {"error_definitions",
       {{"f", "|f - f_ref| / |f_ref|"},
        {"grad", "|g - g_ref| / |g_ref| (Euclidean norms)"},
        {"grad_component", "max_c |g_c - g_ref_c| / |g_ref|"},
        {"entry_points", "max over f(), grad() and f_and_grad()"}}}};
  if (options.perturbation)
    settings["test_perturbation"] = {{"family", family_name(options.perturbation->family)},
                                     {"relative", options.perturbation->relative}};
  return settings;
}

nlohmann::json json_report(const SweepOptions& options, const SweepResult& result) {
  nlohmann::json cells = nlohmann::json::array();
  for (const auto& [key, cell] : result.cells) {
    const auto* kernel = find_generated_double(std::get<0>(key), std::get<1>(key), std::get<2>(key));
    cells.push_back({{"family", family_name(std::get<0>(key))},
                     {"degree", std::get<1>(key)},
                     {"weight_degree", std::get<2>(key)},
                     {"name", kernel ? kernel->name : ""},
                     {"region", region_name(std::get<3>(key))},
                     {"points", cell.points},
                     {"excluded", cell.excluded},
                     {"retried", cell.retried},
                     {"outside_support", cell.outside_support},
                     {"support_mismatch", cell.support_mismatch},
                     {"max_reference_error_estimate", cell.max_reference_error},
                     {"double", precision_json(cell.in_double)},
                     {"extended", precision_json(cell.in_extended)}});
  }
  const GenericVerdict verdict = generic_verdict(result, options.exclusions);
  nlohmann::json exclusions = nlohmann::json::array();
  for (const ExclusionCell& c : exclusion_cells(result, options.exclusions))
    exclusions.push_back({{"family", family_name(c.family)},
                          {"degree", c.degree},
                          {"region", region_name(c.region)},
                          {"evaluations", c.evaluations},
                          {"compared", c.compared},
                          {"excluded", c.excluded},
                          {"retried", c.retried},
                          {"excluded_share", c.excluded_share()},
                          {"passed", c.passed}});
  nlohmann::json summary{{"samples", result.samples},
                         {"items_run", result.items_run},
                         {"items_total", result.items_total},
                         {"seconds", result.seconds},
                         {"reference_kernel_evaluations", result.kernel_evaluations},
                         {"generic_failing_points", verdict.failing_points},
                         {"generic_failing_rows", verdict.failing_cells},
                         {"generic_comparisons", verdict.compared},
                         {"exclusion_cells_failing", verdict.failing_exclusion_cells},
                         {"generic_passed", verdict.passed()}};
  if (result.merged_shards > 0) summary["merged_shards"] = result.merged_shards;
  return {{"tool", "skelconv-verify"},
          {"settings", settings_json(options)},
          {"cells", cells},
          {"exclusions", exclusions},
          {"summary", summary}};
}

}  // namespace skelconv::verify
