// skelconv-verify — accuracy sweep of the generated segment functions against
// binary128 quadrature of the definition integral (docs/mathematics.md §2), and the tools
// around its JSON report: merge shard reports, compare two reports, render one
// as Markdown. See docs/verify.md.
//
// Exit status: 0 when every generic-region comparison meets its target
// (AccuracyTargets) — for `compare`, when no region got worse —, 1 when one
// does not, 2 on a usage error or an unusable report.
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "compare.hpp"
#include "markdown_report.hpp"
#include "merge.hpp"
#include "regions.hpp"
#include "report.hpp"
#include "report_reader.hpp"
#include "skelconv/kernels/kernel_spec.hpp"
#include "skelconv/kernels/kernel_list.hpp"
#include "sweep.hpp"

namespace {

using skelconv::KernelFamily;
using namespace skelconv::verify;

/// What the command line asked for, before it is turned into SweepOptions.
struct SweepArguments {
  int points = 0;
  int generic_points = 0, other_points = 0;  // 0: as --points / --full / the default say
  bool full = false;
  std::string shard = "0/1", family, region, perturbation;
  int degree = 0;
  bool quiet = false;
};

struct OutputArguments {
  std::string json_path, markdown_path;
  bool without_samples = false;
};

/// The families with a segment field (their traits' `primitives`).
std::vector<std::string> segment_family_names() {
  std::vector<std::string> names;
  for (KernelFamily f : skelconv::all_kernel_families)
    if (skelconv::kernels::family_facts(f).on(skelconv::kernels::on_segments)) names.emplace_back(skelconv::family_name(f));
  return names;
}

std::optional<KernelFamily> parse_family(const std::string& name) {
  for (KernelFamily f : skelconv::all_kernel_families)
    if (skelconv::family_name(f) == name && skelconv::kernels::family_facts(f).on(skelconv::kernels::on_segments)) return f;
  return std::nullopt;
}

/// "k/n" with 0 <= k < n into the options; false when malformed.
bool parse_shard(const std::string& shard, SweepOptions& options) {
  const auto slash = shard.find('/');
  if (slash == std::string::npos) return false;
  try {
    std::size_t used_k = 0, used_n = 0;
    options.shard_index = std::stoi(shard.substr(0, slash), &used_k);
    options.shard_count = std::stoi(shard.substr(slash + 1), &used_n);
    if (used_k != slash || used_n != shard.size() - slash - 1) return false;
  } catch (const std::exception&) {
    return false;
  }
  return options.shard_count >= 1 && options.shard_index >= 0 && options.shard_index < options.shard_count;
}

/// "FAMILY:RELATIVE", e.g. "cauchy:1e-9", into a test perturbation.
std::optional<TestPerturbation> parse_perturbation(const std::string& text) {
  const auto colon = text.find(':');
  if (colon == std::string::npos) return std::nullopt;
  const auto family = parse_family(text.substr(0, colon));
  try {
    std::size_t used = 0;
    const double relative = std::stod(text.substr(colon + 1), &used);
    if (!family || used != text.size() - colon - 1 || !(relative != 0) || !(std::abs(relative) < 1)) return std::nullopt;
    return TestPerturbation{*family, relative};
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

void add_sweep_options(CLI::App& app, SweepArguments& args, SweepOptions& options) {
  app.add_option("--points", args.points,
                 "samples per (family, degree, region) in every region (default: generic 2000, others 200)");
  app.add_flag("--full", args.full, "the long sweep: generic 20000, other regions 2000 (overridden by --points)");
  app.add_option("--generic-points", args.generic_points,
                 "samples per (family, degree) in the generic region (overrides --points and --full there)")
      ->check(CLI::Range(1, 100000000));
  app.add_option("--other-points", args.other_points,
                 "samples per (family, degree, region) in every other region (overrides --points and --full there)")
      ->check(CLI::Range(1, 100000000));
  app.add_option("--shard", args.shard, "run shard k of n: work items with index % n == k (format k/n)");
  app.add_option("--family", args.family, "only this family")->check(CLI::IsMember(segment_family_names()));
  app.add_option("--degree", args.degree, "only this kernel degree i")->check(CLI::Range(1, 64));
  app.add_option("--region", args.region, "only this region")
      ->check(CLI::IsMember({"generic", "near_line_beside", "near_line_beyond", "near_ends", "far", "support_boundary",
                             "support_grazing"}));
  app.add_option("--threads", options.threads, "worker threads")->check(CLI::Range(1, 256));
  app.add_option("--seed", options.seed, "random seed (the samples depend on it only)");
  app.add_option("--chunk", options.chunk_size, "samples per work item")->check(CLI::Range(1, 1000000));
  app.add_flag("--quiet", args.quiet, "no progress line on stderr");
  app.add_option("--reference-flag", options.reference.flag_threshold,
                 "flag (retry, then exclude) a reference whose error estimate exceeds this (default 1e-20); a tiny "
                 "value injects an exclusion storm, which the verdict must fail")
      ->check(CLI::PositiveNumber);
  app.add_option("--max-excluded-share", options.exclusions.max_excluded_share,
                 "largest share of a (family, degree, region) cell that may stay excluded (default 0.01)")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--test-perturb", args.perturbation,
                 "TESTS ONLY: multiply every generated result of one family by (1 + r), format FAMILY:r (e.g. "
                 "cauchy:1e-9), a formula regression that `compare` must catch");
}

void add_output_options(CLI::App& app, OutputArguments& out) {
  app.add_option("--json", out.json_path, "write the machine-readable report to this file");
  app.add_option("--markdown", out.markdown_path, "write the report as Markdown (a table per family) to this file");
  app.add_flag("--without-samples", out.without_samples,
               "leave the worst samples out of the JSON (a small report, e.g. a committed baseline)");
}

/// The JSON and Markdown files of `report`; throws ReportError.
void write_outputs(const SweepReport& report, const OutputArguments& out) {
  if (!out.json_path.empty()) write_report(report, out.json_path, !out.without_samples);
  if (!out.markdown_path.empty()) {
    std::ofstream file(out.markdown_path);
    write_markdown_report(file, report.options, report.result);
    if (!file.flush()) throw ReportError(out.markdown_path + ": cannot write");
  }
}

/// The sweep's exit status: its verdict.
int verdict_status(const SweepReport& report) {
  const GenericVerdict verdict = generic_verdict(report.result, report.options.exclusions);
  // A shard without generic items asserts only the exclusion limits.
  if (verdict.compared == 0) return verdict.failing_exclusion_cells == 0 ? 0 : 1;
  return verdict.passed() ? 0 : 1;
}

int run_sweep_command(const SweepArguments& args, SweepOptions options, const OutputArguments& out) {
  if (args.full) options.counts = full_point_counts;
  if (args.points > 0) options.counts = {args.points, args.points};
  if (args.generic_points > 0) options.counts.generic = args.generic_points;
  if (args.other_points > 0) options.counts.other = args.other_points;
  if (!parse_shard(args.shard, options)) {
    std::cerr << "skelconv-verify: --shard must be k/n with 0 <= k < n, got \"" << args.shard << "\"\n";
    return 2;
  }
  if (!args.perturbation.empty()) {
    options.perturbation = parse_perturbation(args.perturbation);
    if (!options.perturbation) {
      std::cerr << "skelconv-verify: --test-perturb must be FAMILY:r with 0 < |r| < 1, got \"" << args.perturbation
                << "\"\n";
      return 2;
    }
  }
  if (!args.family.empty()) options.family = parse_family(args.family);
  if (args.degree > 0) options.degree = args.degree;
  if (!args.region.empty()) options.region = region_from_name(args.region);
  options.progress = !args.quiet;

  if (build_work_list(options).empty()) {
    std::cerr << "skelconv-verify: nothing to do (no generated kernel matches the filters)\n";
    return 2;
  }
  const SweepReport report{"", options, run_sweep(options)};
  write_text_report(std::cout, report.options, report.result);
  write_outputs(report, out);
  return verdict_status(report);
}

int run_merge_command(const std::vector<std::string>& paths, const OutputArguments& out) {
  std::vector<SweepReport> shards;
  for (const std::string& path : paths) shards.push_back(read_report(path));
  const SweepReport merged = merge_reports(shards);
  write_text_report(std::cout, merged.options, merged.result);
  write_outputs(merged, out);
  return verdict_status(merged);
}

int run_compare_command(const std::string& base_path, const std::string& new_path, const CompareOptions& options) {
  const SweepReport base = read_report(base_path), fresh = read_report(new_path);
  const Comparison comparison = compare_reports(base, fresh, options);
  write_comparison(std::cout, comparison, base, fresh);
  return comparison.passed() ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"skelconv-verify: generated segment functions vs binary128 quadrature of the definition"};
  SweepArguments sweep_args;
  SweepOptions options;
  OutputArguments outputs;
  add_sweep_options(app, sweep_args, options);
  add_output_options(app, outputs);

  CLI::App* merge = app.add_subcommand("merge", "merge the JSON reports of shards 0..n-1 of one sweep");
  std::vector<std::string> shard_paths;
  OutputArguments merge_outputs;
  merge->add_option("reports", shard_paths, "the shard reports (--json of each --shard k/n run)")->required();
  add_output_options(*merge, merge_outputs);

  CLI::App* compare = app.add_subcommand("compare", "did any region get worse from BASE to NEW? (same seed and sizes)");
  std::string base_path, new_path;
  CompareOptions compare_options;
  compare->add_option("BASE", base_path, "the report before the change (e.g. verify/baselines/sweep_default.json)")
      ->required();
  compare->add_option("NEW", new_path, "the report after it")->required();
  compare->add_option("--tolerance-factor", compare_options.tolerance_factor,
                      "a cell is worse when a maximum exceeds this many times its old value (default 2)")
      ->check(CLI::Range(1.0, 1e300));
  compare->add_option("--double-floor", compare_options.double_floor,
                      "and exceeds this in double (default 16 ulps, 3.6e-15)")
      ->check(CLI::NonNegativeNumber);
  compare->add_option("--extended-floor", compare_options.extended_floor,
                      "and exceeds this in binary128 (default: BASE's reference flag threshold, 1e-20)")
      ->check(CLI::NonNegativeNumber);

  CLI::App* markdown = app.add_subcommand("markdown", "print a JSON report as Markdown tables");
  std::string markdown_path;
  markdown->add_option("REPORT", markdown_path, "a sweep or merged report")->required();
  app.require_subcommand(0, 1);
  CLI11_PARSE(app, argc, argv);

  try {
    if (*merge) return run_merge_command(shard_paths, merge_outputs);
    if (*compare) return run_compare_command(base_path, new_path, compare_options);
    if (*markdown) {
      const SweepReport report = read_report(markdown_path);
      write_markdown_report(std::cout, report.options, report.result);
      return 0;
    }
    return run_sweep_command(sweep_args, options, outputs);
  } catch (const ReportError& e) {
    std::cerr << "skelconv-verify: " << e.what() << '\n';
    return 2;
  }
}
