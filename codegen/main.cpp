// codegen/main.cpp — skelconv-codegen: writes generated/ from the family
// descriptions. Degree ranges are arguments, not limits in the code.
//
//   skelconv-codegen --out generated [--inverse 1:16] [--cauchy 1:16]
//                    [--compact 2:16] [--weights 0:3] [--polygon-inverse 3:12]
//                    [--polygon-cauchy 3:12] [--polygon-compact 4:12]
//                    [--scalis-inverse 2:10] [--scalis-cauchy 2:10]
//                    [--scalis-compact 2:10]
#include <CLI/CLI.hpp>

#include <sys/personality.h>
#include <unistd.h>

#include <iostream>
#include <regex>
#include <tuple>

#include "generated_families.hpp"
#include "glsl_writer.hpp"
#include "kernel_writer.hpp"

namespace {

struct DegreeRange {
  int first = 0, last = -1;  // empty when last < first
};

DegreeRange parse_range(const std::string& text, const std::string& option) {
  static const std::regex pattern(R"((\d+)(?::(\d+))?)");
  std::smatch m;
  if (text == "none") return {};
  if (!std::regex_match(text, m, pattern))
    throw CLI::ValidationError(option, "expected FIRST:LAST, a single degree, or none; got '" + text + "'");
  DegreeRange r{std::stoi(m[1]), m[2].matched ? std::stoi(m[2]) : std::stoi(m[1])};
  if (r.last < r.first) throw CLI::ValidationError(option, "empty range '" + text + "'");
  return r;
}

// GiNaC orders the terms of sums and products by hash values that are seeded
// with the addresses of its type_info objects, so under address-space layout
// randomisation the same program prints differently from run to run. The
// generator must be byte-for-byte reproducible: it re-executes itself once
// with randomisation off, which fixes the addresses and hence the order.
void run_without_address_randomisation(char** argv) {
  const int current = personality(0xffffffff);
  if (current == -1 || (current & ADDR_NO_RANDOMIZE)) return;
  if (personality(static_cast<unsigned long>(current) | ADDR_NO_RANDOMIZE) == -1) return;
  execv("/proc/self/exe", argv);
  std::cerr << "skelconv-codegen: warning: could not disable address randomisation; "
               "the output may not be reproducible\n";
}

}  // namespace

int main(int argc, char** argv) {
  using skelconv::KernelFamily;
  run_without_address_randomisation(argv);
  CLI::App app{"skelconv-codegen: unrolls the Hubert–Cani recurrences into C++ kernels"};
  std::string out, inverse = "1:16", cauchy = "1:16", compact = "2:16", weights = "0:3";
  std::string polygon_inverse = "3:12", polygon_cauchy = "3:12", polygon_compact = "4:12";
  app.add_option("--out", out, "output folder (e.g. generated)")->required();
  app.add_option("--inverse", inverse, "power-inverse degrees i (FIRST:LAST or none)")->capture_default_str();
  app.add_option("--cauchy", cauchy, "Cauchy degrees i")->capture_default_str();
  app.add_option("--compact", compact, "compact-support degrees i (i ≥ 2)")->capture_default_str();
  app.add_option("--weights", weights, "weight-polynomial degrees")->capture_default_str();
  app.add_option("--polygon-inverse", polygon_inverse, "polygon power-inverse degrees (i ≥ 3)")->capture_default_str();
  app.add_option("--polygon-cauchy", polygon_cauchy, "polygon Cauchy degrees (i ≥ 3)")->capture_default_str();
  app.add_option("--polygon-compact", polygon_compact, "polygon compact degrees (even i ≥ 2; odd ones skipped)")
      ->capture_default_str();
  // SCALIS segments (docs/mathematics.md §4): the weight τ(t)^(i−1) has degree i − 1.
  std::string scalis_inverse = "2:10", scalis_cauchy = "2:10";
  app.add_option("--scalis-inverse", scalis_inverse, "SCALIS inverse segment degrees i (i ≥ 2)")->capture_default_str();
  app.add_option("--scalis-cauchy", scalis_cauchy, "SCALIS Cauchy segment degrees i (i ≥ 2)")->capture_default_str();
  // Compact SCALIS segments: closed forms for the even degrees of the range.
  std::string scalis_compact = "2:10";
  app.add_option("--scalis-compact", scalis_compact, "SCALIS compact segment degrees i (even i ≥ 2; odd ones skipped)")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  try {
    skelconv::codegen::GeneratorRequest request;
    request.command_line = "skelconv-codegen --inverse " + inverse + " --cauchy " + cauchy + " --compact " + compact +
                           " --weights " + weights + " --polygon-inverse " + polygon_inverse + " --polygon-cauchy " +
                           polygon_cauchy + " --polygon-compact " + polygon_compact + " --scalis-inverse " +
                           scalis_inverse + " --scalis-cauchy " + scalis_cauchy + " --scalis-compact " + scalis_compact;
    const DegreeRange w = parse_range(weights, "--weights");
    if (w.last > skelconv::max_weight_degree)
      throw CLI::ValidationError("--weights", "SegmentInput holds weights up to degree " +
                                                  std::to_string(skelconv::max_weight_degree));
    const std::pair<KernelFamily, DegreeRange> families[] = {
        {KernelFamily::inverse, parse_range(inverse, "--inverse")},
        {KernelFamily::cauchy, parse_range(cauchy, "--cauchy")},
        {KernelFamily::compact, parse_range(compact, "--compact")},
    };
    for (const auto& [family, range] : families) {
      const int lowest = skelconv::codegen::generated_family(family).min_segment_degree;
      if (range.last >= range.first && range.first < lowest)
        throw CLI::ValidationError(std::string(skelconv::family_name(family)), "degrees start at " + std::to_string(lowest));
      for (int i = range.first; i <= range.last; ++i)
        for (int d = w.first; d <= w.last; ++d) request.segment_kernels.push_back({family, i, d});
    }
    // Polygons (docs/mathematics.md §3): i = 2 diverges for inverse kernels and is excluded
    // by Hubert 2012 §6; compact kernels k_R^{2j} only (§8).
    const std::pair<KernelFamily, DegreeRange> polygon_families[] = {
        {KernelFamily::inverse, parse_range(polygon_inverse, "--polygon-inverse")},
        {KernelFamily::cauchy, parse_range(polygon_cauchy, "--polygon-cauchy")},
        {KernelFamily::compact, parse_range(polygon_compact, "--polygon-compact")},
    };
    for (const auto& [family, range] : polygon_families) {
      const skelconv::codegen::GeneratedFamily& row = skelconv::codegen::generated_family(family);
      const int lowest = row.min_polygon_degree;
      if (range.last >= range.first && range.first < lowest)
        throw CLI::ValidationError("polygon " + std::string(skelconv::family_name(family)),
                                   "degrees start at " + std::to_string(lowest));
      for (int i = range.first; i <= range.last; ++i)
        if (!row.even_polygon_degrees || i % 2 == 0) request.polygon_kernels.push_back({family, i});
    }
    for (const auto& [family, option, text] :
         {std::tuple{KernelFamily::inverse, "--scalis-inverse", scalis_inverse},
          std::tuple{KernelFamily::cauchy, "--scalis-cauchy", scalis_cauchy}}) {
      const DegreeRange range = parse_range(text, option);
      if (range.last >= range.first && range.first < 2) throw CLI::ValidationError(option, "SCALIS degrees start at 2");
      for (int i = range.first; i <= range.last; ++i) request.scalis_segment_kernels.push_back({family, i});
    }
    {
      const DegreeRange range = parse_range(scalis_compact, "--scalis-compact");
      if (range.last >= range.first && range.first < 2)
        throw CLI::ValidationError("--scalis-compact", "SCALIS degrees start at 2");
      for (int i = range.first; i <= range.last; ++i)
        if (i % 2 == 0) request.scalis_compact_degrees.push_back(i);
    }
    skelconv::codegen::write_generated_folder(request, out);
    // After the C++ files (glsl_writer.hpp says why): the shader target.
    skelconv::codegen::write_glsl_folder(request, std::filesystem::path(out) / "glsl");
    std::cerr << "skelconv-codegen: wrote " << request.segment_kernels.size() << " segment kernels, "
              << request.polygon_kernels.size() << " polygon edge kernels and " << request.scalis_segment_kernels.size()
              << " SCALIS segment kernels to " << out << '\n';
  } catch (const CLI::Error& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::cerr << "skelconv-codegen: error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
