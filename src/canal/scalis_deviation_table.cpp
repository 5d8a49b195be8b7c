// skelconv-canal-scalis-table — prints the SCALIS-versus-canal table of
// docs/canal.md §5 (Markdown), for |AB| = 1 and the cases of
// scalis_deviation_cases(). Takes a few seconds; deterministic.
//
//   build/release/src/skelconv-canal-scalis-table > table.md
#include <cstdio>
#include <exception>

#include <fmt/format.h>

#include "skelconv/canal/scalis_deviation.hpp"

int main() {
  using namespace skelconv;
  using namespace skelconv::canal;
  try {
    std::puts("| kernel | shape | middle max δ/τ | middle RMS | ends max δ/τ | ends RMS | ends not reached |");
    std::puts("|---|---|---|---|---|---|---|");
    for (const ScalisDeviationCase& c : scalis_deviation_cases()) {
      const ScalisSegment segment(Vec3::Zero(), Vec3::UnitX(), c.tau0, c.tau1, c.kernel);
      const ScalisDeviation deviation = measure_scalis_deviation(segment);
      const auto bar = c.name.find(" | ");
      fmt::print("| {} | {} | {:+.2e} | {:.2e} | {:+.2e} | {:.2e} | {}/{} |\n", c.name.substr(0, bar),
                 c.name.substr(bar + 3), deviation.middle.extreme, deviation.middle.rms, deviation.ends.extreme,
                 deviation.ends.rms, deviation.ends.missing, deviation.ends.points);
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "skelconv-canal-scalis-table: %s\n", error.what());
    return 1;
  }
  return 0;
}
