// skelconv-verify — accuracy sweep of the generated segment functions against
// binary128 quadrature of the definition integral (SPEC §2). See docs/verify.md.
//
// Exit status: 0 when every generic-region comparison meets its target
// (AccuracyTargets), 1 when one does not, 2 on a usage error.
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "regions.hpp"
#include "report.hpp"
#include "sweep.hpp"

namespace {

using skelconv::KernelFamily;
using namespace skelconv::verify;

/// The families with a segment field (their traits' `primitives`).
std::vector<std::string> segment_family_names() {
  std::vector<std::string> names;
  for (KernelFamily f : skelconv::all_kernel_families)
    if (skelconv::kernels::family_facts(f).on(skelconv::kernels::on_segments)) names.emplace_back(skelconv::family_name(f));
  return names;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"skelconv-verify: generated segment functions vs binary128 quadrature of the definition"};
  SweepOptions options;
  int points = 0;
  bool full = false;
  std::string shard = "0/1", family, region, json_path;
  int degree = 0;
  bool quiet = false;
  app.add_option("--points", points,
                 "samples per (family, degree, region) in every region (default: generic 2000, others 200)");
  app.add_flag("--full", full, "the long sweep: generic 20000, other regions 2000 (overridden by --points)");
  app.add_option("--shard", shard, "run shard k of n: work items with index % n == k (format k/n)");
  app.add_option("--family", family, "only this family")->check(CLI::IsMember(segment_family_names()));
  app.add_option("--degree", degree, "only this kernel degree i")->check(CLI::Range(1, 64));
  app.add_option("--region", region, "only this region")
      ->check(CLI::IsMember({"generic", "near_line_beside", "near_line_beyond", "near_ends", "far", "support_boundary",
                                 "support_grazing"}));
  app.add_option("--json", json_path, "write the machine-readable report to this file");
  app.add_option("--threads", options.threads, "worker threads")->check(CLI::Range(1, 256));
  app.add_option("--seed", options.seed, "random seed (the samples depend on it only)");
  app.add_option("--chunk", options.chunk_size, "samples per work item")->check(CLI::Range(1, 1000000));
  app.add_flag("--quiet", quiet, "no progress line on stderr");
  app.add_option("--reference-flag", options.reference.flag_threshold,
                 "flag (retry, then exclude) a reference whose error estimate exceeds this (default 1e-20); a tiny "
                 "value injects an exclusion storm, which the verdict must fail")
      ->check(CLI::PositiveNumber);
  app.add_option("--max-excluded-share", options.exclusions.max_excluded_share,
                 "largest share of a (family, degree, region) cell that may stay excluded (default 0.01)")
      ->check(CLI::Range(0.0, 1.0));
  CLI11_PARSE(app, argc, argv);

  if (full) options.counts = full_point_counts;
  if (points > 0) options.counts = {points, points};
  if (const auto slash = shard.find('/'); slash == std::string::npos) {
    std::cerr << "--shard must be k/n\n";
    return 2;
  } else {
    try {
      options.shard_index = std::stoi(shard.substr(0, slash));
      options.shard_count = std::stoi(shard.substr(slash + 1));
    } catch (const std::exception&) {
      options.shard_count = 0;
    }
    if (options.shard_count < 1 || options.shard_index < 0 || options.shard_index >= options.shard_count) {
      std::cerr << "--shard must be k/n with 0 <= k < n\n";
      return 2;
    }
  }
  if (!family.empty()) options.family = skelconv::family_from_name(family);
  if (degree > 0) options.degree = degree;
  if (!region.empty()) options.region = region_from_name(region);
  options.progress = !quiet;

  if (build_work_list(options).empty()) {
    std::cerr << "skelconv-verify: nothing to do (no generated kernel matches the filters)\n";
    return 2;
  }
  const SweepResult result = run_sweep(options);
  write_text_report(std::cout, options, result);
  if (!json_path.empty()) {
    std::ofstream file(json_path);
    file << json_report(options, result).dump(1) << '\n';
    if (!file) {
      std::cerr << "skelconv-verify: cannot write " << json_path << '\n';
      return 2;
    }
  }
  const GenericVerdict verdict = generic_verdict(result, options.exclusions);
  // A shard without generic items asserts only the exclusion limits.
  if (verdict.compared == 0) return verdict.failing_exclusion_cells == 0 ? 0 : 1;
  return verdict.passed() ? 0 : 1;
}
