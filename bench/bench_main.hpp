// bench/bench_main.hpp — what every benchmark program's main() shares.
#pragma once

#include <benchmark/benchmark.h>

#include <cstring>

namespace skelconv::bench {

/// Removes every `flag` from argv (Google Benchmark rejects arguments it does
/// not know); true if it was there.
inline bool take_flag(int& argc, char** argv, const char* flag) {
  bool found = false;
  int kept = 1;
  for (int j = 1; j < argc; ++j) {
    if (std::strcmp(argv[j], flag) == 0) {
      found = true;
    } else {
      argv[kept++] = argv[j];
    }
  }
  argc = kept;
  return found;
}

/// Runs the registered benchmarks with Google Benchmark's own arguments.
inline int run_registered_benchmarks(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace skelconv::bench
