// skelconv-verify-polygons — accuracy sweep of the generated polygon kernels
// (generated/polygon_*.hpp through skelconv/primitives/polygon_field.hpp) against 2-D
// adaptive quadrature of the definition integral (verify/polygon_reference.hpp,
// long double or binary128). See docs/verify.md.
//
// For every family and region, samples are drawn by verify/polygon_sampling.hpp;
// each sample is checked for every degree the table offers (the reference
// computes all degrees of a family in one pass). Reported per (family, degree,
// region): the max relative error of f, of |∇f| and of each component of ∇f
// (normalised by |∇f|), in double, and the references excluded. A reference
// the long double quadrature cannot trust is retried in binary128 before it
// is excluded. Exit status 0 when every generic-region comparison meets the
// targets (≤ 1e-12 for f and ∇f) and no (family, degree, region) cell
// excludes more than ExclusionLimits allows (error_stats.hpp), 1 otherwise,
// 2 on a usage error.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <tuple>
#include <type_traits>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "build_info.hpp"
#include "error_stats.hpp"  // ExclusionLimits
#include "extended_precision.hpp"
#include "polygon_reference.hpp"
#include "polygon_sampling.hpp"
#include "progress.hpp"
#include "skelconv/primitives/polygon_field.hpp"

namespace {

using skelconv::KernelFamily;
using namespace skelconv::verify;

/// Generic-region targets, double precision (docs/verify_reference.md).
constexpr double kGenericTarget = 1e-12;
/// What the reference must reach (its own estimate) to be used.
template <class Real>
constexpr double reference_tolerance() {
  return std::is_same_v<Real, long double> ? 1e-17 : 1e-24;
}

struct Cell {
  std::uint64_t points = 0, excluded = 0, nonfinite = 0, above_target = 0;
  std::uint64_t retried = 0;  ///< reference untrusted at first, recomputed in binary128
  double max_f = 0, max_grad = 0, max_grad_component = 0;
  std::uint64_t worst_index = 0;  ///< sample with the largest f or ∇f error

  void merge(const Cell& o) {
    if (std::max(o.max_f, o.max_grad) > std::max(max_f, max_grad)) worst_index = o.worst_index;
    points += o.points, excluded += o.excluded, nonfinite += o.nonfinite, above_target += o.above_target;
    retried += o.retried;
    max_f = std::max(max_f, o.max_f), max_grad = std::max(max_grad, o.max_grad);
    max_grad_component = std::max(max_grad_component, o.max_grad_component);
  }
};

using CellKey = std::tuple<KernelFamily, int, PolygonRegion>;

struct Item {
  KernelFamily family;
  PolygonRegion region;
  std::uint64_t first, count;
};

template <class Real>
Vec3<Real> widen_to(const Vec3<double>& v) {
  return {Real(v[0]), Real(v[1]), Real(v[2])};
}

/// The reference values of every degree of pb's family, in Real, to the
/// relative accuracy `tolerance` (an untrusted one is flagged).
template <class Real>
auto polygon_references(const PolygonProblem& pb, const std::vector<int>& degrees, double tolerance) {
  std::vector<Vec3<Real>> vertices;
  for (const auto& v : pb.vertices) vertices.push_back(widen_to<Real>(v));
  PolygonReferenceIntegrator<Real> integrator(vertices);
  return integrator.evaluate(widen_to<Real>(pb.p), pb.family, degrees, Real(pb.s), Real(pb.R), Real(tolerance));
}

template <class Reference>
bool usable(const Reference& ref) {
  using std::isfinite;
  return ref.trusted && isfinite(ref.value);
}

/// Compares one sample, every degree, into `cells` (indexed like `degrees`).
/// A degree whose reference is not trusted is retried with the stronger
/// reference — binary128, to the same tolerance, computed once per sample —
/// before it is excluded, so that exclusions stay rare enough to bound.
template <class Real>
void check_sample(const PolygonProblem& pb, const std::vector<int>& degrees, double tolerance,
                  std::vector<Cell>& cells) {
  using std::abs;
  const auto refs = polygon_references<Real>(pb, degrees, tolerance);
  using Stronger = decltype(polygon_references<extended>(pb, degrees, tolerance));
  std::optional<Stronger> stronger;
  for (std::size_t k = 0; k < degrees.size(); ++k) {
    Cell& cell = cells[k];
    auto ref = refs[k];
    if (!usable(ref) && !std::is_same_v<Real, extended>) {
      ++cell.retried;
      if (!stronger) stronger = polygon_references<extended>(pb, degrees, tolerance);
      const auto& retry = (*stronger)[k];
      if (usable(retry)) {
        ref.trusted = true;
        ref.value = Real(retry.value);
        for (int c = 0; c < 3; ++c) ref.gradient[c] = Real(retry.gradient[c]);
      }
    }
    if (!usable(ref)) {
      ++cell.excluded;
      continue;
    }
    skelconv::PolygonInput<double> in{pb.vertices, pb.normal, pb.family, degrees[k], pb.s, pb.R};
    std::array<double, 3> grad;
    const double f = skelconv::polygon_f_and_grad(in, pb.p, grad);
    ++cell.points;
    if (ref.value == 0) {  // compact, support misses the polygon: exact 0 expected
      const bool exact = f == 0 && grad[0] == 0 && grad[1] == 0 && grad[2] == 0;
      if (!exact) ++cell.above_target, cell.max_f = std::max(cell.max_f, 1.0);
      continue;
    }
    if (!std::isfinite(f) || !std::isfinite(grad[0]) || !std::isfinite(grad[1]) || !std::isfinite(grad[2])) {
      ++cell.nonfinite, ++cell.above_target;
      cell.max_f = cell.max_grad = cell.max_grad_component = std::numeric_limits<double>::infinity();
      cell.worst_index = pb.index;
      continue;
    }
    const double e_f = static_cast<double>(abs(Real(f) - ref.value) / abs(ref.value));
    const Real g_norm = norm(ref.gradient);
    double e_g = 0, e_c = 0;
    if (g_norm > 0) {
      const Vec3<Real> diff = sub(widen_to<Real>(grad), ref.gradient);
      e_g = static_cast<double>(norm(diff) / g_norm);
      for (int c = 0; c < 3; ++c) e_c = std::max(e_c, static_cast<double>(abs(diff[c]) / g_norm));
    }
    if (std::max(e_f, e_g) > std::max(cell.max_f, cell.max_grad)) cell.worst_index = pb.index;
    cell.max_f = std::max(cell.max_f, e_f);
    cell.max_grad = std::max(cell.max_grad, e_g);
    cell.max_grad_component = std::max(cell.max_grad_component, e_c);
    if (!(e_f <= kGenericTarget) || !(e_g <= kGenericTarget)) ++cell.above_target;
  }
}

std::string scientific(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1e", x);
  return buffer;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"skelconv-verify-polygons: generated polygon kernels vs quadrature of the definition"};
  int generic_points = 2000, other_points = 200, threads = 2;
  std::uint64_t seed = 20261122;
  std::string family_filter, region_filter, json_path;
  bool quiet = false;
  std::string reference = "long-double";
  app.add_option("--reference", reference, "precision of the reference quadrature")
      ->check(CLI::IsMember({"long-double", "binary128"}))
      ->capture_default_str();
  app.add_option("--generic-points", generic_points, "samples per family in the generic region")->capture_default_str();
  app.add_option("--points", other_points, "samples per family in every other region")->capture_default_str();
  app.add_option("--family", family_filter, "only this family")->check(CLI::IsMember({"inverse", "cauchy", "compact"}));
  app.add_option("--region", region_filter, "only this region");
  app.add_option("--threads", threads, "worker threads")->check(CLI::Range(1, 256));
  app.add_option("--seed", seed, "random seed")->capture_default_str();
  app.add_option("--json", json_path, "write the machine-readable report to this file");
  app.add_flag("--quiet", quiet, "no progress line on stderr");
  double reference_flag = 0;
  ExclusionLimits limits;
  app.add_option("--reference-flag", reference_flag,
                 "use a reference only when its error estimate is below this (default 1e-17 long double, 1e-24 "
                 "binary128); a tiny value injects an exclusion storm, which the verdict must fail")
      ->check(CLI::PositiveNumber);
  app.add_option("--max-excluded-share", limits.max_excluded_share,
                 "largest share of a (family, degree, region) cell that may stay excluded")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  CLI11_PARSE(app, argc, argv);

  std::vector<Item> items;
  constexpr std::uint64_t chunk = 20;
  for (KernelFamily family : {KernelFamily::inverse, KernelFamily::cauchy, KernelFamily::compact}) {
    if (!family_filter.empty() && skelconv::family_name(family) != family_filter) continue;
    for (PolygonRegion region : all_polygon_regions) {
      if (!polygon_region_applies(region, family)) continue;
      if (!region_filter.empty() && polygon_region_name(region) != region_filter) continue;
      const std::uint64_t total = region == PolygonRegion::generic ? generic_points : other_points;
      for (std::uint64_t first = 0; first < total; first += chunk)
        items.push_back({family, region, first, std::min(chunk, total - first)});
    }
  }
  if (items.empty()) {
    std::cerr << "skelconv-verify-polygons: nothing to do (filters match no family/region)\n";
    return 2;
  }
  std::uint64_t total_samples = 0;
  for (const Item& item : items) total_samples += item.count;

  const double tolerance =
      reference_flag > 0 ? reference_flag
                         : reference == "binary128" ? reference_tolerance<extended>() : reference_tolerance<long double>();
  const auto start = std::chrono::steady_clock::now();
  std::map<CellKey, Cell> cells;
  std::mutex merge_mutex;
  std::atomic<std::size_t> next{0};
  std::atomic<std::uint64_t> failures{0};
  {
    ProgressReporter progress(!quiet, total_samples, items.size());
    auto worker = [&] {
      for (std::size_t i = next++; i < items.size(); i = next++) {
        const Item& item = items[i];
        const std::vector<int> degrees = skelconv::polygon_supported_degrees(item.family);
        std::vector<Cell> local(degrees.size());
        for (std::uint64_t k = item.first; k < item.first + item.count; ++k) {
          try {
            const PolygonProblem problem = draw_polygon_problem(seed, item.family, item.region, k);
            if (reference == "binary128")
              check_sample<extended>(problem, degrees, tolerance, local);
            else
              check_sample<long double>(problem, degrees, tolerance, local);
          } catch (const std::exception& e) {
            ++failures;
            std::lock_guard lock(merge_mutex);
            std::cerr << "\nskelconv-verify-polygons: sample " << k << " of " << skelconv::family_name(item.family)
                      << "/" << polygon_region_name(item.region) << ": " << e.what() << '\n';
          }
        }
        std::lock_guard lock(merge_mutex);
        for (std::size_t d = 0; d < degrees.size(); ++d) cells[{item.family, degrees[d], item.region}].merge(local[d]);
        progress.item_done(item.count);
      }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // The table: one row per (family, degree), f / ∇f-component per region.
  std::cout << "Polygon kernels in double vs " << reference
            << " quadrature of the definition: max relative error of f / of the worst ∇f component (÷|∇f|)\n";
  std::cout << "| family | i |";
  for (PolygonRegion r : all_polygon_regions) std::cout << ' ' << polygon_region_name(r) << " |";
  std::cout << "\n|---|---|";
  for (std::size_t r = 0; r < all_polygon_regions.size(); ++r) std::cout << "---|";
  std::cout << '\n';
  std::uint64_t generic_compared = 0, generic_failing = 0, excluded = 0, retried = 0, failing_exclusion_cells = 0;
  nlohmann::json rows = nlohmann::json::array();
  std::map<std::pair<KernelFamily, int>, std::map<PolygonRegion, Cell>> table;
  for (const auto& [key, cell] : cells) table[{std::get<0>(key), std::get<1>(key)}][std::get<2>(key)] = cell;
  for (const auto& [row, by_region] : table) {
    std::cout << "| " << skelconv::family_name(row.first) << " | " << row.second << " |";
    for (PolygonRegion r : all_polygon_regions) {
      const auto it = by_region.find(r);
      if (it == by_region.end()) {
        std::cout << " – |";
        continue;
      }
      const Cell& c = it->second;
      // Exclusions: "(n excl.)" when any, '!' beyond the limits.
      const bool within_limits = limits.allow(c.points, c.excluded, c.points + c.excluded);
      if (!within_limits) ++failing_exclusion_cells;
      const std::string exclusions =
          c.excluded == 0 ? "" : " (" + std::to_string(c.excluded) + " excl." + (within_limits ? ")" : ")!");
      if (c.points == 0)
        std::cout << " none compared" << exclusions << " |";
      else
        std::cout << ' ' << scientific(c.max_f) << " / " << scientific(c.max_grad_component) << exclusions << " |";
      excluded += c.excluded;
      retried += c.retried;
      if (r == PolygonRegion::generic) generic_compared += c.points, generic_failing += c.above_target;
      rows.push_back({{"family", skelconv::family_name(row.first)}, {"degree", row.second},
                      {"region", polygon_region_name(r)}, {"points", c.points}, {"excluded", c.excluded},
                      {"retried", c.retried}, {"exclusions_within_limits", within_limits},
                      {"nonfinite", c.nonfinite}, {"max_f", c.max_f}, {"max_grad", c.max_grad},
                      {"max_grad_component", c.max_grad_component}, {"worst_sample", c.worst_index}});
    }
    std::cout << '\n';
  }
  std::cout << "generic: " << generic_compared << " comparisons, " << generic_failing << " above " << kGenericTarget
            << "; references retried in binary128: " << retried << ", still excluded (estimate above " << tolerance
            << "): " << excluded << "; cells beyond the exclusion limits (more than " << 100 * limits.max_excluded_share
            << "% excluded): " << failing_exclusion_cells << "; failed samples: " << failures << "; " << total_samples << " samples in " << static_cast<int>(seconds)
            << " s\n";
  if (!json_path.empty()) {
    std::ofstream file(json_path);
    // settings.commit traces a committed baseline back to its code
    // (check_baseline_commits.cmake refuses "-dirty").
    const nlohmann::json settings{{"commit", std::string(skelconv::verify::build_commit())},
                                  {"generic_points", generic_points},
                                  {"points", other_points}};
    file << nlohmann::json{{"settings", settings},
                           {"seed", seed},
                           {"generic_target", kGenericTarget},
                           {"reference", reference},
                           {"reference_tolerance", tolerance},
                           {"retry_reference", "binary128"},
                           {"max_excluded_share", limits.max_excluded_share},
                           {"min_compared_share", limits.min_compared_share},
                           {"exclusion_cells_failing", failing_exclusion_cells},
                           {"seconds", seconds},
                           {"cells", rows}}
                .dump(1)
         << '\n';
    if (!file) {
      std::cerr << "skelconv-verify-polygons: cannot write " << json_path << '\n';
      return 2;
    }
  }
  return generic_failing == 0 && failures == 0 && generic_compared > 0 && failing_exclusion_cells == 0 ? 0 : 1;
}
